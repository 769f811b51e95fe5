// The planar proof of a fill of few chains (at most kFewChains): the whole-fill sweep of
// rasterizer_planar.cpp (its essay gives the argument), cut down to what such a fill needs.
//
// Most fills are small: a circle is two or three chains, a glyph a handful per contour, and 179 of the
// tiger's 224 fills are at most 16. For them the proof is a fixed cost per fill, and the general sweep's
// means of keeping an event's work to the chains it touches among many (the chains sorted by bottom,
// positions numbered lazily, the list of changed places), and the vectors it keeps its order in, cost
// more than the passes over every open chain they save. Here the chains by top and the open chains in x
// order sit in two small arrays on the stack; an event drops the chains that end in one pass over the
// open ones and finds the next bottom in the same pass, places each chain that starts by a binary search,
// and rechecks and rewinds from the first changed place to the end. Those are the general sweep's own
// steps among at most 16 open chains (its kFewOpenChains), in the same order, with the same checks.
//
// Crossings are gone through as in the general sweep (Bentley and Ottmann): the same queue (a heap in
// ScanState::planar_crossings, so events of one height pop in the same order), the same swaps and
// checks. A crossing's chain is found by a search of the few open chains; the general sweep's lazy
// numbering of places is kept only to count the steps it would count. Handing a crossing fill to the
// general sweep instead (from the top) cost more than it saved: docs/benchmarks.md.
//
// So a fill swept here leaves the same boundary pieces in the same order, resolves the same crossings and
// counts the same steps (it gives up where the general sweep does) as the general sweep would: the
// accumulation, and so every byte of output, is unchanged (tests/unit/raster/planar_few_chains_test.cpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "planar_checks.h"
#include "rasterizer_impl.h"

namespace curvescan::detail {

bool prove_planar_few(ScanState& s, FillRule rule) {
  const ClippedEdge* const edges = s.edges.data();
  PlanarChain* const chain_at = s.planar_chains.data();
  const std::size_t chain_count = s.planar_chains.size();
  if (chain_count == 0 || chain_count > kFewChains) return false;

  // The chains by top: an insertion sort, stable, as std::sort is on this few (the general sweep's order
  // of chains that start at one height, so the same order of coincident ones). The tops are sorted beside
  // the ids (tops[i] is by_top[i]'s top), so the sort and the sweep's test of the next start compare
  // them without going through the chains.
  std::uint32_t by_top[kFewChains];
  double tops[kFewChains];
  double fill_bottom = -std::numeric_limits<double>::infinity();
  for (std::uint32_t c = 0; c < chain_count; ++c) {
    const double top = chain_at[c].top;
    fill_bottom = std::max(fill_bottom, chain_at[c].bottom);
    std::uint32_t j = c;
    for (; j > 0 && tops[j - 1] > top; --j) {
      by_top[j] = by_top[j - 1];
      tops[j] = tops[j - 1];
    }
    by_top[j] = c;
    tops[j] = top;
  }

  // The open chains in x order.
  std::uint32_t active[kFewChains];
  std::size_t open = 0;
  std::vector<PlanarPiece>& pieces = s.planar_pieces;
  pieces.clear();
  s.planar_open_right = false;
  // The budget and the crossings as in the general sweep.
  constexpr std::uint64_t kNotYet = ~std::uint64_t{0};
  std::uint64_t crossing_limit = kNotYet;
  const std::uint64_t base_budget = planar_proof_budget(s);
  std::uint64_t budget = base_budget;
  std::uint64_t steps = 0;
  std::uint64_t& crossings = s.stats.sweep_crossings;
  std::vector<PlanarCrossing>& pending = s.planar_crossings;
  pending.clear();
  const auto later = [](const PlanarCrossing& a, const PlanarCrossing& b) { return a.y > b.y; };
  const double fill_top = tops[0];
  // The general sweep's numbering of places, kept only to count its steps: a crossing's chain is found by
  // a search of the few open chains, but the steps counted are those of the general sweep's lookup, so
  // that a fill gives up at the same point.
  std::size_t numbered = 0;
  const auto place_of = [&](std::uint32_t c) {
    std::size_t p = 0;
    while (p < open && active[p] != c) ++p;
    if (chain_at[c].position < numbered && chain_at[c].position == p) return p;
    steps += open - std::min(numbered, open);
    for (std::size_t q = numbered; q < open; ++q)
      chain_at[active[q]].position = static_cast<std::uint32_t>(q);
    numbered = open;
    return p;
  };

  // As in the general sweep: the chain bounds the region with sign `boundary` from y down; its open piece
  // (if any) closes at y and a new one opens.
  const auto set_boundary = [&](PlanarChain& chain, std::int8_t boundary, double y) {
    if (boundary == chain.boundary) return;
    if (chain.boundary != 0) pieces[chain.open_piece].y1 = y;
    chain.boundary = boundary;
    if (boundary == 0) return;
    chain.open_piece = static_cast<std::uint32_t>(pieces.size());
    pieces.push_back({cursor_at(edges, chain, y), y, chain.bottom, static_cast<double>(boundary)});
  };
  // As in the general sweep: neighbours `l` and `r` checked from y down to where the first of them ends;
  // their first crossing, if any, is queued (false when crossings are not resolved).
  const auto check_pair = [&](std::uint32_t l, std::uint32_t r, double y) {
    PlanarChain& left = chain_at[l];
    PlanarChain& right = chain_at[r];
    if (settled_by_extent(left, r, right)) return true;
    left.checked_right = r;
    if (proven_in_order(left, r)) {
      left.cross_y = std::numeric_limits<double>::infinity();
      return true;
    }
    cursor_at(edges, left, y);
    cursor_at(edges, right, y);
    left.cross_y = first_crossing(edges, left, right, y, std::min(left.bottom, right.bottom), steps);
    if (left.cross_y == std::numeric_limits<double>::infinity()) {
      remember_in_order(left, r);
      return true;
    }
    if (crossing_limit == kNotYet) {
      crossing_limit = sweep_crossing_limit(s);
      budget = base_budget + kSweepStepsPerCrossing * crossing_limit;
    }
    if (crossing_limit == 0) return false;
    pending.push_back({left.cross_y, l, r});
    std::push_heap(pending.begin(), pending.end(), later);
    return true;
  };

  std::size_t next = 0;  // the next chain to start, in by_top
  double y = fill_top;
  while (true) {
    // The chains that end at y leave (their open pieces end here), and the next bottom is found.
    double y_next = std::numeric_limits<double>::infinity();
    std::size_t first_changed = kFewChains;
    steps += open;
    std::size_t kept = 0;
    for (std::size_t p = 0; p < open; ++p) {
      const std::uint32_t c = active[p];
      PlanarChain& chain = chain_at[c];
      if (chain.bottom <= y) {
        if (chain.boundary != 0) pieces[chain.open_piece].y1 = y;
        first_changed = std::min(first_changed, kept);
        continue;
      }
      y_next = std::min(y_next, chain.bottom);
      active[kept++] = c;
    }
    open = kept;
    // The chains that start at y enter at their place in the x order at y.
    for (; next < chain_count && tops[next] <= y; ++next) {
      const std::uint32_t c = by_top[next];
      const PlanarChain& chain = chain_at[c];
      std::uint32_t* const at = active + place_among(edges, chain_at, active, open, chain.head, y, steps);
      std::copy_backward(at, active + open, active + open + 1);
      *at = c;
      ++open;
      first_changed = std::min(first_changed, static_cast<std::size_t>(at - active));
      y_next = std::min(y_next, chain.bottom);
      steps += open;
      if (steps > budget) return false;
    }
    if (next < chain_count) y_next = std::min(y_next, tops[next]);
    if (open == 0) {
      pending.clear();  // only crossings of chains that have ended
      if (next == chain_count) return true;
      y = y_next;
      continue;
    }

    // From the first changed place to the end: each chain's check against a new left neighbour (down to
    // where the first of the two ends), then the winding number right of it and its boundary state.
    numbered = std::min(numbered, first_changed);
    std::size_t p = first_changed;
    int winding = p > 0 && p < open ? chain_at[active[p - 1]].winding_right : 0;
    bool filled = is_filled(winding, rule);
    for (; p < open; ++p) {
      PlanarChain& chain = chain_at[active[p]];
      if (p > 0 && chain_at[active[p - 1]].checked_right != active[p] &&
          !check_pair(active[p - 1], active[p], y)) {
        return false;
      }
      set_boundary(chain, step_winding(chain, winding, filled, rule), y);
      ++steps;
    }
    // Still filled right of the last chain: the region goes on past the clip's right side.
    if (is_filled(chain_at[active[open - 1]].winding_right, rule)) s.planar_open_right = true;

    // The crossings above the next start or end, as in the general sweep (its comments say why).
    while (!pending.empty() && pending.front().y < y_next) {
      std::pop_heap(pending.begin(), pending.end(), later);
      const PlanarCrossing event = pending.back();
      pending.pop_back();
      if (!crossing_stands(event, chain_at, y)) continue;
      const double yc = event.y;
      const std::size_t q = place_of(event.left);
      if (q + 1 >= open || active[q + 1] != event.right) continue;
      if (++crossings > crossing_limit) return false;
      swap_at_crossing(active, q, chain_at, rule, yc, set_boundary);
      if (q > 0) check_pair(active[q - 1], active[q], yc);
      check_pair(active[q], active[q + 1], yc);
      if (chain_at[active[q]].cross_y <= yc) return false;
      if (q + 2 < open) check_pair(active[q + 1], active[q + 2], yc);
      steps += 8;
      if (steps > budget) return false;
    }
    if (steps > budget) return false;
    const double height = fill_bottom - fill_top;
    const double swept = y_next - fill_top;
    if (crossings >= kSweepCrossingsSample && height > swept &&
        static_cast<double>(crossings) * height > static_cast<double>(crossing_limit) * swept) {
      return false;
    }
    y = y_next;
  }
}

}  // namespace curvescan::detail
