// One sub-scanline of a sampled row, by columns (essay in rasterizer.cpp, step 7).
//
// A sub-scanline needs the x of every boundary of the filled set along it: its items (the row's edges at
// that height) in x order and the winding number walked from left to right. One comparison sort of the
// whole sub-scanline costs O(n log n), and starting from the previous sub-scanline's order does not help
// where the row's edges cross each other everywhere: with 10^6 random segments in a 512² clip, two
// sub-scanlines 1/16 px apart differ by about 1.4·10^7 inversions among 3·10^5 items, past the cap of
// adaptive_sort, so every sub-scanline paid for a full std::sort of items that no longer fit in the cache.
// Instead, with the row's edges kept in one order (x order at the row's top) for all sixteen:
//
// 1. Each edge's x at the sub-scanline gives its column bucket: n/4 equal slices of the clip's width, so
//    about four edges to a bucket where they are spread evenly. The buckets follow each other in x order
//    (the bucket is monotone in x); each bucket counts its edges going down (+1) and up (−1). One
//    sequential pass, O(n).
// 2. The winding number left of a bucket is the winding number left of the row plus the directions of
//    the buckets before it, whatever their inner order: one pass over the buckets. Under nonzero, a
//    bucket whose left winding w is positive and greater than its count of edges going up, or negative
//    and below minus its count going down, cannot reach zero inside it in any order: it is filled
//    throughout and holds no boundary. A bucket of no edge meeting the sub-scanline holds none either.
//    Even-odd flips at every edge, so there every bucket with an edge is marked. Buckets much narrower
//    than a pixel matter here: the winding number must be large next to a bucket's counts. At 10^5
//    random segments in a 512² clip, 55 % of the buckets holding an edge were marked with one bucket per
//    pixel column (65 edges each), 5 % with four edges to a bucket (2 % at 10^6 segments).
// 3. The edges of the marked buckets are gathered bucket by bucket (a counting sort over the marked
//    buckets), sorted by x inside each bucket (adaptive_sort, about four edges each), and walked bucket by
//    bucket, each from its left winding number, as one sort of the whole sub-scanline would have walked
//    them.
//
// Ties in x are broken by the edge's slot, so the order is a strict total one: the boundaries found are
// those of one sort of the whole sub-scanline, in the same order, and the coverage is byte for byte the
// same. Cost per sub-scanline: O(n) plus the sorts inside the marked buckets (near the fill's outline,
// where the winding number comes near zero; under even-odd every bucket with an edge), instead of
// O(n log n) sixteen times a row. The row is put in exact x order once, at its last sub-scanline
// (order_row_by_x: the same buckets, then a sort inside each), so that the next row starts from the order
// it started from before (its exact paths charge their sorts to their budget).
#include <algorithm>
#include <cmath>

#include "band_sort.h"
#include "rasterizer_impl.h"

namespace curvescan::detail {

namespace {

/// Items per column bucket where they are spread evenly: few enough that sorting a bucket costs about
/// as much as walking it, many enough that the buckets' counters cost less than the items.
constexpr std::size_t kItemsPerBucket = 4;

/// n / kItemsPerBucket equal slices of the clip's width. bucket_of is monotone in x (a floor of a
/// monotone map, clamped), so the buckets follow each other in x order, and equal x share a bucket.
struct ColumnBuckets {
  ColumnBuckets(IntRect clip, std::size_t n)
      : buckets(std::max<std::size_t>(1, n / kItemsPerBucket)),
        x0(clip.x0),
        per_pixel(static_cast<double>(buckets) / std::max(1, clip.x1 - clip.x0)),
        last(static_cast<double>(buckets - 1)) {}
  [[nodiscard]] std::uint32_t bucket_of(double x) const noexcept {
    // Clamped (an edge left of the clip is vertical on its left side; rounding at the right end), and a
    // NaN, which clipped edges never give, to bucket 0 rather than into an undefined conversion.
    const double slice = std::floor((x - x0) * per_pixel);
    return slice > 0.0 ? static_cast<std::uint32_t>(std::min(slice, last)) : 0;
  }
  std::size_t buckets;
  double x0;
  double per_pixel;
  double last;
};

/// The strict total order of a sub-scanline: by x, ties by slot, so every sort gives the same order. A
/// lambda, not a function, so that the sorts inline it (a function pointer cost 7 % of the time at 10^6
/// segments).
constexpr auto by_x_then_slot = [](const SampleItem& a, const SampleItem& b) noexcept {
  return a.x < b.x || (a.x == b.x && a.slot < b.slot);
};

}  // namespace

std::uint64_t add_sub_scanline_by_columns(ScanState& s, double yc, FillRule rule, double weight,
                                          int winding_left) {
  const std::size_t n = s.sample_edges.size();
  if (n == 0) return 0;
  const ColumnBuckets grid(s.clip, n);
  const ClippedEdge* edges = s.sample_edges.data();

  // 1. Every edge's x and direction at the sub-scanline, in the row's order (sequential reads), and the
  //    directions counted per bucket. Edges that miss the sub-scanline (direction 0) change no winding
  //    number and bound nothing: they are not counted, nor walked below.
  //    Through local pointers: a store of a signed char may alias anything, so GCC otherwise reloads every
  //    vector's data pointer at every edge. An edge counts in one bucket, so both counts share a slot
  //    (ColumnCounts: one cache line touched per edge, not two).
  s.sample_x.resize(n);
  s.sample_dir.resize(n);
  s.item_column.resize(n);
  s.column_counts.assign(grid.buckets, ColumnCounts{});
  double* const xs = s.sample_x.data();
  signed char* const dirs = s.sample_dir.data();
  std::uint32_t* const columns = s.item_column.data();
  ColumnCounts* const counts = s.column_counts.data();
  for (std::size_t p = 0; p < n; ++p) {
    const ClippedEdge& e = edges[p];
    const double x = e.x_at(yc);
    const int dir = e.y_top <= yc && yc < e.y_bot ? e.dir : 0;
    const std::uint32_t b = grid.bucket_of(x);
    xs[p] = x;
    dirs[p] = static_cast<signed char>(dir);
    columns[p] = b;
    counts[b].rising += dir < 0 ? 1 : 0;
    counts[b].falling += dir > 0 ? 1 : 0;
  }

  // 2. The winding number left of each bucket; the buckets that may hold a boundary are marked with it.
  s.column_winding.resize(grid.buckets);
  s.column_marked.assign(grid.buckets, 0);
  int winding = winding_left;
  std::size_t marked = 0;
  for (std::size_t b = 0; b < grid.buckets; ++b) {
    const int down = static_cast<int>(counts[b].falling);  // +1 items
    const int up = static_cast<int>(counts[b].rising);     // −1 items
    if (down == 0 && up == 0) continue;
    const bool filled_throughout =
        rule == FillRule::kNonZero && ((winding > 0 && winding > up) || (winding < 0 && -winding > down));
    if (!filled_throughout) {
      s.column_marked[b] = 1;
      s.column_winding[b] = winding;
      ++marked;
    }
    winding += down - up;
  }
  std::uint64_t visited = 2 * n + grid.buckets;
  if (marked == 0) return visited;

  // 3. The edges of the marked buckets, sorted by x (ties by slot): placed bucket by bucket (a counting
  //    sort: the buckets follow each other in x order), in the row's order inside a bucket, then each
  //    bucket sorted alone. Sorting all of them at once from the row's order (the x order at the row's
  //    top) paid for every edge that moved past another one since the row's top, in marked buckets far
  //    apart as well: at 10^5 random segments in a 512 x 32 clip under even-odd, often more than
  //    adaptive_sort's cap, then std::sort on top.
  s.column_start.resize(grid.buckets);
  std::size_t m = 0;
  for (std::size_t b = 0; b < grid.buckets; ++b) {
    if (s.column_marked[b] == 0) continue;
    s.column_start[b] = m;
    m += counts[b].falling + counts[b].rising;
  }
  s.sample_items.resize(m);
  SampleItem* items = s.sample_items.data();
  const unsigned char* const marked_columns = s.column_marked.data();
  std::size_t* const next_slot = s.column_start.data();
  for (std::size_t p = 0; p < n; ++p) {
    if (dirs[p] == 0) continue;
    const std::uint32_t b = columns[p];
    if (marked_columns[b] != 0) items[next_slot[b]++] = {xs[p], static_cast<std::uint32_t>(p), dirs[p]};
  }
  visited += n + m;
  for (std::size_t k = 0; k < m;) {
    const std::uint32_t b = columns[items[k].slot];
    const std::size_t count = counts[b].falling + counts[b].rising;
    visited += adaptive_sort(items + k, count, by_x_then_slot);
    k += count;
  }

  // 4. Walk them bucket by bucket, each from the winding number on its left.
  std::uint32_t current = UINT32_MAX;
  bool filled = false;
  for (std::size_t k = 0; k < m; ++k) {
    const std::uint32_t b = columns[items[k].slot];
    if (b != current) {
      current = b;
      winding = s.column_winding[b];
      filled = is_filled(winding, rule);
    }
    winding += items[k].dir;
    const bool now = is_filled(winding, rule);
    if (now == filled) continue;
    filled = now;
    s.row.add_boundary(items[k].x, items[k].x, weight, now ? 1.0 : -1.0);
  }
  return visited;
}

std::uint64_t order_row_by_x(ScanState& s, double yc) {
  const std::size_t n = s.sample_edges.size();
  if (n == 0) return 0;
  const ColumnBuckets grid(s.clip, n);
  const ClippedEdge* edges = s.sample_edges.data();
  s.column_start.assign(grid.buckets + 1, 0);
  s.item_column.resize(n);
  s.sample_items.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    const double x = edges[p].x_at(yc);
    const std::uint32_t b = grid.bucket_of(x);
    s.sample_items[p] = {x, static_cast<std::uint32_t>(p), 0};
    s.item_column[p] = b;
    ++s.column_start[b + 1];
  }
  for (std::size_t b = 0; b < grid.buckets; ++b) s.column_start[b + 1] += s.column_start[b];
  s.column_fill.assign(s.column_start.begin(), s.column_start.end() - 1);
  s.sample_scratch.resize(n);
  for (std::size_t p = 0; p < n; ++p) s.sample_scratch[s.column_fill[s.item_column[p]]++] = s.sample_items[p];
  std::uint64_t visited = 3 * n + grid.buckets;
  for (std::size_t b = 0; b < grid.buckets; ++b) {
    const std::size_t first = s.column_start[b];
    visited += adaptive_sort(s.sample_scratch.data() + first, s.column_start[b + 1] - first, by_x_then_slot);
  }
  s.sample_active.resize(n);
  for (std::size_t p = 0; p < n; ++p) s.sample_active[p] = s.active[s.sample_scratch[p].slot];
  s.active.swap(s.sample_active);
  return visited;
}

}  // namespace curvescan::detail
