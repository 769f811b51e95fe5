// One sub-scanline of a sampled row, by columns (essay in rasterizer.cpp, step 7).
//
// A sub-scanline needs the x of every boundary of the filled set along it: its items (the row's edges at
// that height) in x order and the winding number walked from left to right. One comparison sort of the
// whole sub-scanline costs O(n log n), and starting from the previous sub-scanline's order does not help
// where the row's edges cross each other everywhere: with 10^6 random segments in a 512² clip, two
// sub-scanlines 1/16 px apart differ by about 1.4·10^7 inversions among 3·10^5 items, past the cap of
// adaptive_sort, so every sub-scanline paid for a full std::sort of items that no longer fit in the cache.
// Instead:
//
// 1. The items are distributed into column buckets: n/4 equal slices of the clip's width, so about four
//    items to a bucket where they are spread evenly (a stable counting sort: O(n)). The buckets follow
//    each other in x order; only the order inside a bucket is left to find. Buckets much narrower than a
//    pixel matter for step 2: the winding number left of a bucket must be large next to the bucket's
//    items, and at 10^6 random segments it is a few hundred while a pixel column holds 650 items.
// 2. The winding number left of a bucket is the winding number left of the row plus the directions of the
//    buckets before it, whatever their inner order. Under nonzero, a bucket whose left winding w is
//    positive and greater than the number of its items going up (direction −1), or negative and below
//    minus the number going down (+1), cannot reach zero inside it in any order: the bucket is filled
//    throughout, holds no boundary, and is not sorted. A bucket of items that miss the sub-scanline
//    (direction 0) holds no boundary either. Even-odd flips at every item, so it has no such skip.
// 3. Every other bucket is sorted from the order the stable distribution kept (the previous
//    sub-scanline's, nearly sorted where the bucket was sorted then; adaptive_sort bounds it anyway) and
//    walked as one sort of the whole sub-scanline would have been.
//
// Ties in x are broken by the item's slot, so the order is a strict total one: the boundaries found are
// those of one sort of the whole sub-scanline, in the same order, and the coverage is byte for byte the
// same. Cost: O(n) per sub-scanline plus the sorts of the buckets where the winding number comes near
// zero (the fill's outline; all of them under even-odd, of about four items each where the items are
// spread out), instead of O(n log n). Edges bunched into one bucket (many meeting at one point) cost that
// bucket's sort, at most O(k log k) for k of them (adaptive_sort). The last sub-scanline of the row sorts every
// bucket, so that the row hands the next one its edges in exact x order, as before (the exact paths of
// the next row start from that order and charge their sorts to their budget).
#include <algorithm>
#include <cmath>

#include "band_sort.h"
#include "rasterizer_impl.h"

namespace curvescan::detail {

namespace {

/// Items per column bucket where they are spread evenly: few enough that sorting a bucket costs about
/// as much as walking it, many enough that the buckets' counters cost less than the items.
constexpr std::size_t kItemsPerBucket = 4;

}  // namespace

std::uint64_t add_sub_scanline_by_columns(ScanState& s, FillRule rule, double weight, int winding_left,
                                          bool sort_every_column) {
  const std::size_t n = s.sample_items.size();
  if (n == 0) return 0;
  const double width = std::max(1, s.clip.x1 - s.clip.x0);
  const double x0 = s.clip.x0;
  // About kItemsPerBucket items per bucket where they are spread evenly, whatever the clip's width.
  const std::size_t buckets = std::max<std::size_t>(1, n / kItemsPerBucket);
  const double buckets_per_pixel = static_cast<double>(buckets) / width;
  const double last_bucket = static_cast<double>(buckets - 1);

  // 1. Stable distribution by column; the directions of each bucket counted on the way.
  s.column_start.assign(buckets + 1, 0);
  s.column_rising.assign(buckets, 0);
  s.column_falling.assign(buckets, 0);
  s.item_column.resize(n);
  const SampleItem* items = s.sample_items.data();
  for (std::size_t p = 0; p < n; ++p) {
    // Clamped items (an edge left of the clip is vertical on its left side; rounding at the right end)
    // go to the first or the last bucket: ⌊x⌋ clamped is still monotone in x.
    const auto b = static_cast<std::uint32_t>(
        std::clamp(std::floor((items[p].x - x0) * buckets_per_pixel), 0.0, last_bucket));
    s.item_column[p] = b;
    ++s.column_start[b + 1];
    s.column_rising[b] += items[p].dir < 0 ? 1 : 0;
    s.column_falling[b] += items[p].dir > 0 ? 1 : 0;
  }
  for (std::size_t b = 0; b < buckets; ++b) s.column_start[b + 1] += s.column_start[b];
  s.column_fill.assign(s.column_start.begin(), s.column_start.end() - 1);
  s.sample_scratch.resize(n);
  for (std::size_t p = 0; p < n; ++p) s.sample_scratch[s.column_fill[s.item_column[p]]++] = items[p];
  s.sample_items.swap(s.sample_scratch);
  std::uint64_t visited = 2 * n + buckets;

  // 2 and 3. Walk the buckets left to right; sort and walk only those that can hold a boundary.
  SampleItem* sorted = s.sample_items.data();
  const auto by_x = [](const SampleItem& a, const SampleItem& b) {
    return a.x < b.x || (a.x == b.x && a.slot < b.slot);
  };
  int winding = winding_left;
  bool filled = is_filled(winding, rule);
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t lo = s.column_start[b];
    const std::size_t hi = s.column_start[b + 1];
    if (lo == hi) continue;
    const int down = static_cast<int>(s.column_falling[b]);  // +1 items
    const int up = static_cast<int>(s.column_rising[b]);     // −1 items
    if (!sort_every_column) {
      const bool no_boundary =
          (down == 0 && up == 0) ||
          (rule == FillRule::kNonZero && ((winding > 0 && winding > up) || (winding < 0 && -winding > down)));
      if (no_boundary) {
        winding += down - up;  // nonzero all the way through (or unchanged): `filled` stays as it is
        continue;
      }
    }
    visited += adaptive_sort(sorted + lo, hi - lo, by_x);
    for (std::size_t p = lo; p < hi; ++p) {
      winding += sorted[p].dir;
      const bool now = is_filled(winding, rule);
      if (now == filled) continue;
      filled = now;
      s.row.add_boundary(sorted[p].x, sorted[p].x, weight, now ? 1.0 : -1.0);
    }
  }
  return visited;
}

}  // namespace curvescan::detail
