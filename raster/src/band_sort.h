// Insertion sort for the nearly sorted arrays of the scanline: the pieces of one row come in the order of
// the previous row, and ordinary shapes change that order rarely, so the cost is O(n + inversions)
// (Wylie & Romney's scan-line sorts; the same choice as FreeType's and font-rs's active lists).
#pragma once

#include <cstddef>
#include <utility>

namespace curvescan::detail {

/// Sorts [first, first + count) so that !less(a[i], a[i-1]) for all i; stable. `on_swap(moved, passed)`
/// is called once for every pair that changes order (an inversion), `moved` being the element moving left.
template <class T, class Less, class OnSwap>
void insertion_sort(T* first, std::size_t count, Less less, OnSwap on_swap) {
  for (std::size_t i = 1; i < count; ++i) {
    if (!less(first[i], first[i - 1])) continue;
    T moving = std::move(first[i]);
    std::size_t j = i;
    while (j > 0 && less(moving, first[j - 1])) {
      on_swap(moving, first[j - 1]);
      first[j] = std::move(first[j - 1]);
      --j;
    }
    first[j] = std::move(moving);
  }
}

template <class T, class Less>
void insertion_sort(T* first, std::size_t count, Less less) {
  insertion_sort(first, count, less, [](const T&, const T&) {});
}

}  // namespace curvescan::detail
