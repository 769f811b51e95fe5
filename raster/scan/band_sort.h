// Insertion sort for the nearly sorted arrays of the scanline: the pieces of one row come in the order of
// the previous row, and ordinary shapes change that order rarely, so the cost is O(n + inversions)
// (Wylie & Romney's scan-line sorts; the same choice as FreeType's and font-rs's active lists).
// Inversions can be Θ(n²) (every piece crossing every other one inside a row), so the bounded form gives
// up after a budget of moves and adaptive_sort() then finishes with an O(n log n) sort: never worse than
// std::sort by more than the budget.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>

namespace curvescan::detail {

/// Sorts [first, first + count) so that !less(a[i], a[i-1]) for all i; stable. `on_swap(moved, passed)`
/// is called once for every pair that changes order (an inversion), `moved` being the element moving
/// left. Stops as soon as more than `max_moves` pairs have changed order; returns the number of pairs
/// that changed order, which is max_moves + 1 when it stopped early (the array is then a permutation of
/// the input, partly sorted).
template <class T, class Less, class OnSwap>
std::size_t insertion_sort_bounded(T* first, std::size_t count, Less less, OnSwap on_swap,
                                   std::size_t max_moves) {
  std::size_t moves = 0;
  for (std::size_t i = 1; i < count; ++i) {
    if (!less(first[i], first[i - 1])) continue;
    T moving = std::move(first[i]);
    std::size_t j = i;
    while (j > 0 && less(moving, first[j - 1])) {
      if (moves == max_moves) {
        first[j] = std::move(moving);
        return max_moves + 1;
      }
      ++moves;
      on_swap(moving, first[j - 1]);
      first[j] = std::move(first[j - 1]);
      --j;
    }
    first[j] = std::move(moving);
  }
  return moves;
}

/// Unbounded insertion sort (the callers know the input is nearly sorted); returns the number of moves.
template <class T, class Less, class OnSwap>
std::size_t insertion_sort(T* first, std::size_t count, Less less, OnSwap on_swap) {
  return insertion_sort_bounded(first, count, less, on_swap, SIZE_MAX - 1);
}

template <class T, class Less>
std::size_t insertion_sort(T* first, std::size_t count, Less less) {
  return insertion_sort(first, count, less, [](const T&, const T&) {});
}

/// ⌈log2(n + 2)⌉: the comparison depth of a sort of n items, at least 1.
[[nodiscard]] inline std::size_t sort_depth(std::size_t n) noexcept {
  return static_cast<std::size_t>(std::bit_width(n + 1));
}

/// Sorts nearly sorted input in O(n + inversions), and any input in O(n log n): insertion sort with a
/// budget of n·⌈log2 n⌉ moves, then std::sort on what is left. Returns the work done, in elements visited
/// (count + moves, plus count·⌈log2 count⌉ when std::sort ran), for the rasterizer's work counter.
template <class T, class Less>
std::size_t adaptive_sort(T* first, std::size_t count, Less less) {
  const std::size_t budget = count * sort_depth(count);
  const std::size_t moves = insertion_sort_bounded(first, count, less, [](const T&, const T&) {}, budget);
  if (moves <= budget) return count + moves;
  std::sort(first, first + count, less);
  return count + moves + budget;
}

}  // namespace curvescan::detail
