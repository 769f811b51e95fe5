// The planar fast path of the exact scan (essay in rasterizer.cpp, step 8).
//
// Most fills are planar: no two of their edges cross (glyphs, icons, most shapes). Then the filled region's
// boundary is known before any row is scanned, and the rows need no bands, no sorting and no rule
// resolution: each boundary edge just adds its signed area to the rows it crosses (coverage_row.h), the
// plain accumulation of font-rs and FreeType, which is exact here because only the true boundary is added.
//
// The proof. Edges linked end to end (link_contour_edges) form y-monotone chains; a chain starts and ends
// only at a y-extremum of its contour or where the clipper cut it. A sweep goes down the chains' tops and
// bottoms (the events). Between two consecutive events the set of chains is fixed; they are kept in x
// order, and every pair of neighbours in that order must stay in order (left at or left of right) over
// the whole interval: both are piecewise linear in y, so comparing them at every joint height of either is
// exact (their difference is linear in between). If every neighbouring pair stays in order, the order is
// one sorted order at every height of the interval (a swap of any two would need a swap of two neighbours
// first), so the winding number between consecutive chains is the prefix sum of their directions,
// constant over the interval, and a chain across which the rule's filled state flips is a boundary of the
// filled region there, with sign +1 (enter) or -1 (leave). Touching and coincident chains pass (any order
// of coincident chains bounds zero area), so contours drawn twice, shared edges and the vertical edges the
// clipper puts on the clip's left side stay on this path. A pair found out of order proves nothing about
// the fill: the caller falls back to the row scan, which resolves crossings.
//
// Each pair is checked once: when the two become neighbours (at an event, by an insertion or a removal
// between them), from that height down to where the first of them ends, and remembered
// (PlanarChain::checked_right), so a pair that stays neighbours over many events, or that is parted by a
// hole and meets again below it, is not walked again. That covers every interval: a pair that is
// neighbours in an interval became neighbours at its top or earlier, and was checked from then down to
// below the interval. This is the argument of Shamos and Hoey ("Geometric intersection problems", 1976:
// only segments that become adjacent in the sweep order need testing), for monotone chains.
//
// Cost: O(n) to build the chains, O(c log c) to order their tops, and per event one pass over the active
// chains (removals, cursors and the next event; the checks of new neighbours and the windings) plus the
// joints walked by the checks (each joint about twice per neighbour the chain has over its life). The
// proof is abandoned (row scan instead) once it has done 32·n + 4096 steps, so a fill whose events each
// see thousands of chains (a fine comb) costs at most a constant times its edge count here before taking
// the usual path. The accumulation is O(edge pieces per row + touched cells), like the row scan's
// cheapest case; a chain's pieces that stay in one column of a row are summed before they reach the row
// (CoverageRow::add_chain_piece).
//
// In double arithmetic, a neighbour check compares x values computed at joint heights: a pair crossing by
// less than one rounding error may pass and adds a sliver of that width to the wrong side (the same class
// of error as the crossing heights of the row scan, far below 1/255); a touching pair that rounds apart
// fails the proof and is resolved by the row scan. Either way the output is the exact coverage up to
// rounding.
#include <algorithm>
#include <cmath>
#include <limits>

#include "rasterizer_impl.h"

namespace curvescan::detail {

namespace {

/// How far a chain may be right of its right neighbour and still count as left of it: rounding of x at a
/// joint height (x_at), and of the crossing points the clipper computes on the clip's left side, is a few
/// ulps of coordinates below 2^30; a real crossing that small adds a sliver at most this wide to the wrong
/// side, an area error below 1e-8 per pixel.
constexpr double kOrderSlack = 1.0 / (1 << 26);

[[nodiscard]] bool right_of(double x, double reference) noexcept { return x > reference + kOrderSlack; }

/// Whether chain `left` is at or left of chain `right` at every height of [y0, y1]; both cursors hold y0.
/// Counts the joints walked into `steps`.
bool stays_left(const ClippedEdge* edges, const PlanarChain& left, const PlanarChain& right, double y0,
                double y1, std::uint64_t& steps) {
  std::uint32_t a = left.cursor;
  std::uint32_t b = right.cursor;
  if (right_of(edges[a].x_at(y0), edges[b].x_at(y0))) return false;
  // At each joint height y (below y0) one of the two edges ends there, at its bottom x, and the other
  // holds y above its top (both cursors' edges end below y0): the x values x_at would give, without its
  // clamps.
  while (true) {
    ++steps;
    const ClippedEdge& ea = edges[a];
    const ClippedEdge& eb = edges[b];
    if (ea.y_bot <= eb.y_bot) {
      const double y = ea.y_bot;
      if (y >= y1) return !right_of(ea.x_at(y1), eb.x_at(y1));
      const double xb = eb.y_bot == y ? eb.x_bot : eb.x_top + (y - eb.y_top) * eb.dxdy;
      if (right_of(ea.x_bot, xb)) return false;
      if (eb.y_bot == y) b = eb.below;
      a = ea.below;
    } else {
      const double y = eb.y_bot;
      if (y >= y1) return !right_of(ea.x_at(y1), eb.x_at(y1));
      if (right_of(ea.x_top + (y - ea.y_top) * ea.dxdy, eb.x_bot)) return false;
      b = eb.below;
    }
  }
}

/// The order of two chains meeting at height y (a from edge `a`, b from edge `b`, both holding y): by x at
/// y, and where they meet, by x at the first joint height below where they part (a contour's top tip
/// starts two chains at one point; the clipper puts coincident vertical pieces on the clip's left side
/// that part further down). Chains that never part are equal (any order of them bounds zero area). Only
/// the choice of an order: the proof checks it. Counts the joints walked into `steps`.
bool chain_before(const ClippedEdge* edges, std::uint32_t a, std::uint32_t b, double y, std::uint64_t& steps) {
  while (true) {
    const double xa = edges[a].x_at(y);
    const double xb = edges[b].x_at(y);
    if (right_of(xb, xa)) return true;
    if (right_of(xa, xb)) return false;
    ++steps;
    const double y_bot = std::min(edges[a].y_bot, edges[b].y_bot);
    if (y_bot > y) {
      y = y_bot;
      continue;
    }
    if (edges[a].y_bot == y) a = edges[a].below;
    if (edges[b].y_bot == y) b = edges[b].below;
    if (a == ClippedEdge::kNoEdge || b == ClippedEdge::kNoEdge) return false;
  }
}

}  // namespace

bool prove_planar(ScanState& s, FillRule rule) {
  const ClippedEdge* edges = s.edges.data();
  const std::size_t n = s.edges.size();
  std::vector<PlanarChain>& chains = s.planar_chains;
  chains.clear();
  for (std::uint32_t i = 0; i < n; ++i) {
    if (edges[i].linked_above) continue;
    std::uint32_t j = i;
    while (edges[j].below != ClippedEdge::kNoEdge) j = edges[j].below;
    chains.push_back(
        {i, i, edges[i].y_top, edges[j].y_bot, edges[i].dir, PlanarChain::kNone, PlanarChain::kNone});
  }
  std::vector<std::uint32_t>& order = s.planar_order;
  order.resize(chains.size());
  for (std::uint32_t c = 0; c < chains.size(); ++c) order[c] = c;
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return chains[a].top < chains[b].top; });

  // Sizes and data pointers read once: the loops below write chains and pieces through references, so
  // the compiler would otherwise reload every vector's bounds at each use.
  const std::size_t chain_count = order.size();
  const std::uint32_t* const by_top = order.data();
  PlanarChain* const chain_at = chains.data();
  const std::uint64_t budget = 32 * std::uint64_t{n} + 4096;
  std::uint64_t steps = 0;
  std::vector<std::uint32_t>& active = s.planar_active;
  active.clear();
  s.planar_pieces.clear();
  s.planar_open_right = false;
  std::size_t next = 0;
  double y = chains[order[0]].top;
  while (true) {
    // One pass over the chains met so far: those that ended at y leave, the others move their cursor to
    // the edge holding y, and the next event is the first bottom or the next top.
    double y_next = std::numeric_limits<double>::infinity();
    std::size_t kept = 0;
    for (const std::uint32_t c : active) {
      PlanarChain& chain = chain_at[c];
      if (chain.bottom <= y) {
        // Ends at this event (bottoms are events): its boundary piece, if one is open, ends here too.
        if (chain.boundary != 0) s.planar_pieces[chain.open_piece].y1 = y;
        continue;
      }
      while (edges[chain.cursor].y_bot <= y) chain.cursor = edges[chain.cursor].below;
      y_next = std::min(y_next, chain.bottom);
      active[kept++] = c;
    }
    active.resize(kept);
    // Chains that start at y enter at their place in the x order at y.
    for (; next < chain_count && chain_at[by_top[next]].top <= y; ++next) {
      const PlanarChain& chain = chain_at[by_top[next]];
      const auto at = std::partition_point(active.begin(), active.end(), [&](std::uint32_t c) {
        return chain_before(edges, chain_at[c].cursor, chain.head, y, steps);
      });
      active.insert(at, by_top[next]);
      y_next = std::min(y_next, chain.bottom);
      steps += active.size();
      // Checked per insertion: placing a chain among coincident ones walks them until they part.
      if (steps > budget) return false;
    }
    if (next < chain_count) y_next = std::min(y_next, chain_at[by_top[next]].top);
    if (active.empty()) {
      if (next == chain_count) return true;
      y = y_next;
      continue;
    }
    steps += 2 * active.size();

    // One pass left to right: each chain's check against its left neighbour, then the winding number
    // right of it and whether it bounds the filled region. Only neighbours that were not neighbours
    // before are checked, each down to where the first of them ends (Shamos and Hoey's argument, in the
    // essay above). A chain's boundary piece stays open (its end not yet written) while the chain bounds
    // the region with the same sign, so an interval that changes nothing for the chain writes nothing;
    // the piece is closed where that changes or where the chain ends.
    int winding = 0;
    bool filled = false;
    const std::uint32_t* const in_order = active.data();
    const std::size_t active_count = active.size();
    for (std::size_t p = 0; p < active_count; ++p) {
      PlanarChain& chain = chain_at[in_order[p]];
      if (p > 0) {
        PlanarChain& left = chain_at[in_order[p - 1]];
        if (left.checked_right != in_order[p]) {
          if (!stays_left(edges, left, chain, y, std::min(left.bottom, chain.bottom), steps)) return false;
          left.checked_right = in_order[p];
        }
      }
      winding += chain.dir;
      const bool now = is_filled(winding, rule);
      const std::int8_t boundary = now == filled ? 0 : (now ? 1 : -1);
      filled = now;
      if (boundary == chain.boundary) continue;  // the same as just above: its open piece (if any) goes on
      if (chain.boundary != 0) s.planar_pieces[chain.open_piece].y1 = y;
      chain.boundary = boundary;
      if (boundary == 0) continue;
      chain.open_piece = static_cast<std::uint32_t>(s.planar_pieces.size());
      // y1 is written when the piece is closed, at the latest where the chain ends.
      s.planar_pieces.push_back({chain.cursor, y, y_next, static_cast<double>(boundary)});
    }
    // Still filled right of the last chain: the region goes on past the clip's right side (the clipper
    // dropped its right edges).
    if (filled) s.planar_open_right = true;
    if (steps > budget) return false;
    y = y_next;
  }
}

void accumulate_planar(ScanState& s, SpanSink& sink) {
  const ClippedEdge* edges = s.edges.data();
  const std::vector<PlanarPiece>& pieces = s.planar_pieces;
  s.row.reset(s.clip.x0, s.clip.x1 - s.clip.x0);
  s.spans.clear();
  std::vector<std::uint32_t>& live = s.planar_row_pieces;
  live.clear();
  s.planar_cursor.resize(pieces.size());
  std::size_t next = 0;
  int y = s.clip.y0;
  while (y < s.clip.y1) {
    if (live.empty()) {
      if (next == pieces.size()) break;
      y = std::max(y, static_cast<int>(std::floor(pieces[next].y0)));
    }
    const double ya = y;
    const double yb = ya + 1.0;
    for (; next < pieces.size() && pieces[next].y0 < yb; ++next) {
      s.planar_cursor[next] = pieces[next].first_edge;
      live.push_back(static_cast<std::uint32_t>(next));
    }
    // Whether every live piece crosses the whole row along one vertical edge; then (below) the rows
    // under it repeat it for as long as those edges go on and no piece starts or ends.
    bool vertical_rows = true;
    double repeat_bottom = s.clip.y1;
    for (const std::uint32_t p : live) {
      const PlanarPiece& piece = pieces[p];
      const double top = std::max(ya, piece.y0);
      const double bottom = std::min(yb, piece.y1);
      std::uint32_t e = s.planar_cursor[p];
      while (edges[e].y_bot <= top) e = edges[e].below;
      const std::uint32_t first = e;
      while (true) {
        const ClippedEdge& edge = edges[e];
        if (edge.y_top >= top && edge.y_bot < bottom) {
          // An edge inside the piece's part of the row (most edges of a finely flattened curve): the
          // values the general case below computes (x_at is x_top and x_bot at the ends), without the
          // clamps.
          s.row.add_chain_piece(edge.x_top, edge.x_bot, edge.y_bot - edge.y_top, piece.sign);
          e = edge.below;
          continue;
        }
        const double lo = std::max(top, edge.y_top);
        const double hi = std::min(bottom, edge.y_bot);
        if (hi > lo) s.row.add_chain_piece(edge.x_at(lo), edge.x_at(hi), hi - lo, piece.sign);
        if (edge.y_bot >= bottom) break;
        e = edge.below;
      }
      s.row.end_chain();
      s.planar_cursor[p] = e;
      const ClippedEdge& edge = edges[e];
      vertical_rows = vertical_rows && e == first && edge.x_top == edge.x_bot && edge.y_top <= ya && top == ya &&
                      bottom == yb;
      repeat_bottom = std::min(repeat_bottom, std::min(edge.y_bot, piece.y1));
    }
    std::erase_if(live, [&](std::uint32_t p) { return pieces[p].y1 <= yb; });
    const std::size_t row_first_span = s.spans.size();
    s.row.emit(y, s.spans);
    ++y;
    // Every live piece is one vertical edge over the whole row: each row below that the same edges cross
    // entirely, and that no piece reaches or leaves, adds the same pieces (x_at of a vertical edge is
    // x_top at every height, h = 1), so its spans are this row's, moved down; they are copied instead of
    // accumulated (rectangles, the clip's left side, rectilinear shapes). Row r qualifies while
    // r + 1 <= every edge's and piece's bottom and the next piece's top.
    if (next < pieces.size()) repeat_bottom = std::min(repeat_bottom, pieces[next].y0);
    const int repeat_end = static_cast<int>(std::min(std::floor(repeat_bottom), static_cast<double>(s.clip.y1)));
    if (vertical_rows && !live.empty() && repeat_end > y) {
      s.planar_repeat_spans.assign(s.spans.begin() + static_cast<std::ptrdiff_t>(row_first_span), s.spans.end());
      for (; y < repeat_end; ++y) {
        hand_over_spans(s, sink, false);
        for (Span span : s.planar_repeat_spans) {
          span.y = y;
          s.spans.push_back(span);
        }
      }
      std::erase_if(live, [&](std::uint32_t p) { return pieces[p].y1 <= y; });
    }
    hand_over_spans(s, sink, false);
  }
  hand_over_spans(s, sink, true);
}

void accumulate_planar_dense(ScanState& s, IntRect box, std::span<std::uint8_t> mask) {
  const ClippedEdge* edges = s.edges.data();
  DenseCoverage& dense = s.dense;
  dense.reset(box.x0, box.y0, box.x1 - box.x0, box.y1 - box.y0);
  // Each piece once, top to bottom: its edges cut at the row lines (no list of the pieces live in a row).
  for (const PlanarPiece& piece : s.planar_pieces) {
    std::uint32_t e = piece.first_edge;
    while (true) {
      const ClippedEdge& edge = edges[e];
      const double y = piece.y0 > edge.y_top ? piece.y0 : edge.y_top;
      const double y_end = piece.y1 < edge.y_bot ? piece.y1 : edge.y_bot;
      if (y < y_end) {
        dense.add_edge(edge.x_top, edge.y_top, edge.x_bot, edge.y_bot, edge.dxdy, y, y_end, piece.sign);
      }
      if (edge.y_bot >= piece.y1) break;
      e = edge.below;
    }
  }
  dense.write_mask(mask);
}

bool accumulate_small_planar(ScanState& s, SpanSink& sink) {
  const std::size_t count = s.edges.size();
  if (count > kSmallFillEdges || s.planar_open_right) return false;
  // The edges' box (they are clipped, so it lies inside the clip box).
  double x_min = s.edges[0].x_top;
  double x_max = x_min;
  double y_min = s.edges[0].y_top;
  double y_max = s.edges[0].y_bot;
  for (const ClippedEdge& e : s.edges) {
    x_min = std::min({x_min, e.x_top, e.x_bot});
    x_max = std::max({x_max, e.x_top, e.x_bot});
    y_min = std::min(y_min, e.y_top);
    y_max = std::max(y_max, e.y_bot);
  }
  const IntRect box{std::max(s.clip.x0, static_cast<int>(std::floor(x_min))),
                    std::max(s.clip.y0, static_cast<int>(std::floor(y_min))),
                    std::min(s.clip.x1, static_cast<int>(std::ceil(x_max))),
                    std::min(s.clip.y1, static_cast<int>(std::ceil(y_max)))};
  const int width = box.x1 - box.x0;
  const int height = box.y1 - box.y0;
  if (width <= 0 || height <= 0) return true;  // a closed region of no width: no area, nothing to send
  if (width > kSmallFillColumns || std::int64_t{width} * height > kSmallFillPixels) return false;
  // Closed on the right: right of the box the winding number is that of the region's outside, so every
  // pixel with coverage lies in the box.
  s.planar_mask.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  accumulate_planar_dense(s, box, s.planar_mask);
  s.spans.clear();
  const std::uint8_t* row = s.planar_mask.data();
  for (int y = box.y0; y < box.y1; ++y, row += width) {
    // Runs of one non-zero value, as CoverageRow::emit sends them.
    int c = 0;
    while (c < width) {
      while (c < width && row[c] == 0) ++c;
      if (c == width) break;
      const int start = c;
      const std::uint8_t value = row[c];
      while (c < width && row[c] == value) ++c;
      s.spans.push_back({box.x0 + start, y, c - start, value});
    }
    hand_over_spans(s, sink, false);
  }
  hand_over_spans(s, sink, true);
  return true;
}

}  // namespace curvescan::detail
