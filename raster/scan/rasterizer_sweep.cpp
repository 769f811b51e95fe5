// The crossing sweep of one band, and the bounded sub-scanline fallback (essay in rasterizer.cpp, steps 3,
// 4 and 7).
//
// A band whose pieces do not keep their x order from top to bottom is swept downwards. The crossing pairs
// are the inversions between the top order and the bottom order (found by one insertion sort, each once);
// each pair crosses once, at a height computed from the two pieces, and the sweep visits those heights in
// order. At a crossing height only the pieces of the crossing pairs change order, and they form a
// contiguous range of the current order (the pieces passing through one point are adjacent): the range is
// re-sorted by x at the middle of the next sub-band and the winding numbers are recomputed inside it
// from the winding number on its left, which did not change. The winding on its right did not change
// either (a permutation keeps the sum of directions), so no other piece changes state. Each piece keeps
// its boundary state (+1 enter, -1 leave, 0 neither) and the height where that state began; when the state
// changes, the finished run is emitted as one trapezoid. This is the Bentley-Ottmann sweep (Bentley &
// Ottmann, "Algorithms for reporting and counting geometric intersections", 1979) restricted to one band,
// where no piece starts or ends and the crossings are known in advance, so no event queue is needed.
// Cost: O(n + k log k) for n pieces and k crossings, instead of O(n·k) for re-walking every piece in every
// sub-band.
//
// Rounding: the crossing height of each pair is rounded, so the pieces meeting near one point may be
// given slightly different heights and a range may be out of order against its neighbours; the range is
// widened until its ends are in order with them, so the order used for each sub-band is always a sorted
// order by x at the sub-band's middle (what the plain reference uses).
#include <algorithm>
#include <cmath>

#include "band_sort.h"
#include "rasterizer_impl.h"

namespace curvescan::detail {

namespace {

/// Emits piece `p`'s boundary run from y0 to y1: straight to the row when the band is the whole row (the
/// run cannot be continued by another band), through the run bookkeeping otherwise.
void emit_run(ScanState& s, const BandPiece& p, double y0, double y1, double sign, bool whole_row) {
  if (!(y1 > y0)) return;
  if (whole_row) {
    const ClippedEdge& e = s.edges[p.edge];
    s.row.add_boundary(e.x_at(y0), e.x_at(y1), y1 - y0, sign);
  } else {
    add_boundary_run(s, p.edge, y0, y1, sign);
  }
}

}  // namespace

bool sweep_band(ScanState& s, double ya, double yb, bool whole_row, FillRule rule, int winding_left) {
  const std::size_t n = s.pieces.size();
  const BandPiece* pieces = s.pieces.data();
  const double h = yb - ya;

  // 1. The crossing pairs: inversions between the top order (s.pieces) and the bottom order.
  s.order.resize(n);
  for (std::size_t i = 0; i < n; ++i) s.order[i] = static_cast<std::uint32_t>(i);
  s.band_crossings.clear();
  // At most kMaxBandCrossings crossings are kept (24 bytes each): a band crossing itself more than that
  // is sampled, whatever is left of the budget, so that memory stays bounded (a star polygon of 2·10^4
  // edges once kept 23 million crossings of one band, 1 GB, on the pool's budget).
  const std::size_t allowed = static_cast<std::size_t>(
      std::min<std::uint64_t>({s.row_budget_left, kMaxBandCrossings, SIZE_MAX - 2}));
  const std::size_t found = insertion_sort_bounded(
      s.order.data(), n, [&](std::uint32_t a, std::uint32_t b) { return pieces[a].xb < pieces[b].xb; },
      [&](std::uint32_t moved, std::uint32_t passed) {
        // `passed` is left of (or level with) `moved` at the top, right of it at the bottom: the difference
        // d(t) = x_moved - x_passed goes from d0 > 0 (ties at the top are ordered by the bottom) to d1 < 0,
        // and is zero at t = d0 / (d0 - d1) in (0, 1].
        const double d0 = pieces[moved].xa - pieces[passed].xa;
        const double d1 = pieces[moved].xb - pieces[passed].xb;
        const double t = std::clamp(d0 / (d0 - d1), 0.0, 1.0);
        s.band_crossings.push_back({ya + t * h, passed, moved});
      },
      allowed);
  s.stats.pieces_visited += n + std::min(found, allowed);
  if (found > allowed) {
    s.row_budget_left -= std::min<std::uint64_t>(s.row_budget_left, n + allowed);  // spent on the attempt
    return false;
  }
  s.row_budget_left -= std::min<std::uint64_t>(s.row_budget_left, n + found);
  s.stats.crossings += found;
  // By height. The insertion sort reports them in the order it finds them, which is the order of height
  // when a band holds one crossing, or a few far apart: checked first (O(k)), sorted only if needed. The
  // order among crossings of one height does not matter (step 3 takes them together and sorts their
  // ranges), so an unstable sort gives the same sweep.
  const auto by_height = [](const BandCrossing& a, const BandCrossing& b) { return a.y < b.y; };
  if (!std::is_sorted(s.band_crossings.begin(), s.band_crossings.end(), by_height))
    std::sort(s.band_crossings.begin(), s.band_crossings.end(), by_height);

  // 2. The state in the first sub-band: the top order, made exact against rounding by a sort by x at the
  // middle of that sub-band (no moves in exact arithmetic).
  const double first_cut = s.band_crossings.empty() ? yb : s.band_crossings.front().y;
  const double t_first = (0.5 * (ya + first_cut) - ya) / h;
  for (std::size_t i = 0; i < n; ++i) s.order[i] = static_cast<std::uint32_t>(i);
  s.stats.pieces_visited += insertion_sort(s.order.data(), n, [&](std::uint32_t a, std::uint32_t b) {
    return pieces[a].xa + (pieces[a].xb - pieces[a].xa) * t_first <
           pieces[b].xa + (pieces[b].xb - pieces[b].xa) * t_first;
  });
  s.position.resize(n);
  s.winding_before.resize(n + 1);
  s.boundary_sign.resize(n);
  s.run_start.resize(n);
  // The per-piece state through local pointers: a store to boundary_sign (signed char) may alias
  // anything, and GCC otherwise reloads every vector's data pointer after it. None of these vectors is
  // resized below (emit_run touches only the row and the pending runs).
  std::uint32_t* order = s.order.data();
  std::uint32_t* position = s.position.data();
  int* winding_before = s.winding_before.data();
  signed char* boundary_sign = s.boundary_sign.data();
  double* run_start = s.run_start.data();
  int winding = winding_left;
  for (std::size_t p = 0; p < n; ++p) {
    const std::uint32_t i = order[p];
    position[i] = static_cast<std::uint32_t>(p);
    winding_before[p] = winding;
    const bool before = is_filled(winding, rule);
    winding += pieces[i].dir;
    const bool after = is_filled(winding, rule);
    boundary_sign[i] = static_cast<signed char>(before == after ? 0 : (after ? 1 : -1));
    run_start[i] = ya;
  }
  winding_before[n] = winding;
  s.stats.pieces_visited += n;

  // 3. Crossing heights in order. After the crossings at height c, the order is the order at the middle
  // of the sub-band [c, next]; only the ranges holding a crossing pair are re-sorted.
  const BandCrossing* crossings = s.band_crossings.data();
  const std::size_t count = s.band_crossings.size();
  std::uint64_t visited = 0;
  s.carried_crossings.clear();
  std::size_t g = 0;
  while (g < count) {
    const double c = crossings[g].y;
    std::size_t g_end = g + 1;
    while (g_end < count && crossings[g_end].y == c) ++g_end;
    if (!(c < yb)) break;  // crossings at the very bottom: no area is left below them
    const double next = g_end < count ? crossings[g_end].y : yb;
    const double t_mid = (0.5 * (c + next) - ya) / h;
    const auto key = [&](std::uint32_t i) { return pieces[i].xa + (pieces[i].xb - pieces[i].xa) * t_mid; };
    const auto less = [&](std::uint32_t a, std::uint32_t b) { return key(a) < key(b); };
    // The new states of positions [lo, hi], sorted: a piece whose state changes ends its run at c.
    const auto settle = [&](std::size_t lo, std::size_t hi) {
      int w = winding_before[lo];
      for (std::size_t p = lo; p <= hi; ++p) {
        const std::uint32_t i = order[p];
        position[i] = static_cast<std::uint32_t>(p);
        winding_before[p] = w;
        const bool before = is_filled(w, rule);
        w += pieces[i].dir;
        const bool after = is_filled(w, rule);
        const signed char sign = static_cast<signed char>(before == after ? 0 : (after ? 1 : -1));
        if (sign == boundary_sign[i]) continue;
        if (boundary_sign[i] != 0) emit_run(s, pieces[i], run_start[i], c, boundary_sign[i], whole_row);
        boundary_sign[i] = sign;
        run_start[i] = c;
      }
    };
    // Re-sorts the positions [lo, hi], widened while a neighbour is out of order with an end (rounding,
    // see above), and settles them.
    const auto repair = [&](std::size_t lo, std::size_t hi) {
      while (true) {
        visited += (hi - lo + 1) + insertion_sort(order + lo, hi - lo + 1, less);
        if (lo > 0 && less(order[lo], order[lo - 1])) {
          --lo;
        } else if (hi + 1 < n && less(order[hi + 1], order[hi])) {
          ++hi;
        } else {
          break;
        }
      }
      settle(lo, hi);
    };
    const auto swapped = [&](std::uint32_t e) {
      return position[crossings[e].left_at_top] > position[crossings[e].right_at_top];
    };

    if (g_end == g + 1 && s.carried_crossings.empty()) {
      // Usually one pair crosses at a height and nothing is carried: its range alone, with none of the
      // bookkeeping of several ranges below (the same range, so the same sort and the same states).
      const std::size_t pa = position[crossings[g].left_at_top];
      const std::size_t pb = position[crossings[g].right_at_top];
      const std::size_t lo = std::min(pa, pb);
      const std::size_t hi = std::max(pa, pb);
      if (hi == lo + 1) {
        // Most often the pair is adjacent: repair's insertion sort of two and its two tests of the
        // neighbours, with each x computed once. Where a neighbour is out of order, repair does it all.
        const std::uint32_t a = order[lo];
        const std::uint32_t b = order[hi];
        const double ka = key(a);
        const double kb = key(b);
        const bool swap = kb < ka;
        const double k_first = swap ? kb : ka;
        const double k_second = swap ? ka : kb;
        if (!(lo > 0 && k_first < key(order[lo - 1])) && !(hi + 1 < n && key(order[hi + 1]) < k_second)) {
          order[lo] = swap ? b : a;
          order[hi] = swap ? a : b;
          visited += 2 + (swap ? 1 : 0);
          settle(lo, hi);
        } else {
          repair(lo, hi);
        }
      } else {
        repair(lo, hi);
      }
      if (!swapped(static_cast<std::uint32_t>(g)))
        s.carried_crossings.push_back(static_cast<std::uint32_t>(g));
      g = g_end;
      continue;
    }
    // The pairs crossing here, and those of earlier heights that the order at the middle of their
    // sub-band did not swap yet (their heights rounded a hair too high, above a sub-band thinner than the
    // rounding: they swap in the next one).
    for (std::size_t e = g; e < g_end; ++e) s.carried_crossings.push_back(static_cast<std::uint32_t>(e));
    s.repair_ranges.clear();
    for (const std::uint32_t e : s.carried_crossings) {
      const std::size_t pa = position[crossings[e].left_at_top];
      const std::size_t pb = position[crossings[e].right_at_top];
      s.repair_ranges.push_back({std::min(pa, pb), std::max(pa, pb)});
    }
    if (s.repair_ranges.size() > 1) std::sort(s.repair_ranges.begin(), s.repair_ranges.end());
    std::size_t r = 0;
    while (r < s.repair_ranges.size()) {
      const std::size_t lo = s.repair_ranges[r].first;
      std::size_t hi = s.repair_ranges[r].second;
      for (++r; r < s.repair_ranges.size() && s.repair_ranges[r].first <= hi; ++r)
        hi = std::max(hi, s.repair_ranges[r].second);
      repair(lo, hi);
    }
    // Pairs that have swapped are done (two straight pieces cross once); the others are carried.
    std::erase_if(s.carried_crossings, swapped);
    g = g_end;
  }
  s.stats.pieces_visited += visited;

  // 4. Close the runs still open at the bottom of the band.
  for (std::size_t i = 0; i < n; ++i) {
    if (boundary_sign[i] != 0) emit_run(s, pieces[i], run_start[i], yb, boundary_sign[i], whole_row);
  }
  s.stats.pieces_visited += n;
  return true;
}

namespace {

/// One sub-scanline through the pieces s.pieces, whose x at the sample height are in s.sample_x: adds,
/// for every boundary of the filled set along the sub-scanline, a vertical piece of height `weight` at its
/// x. s.sample_order holds the order of the previous sub-scanline when it is of the same pieces, or is
/// empty. `winding_left` is the winding number left of every piece.
void add_sub_scanline(ScanState& s, FillRule rule, double weight, int winding_left) {
  const std::size_t n = s.sample_x.size();
  if (s.sample_order.size() != n) {
    s.sample_order.resize(n);
    for (std::size_t i = 0; i < n; ++i) s.sample_order[i] = static_cast<std::uint32_t>(i);
  }
  // The order of the previous sub-scanline is the starting point: nearly sorted for ordinary rows, and
  // never worse than O(n log n) (adaptive_sort).
  const double* x = s.sample_x.data();
  s.stats.pieces_visited +=
      adaptive_sort(s.sample_order.data(), n, [x](std::uint32_t a, std::uint32_t b) { return x[a] < x[b]; });
  int winding = winding_left;
  bool filled = is_filled(winding, rule);
  for (const std::uint32_t i : s.sample_order) {
    winding += s.pieces[i].dir;
    const bool now = is_filled(winding, rule);
    if (now == filled) continue;
    filled = now;
    s.row.add_boundary(x[i], x[i], weight, now ? 1.0 : -1.0);
  }
}

}  // namespace

void sample_band(ScanState& s, double ya, double yb, FillRule rule, int winding_left) {
  const double h = yb - ya;
  const int subs = std::max(1, static_cast<int>(std::ceil(kSubScanlines * h)));
  const double weight = h / subs;
  const std::size_t n = s.pieces.size();
  s.sample_x.resize(n);
  s.sample_order.clear();
  for (int k = 0; k < subs; ++k) {
    const double t = (k + 0.5) / subs;
    for (std::size_t i = 0; i < n; ++i)
      s.sample_x[i] = s.pieces[i].xa + (s.pieces[i].xb - s.pieces[i].xa) * t;
    add_sub_scanline(s, rule, weight, winding_left);
  }
  ++s.stats.sampled_bands;
}

void sample_row_exact_in_x(ScanState& s, int y, FillRule rule, int winding_left) {
  const double weight = 1.0 / kSubScanlines;
  // Every active edge takes part in every sub-scanline, with its x clamped to its ends and no direction
  // where it does not meet the sub-scanline (top-inclusive, as the aliased mode). The row's edges are
  // copied once into s.sample_edges (in the active list's x order), so that the sixteen passes read
  // contiguous memory instead of chasing edge indices through the whole fill's edges (a cache miss each,
  // once the edges outgrow the cache).
  const std::size_t n = s.active.size();
  s.sample_edges.resize(n);
  for (std::size_t p = 0; p < n; ++p) s.sample_edges[p] = s.edges[s.active[p]];
  // Each sub-scanline counts the edges' directions by column bucket and sorts only the edges of the
  // buckets that may hold a boundary (sub_scanline_columns.cpp): O(n) where the winding number stays
  // away from zero, instead of a sort of the whole row sixteen times. The row is ordered once, at its
  // last sub-scanline, so that the next row starts from x order (ties broken by slot), as before.
  for (int k = 0; k < kSubScanlines; ++k) {
    const double yc = y + (k + 0.5) * weight;
    s.stats.pieces_visited += add_sub_scanline_by_columns(s, yc, rule, weight, winding_left);
  }
  s.stats.pieces_visited += order_row_by_x(s, y + (kSubScanlines - 0.5) * weight);
  ++s.stats.sampled_rows;
}

}  // namespace curvescan::detail
