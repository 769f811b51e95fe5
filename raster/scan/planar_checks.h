// The two comparisons of monotone chains on which the whole-fill sweep's planar proof rests
// (rasterizer_planar.cpp, essay there), shared by its general sweep and by the proof of a fill of few
// chains (rasterizer_planar_few.cpp): where two neighbouring chains first cross, and in which order two
// chains that meet at a height go.
#pragma once

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>

#include "edge_clip.h"
#include "rasterizer_impl.h"

namespace curvescan::detail {

/// How far a chain may be right of its right neighbour and still count as left of it: rounding of x at a
/// joint height (x_at), and of the crossing points the clipper computes on the clip's left side, is a few
/// ulps of coordinates below 2^30; a real crossing that small adds a sliver at most this wide to the wrong
/// side, an area error below 1e-8 per pixel.
inline constexpr double kOrderSlack = 1.0 / (1 << 26);

[[nodiscard]] inline bool right_of(double x, double reference) noexcept {
  return x > reference + kOrderSlack;
}

/// Whether chain `left` stays at or left of chain `right` at every height, by their x extents alone: the
/// greatest x of `left`'s vertices at or left of the least x of `right`'s. Then first_crossing would walk
/// their joints to find no crossing; this certificate costs two loads and a comparison. It holds for the
/// two sides of a convex shape (a circle: its left side's greatest x is the x of its top and bottom, the
/// right side's least x the same), for shapes side by side (a row of dashes, the letters of a word) and
/// for a hole's sides against the outline around it where the hole lies between them. It is exact, not
/// rounded: every x first_crossing compares lies between its edge's two ends, inside the extent, so the
/// two agree wherever that interpolation does not round outside its edge's ends (by an ulp or two of the
/// coordinates, far below kOrderSlack for coordinates below 2^24).
[[nodiscard]] inline bool in_order_by_extent(const PlanarChain& left, const PlanarChain& right) noexcept {
  return left.x_max <= right.x_min;
}

/// Settles the pair of neighbours `left` and `right` (id `right_id`) by their x extents alone, when they are
/// apart (in_order_by_extent): `right` is then left's checked neighbour, with no crossing. False when the
/// extents overlap and the pair's joints must be walked (first_crossing).
inline bool settled_by_extent(PlanarChain& left, std::uint32_t right_id, const PlanarChain& right) noexcept {
  if (!in_order_by_extent(left, right)) return false;
  left.checked_right = right_id;
  left.cross_y = std::numeric_limits<double>::infinity();
  return true;
}

/// Whether chain `right_id` is one that a walk of first_crossing already proved to stay at or right of
/// `left` down to the lower of their bottoms (PlanarChain::proven_right). The sweep only goes down and the
/// two bottoms do not change, so that proof covers every later check of the pair: the walk would return
/// +infinity again. (Its first comparison, at the sweep height, is of x values interpolated inside a joint
/// interval at whose ends the pair was in order; the difference is linear there, so it stays in order up
/// to a rounding of a few ulps, far below kOrderSlack.) Two are kept because a stroke's two sides are
/// parted by a round join's short chain and meet again below it, while the side meanwhile was proven
/// against the join's chain. In the 20 px stroke of 50 cubics (bench/stroke_bench.cpp), of the 2,268
/// walks of a pair already proven in order, one slot finds 1,094, two 1,957 and four 2,162.
/// The one found goes to the front (the least recently used is the one a new proof replaces).
[[nodiscard]] inline bool proven_in_order(PlanarChain& left, std::uint32_t right_id) noexcept {
  if (left.proven_right[0] == right_id) return true;
  if (left.proven_right[1] != right_id) return false;
  std::swap(left.proven_right[0], left.proven_right[1]);
  return true;
}

/// Records that a walk proved chain `right_id` to stay at or right of `left` (proven_in_order).
inline void remember_in_order(PlanarChain& left, std::uint32_t right_id) noexcept {
  left.proven_right[1] = left.proven_right[0];
  left.proven_right[0] = right_id;
}

/// One chain passed from left to right in the sweep's x order: the winding number right of it (from
/// `winding`, the number left of it; both updated, and the chain keeps it) and the sign with which it
/// bounds the filled region from here down: +1 where the region starts, -1 where it stops, 0 where it
/// is filled or empty on both sides. `filled` follows the winding number.
[[nodiscard]] inline std::int8_t step_winding(PlanarChain& chain, int& winding, bool& filled,
                                              FillRule rule) noexcept {
  winding += chain.dir;
  chain.winding_right = winding;
  const bool now = is_filled(winding, rule);
  const std::int8_t boundary = now == filled ? 0 : (now ? 1 : -1);
  filled = now;
  return boundary;
}

/// Whether queued crossing `event` still stands at sweep height y: its pair were last checked against each
/// other with this crossing found, and neither has ended (a chain that ended at or above y is not open).
/// A stale event (the pair parted, or was checked again since) is dropped: the pair's current crossing,
/// if any, was queued anew.
[[nodiscard]] inline bool crossing_stands(const PlanarCrossing& event, const PlanarChain* chain_at,
                                          double y) noexcept {
  const PlanarChain& left = chain_at[event.left];
  return left.checked_right == event.right && left.cross_y == event.y && left.bottom > y &&
         chain_at[event.right].bottom > y;
}

/// The neighbours at places q and q + 1 of the x order `order` swap at the crossing at height yc (Bentley
/// and Ottmann): only the winding number between them changes, so only their boundary states, set from yc
/// down through `set_boundary(chain, sign, yc)`.
template <class SetBoundary>
inline void swap_at_crossing(std::uint32_t* order, std::size_t q, PlanarChain* chain_at, FillRule rule,
                             double yc, SetBoundary& set_boundary) {
  std::swap(order[q], order[q + 1]);
  chain_at[order[q]].position = static_cast<std::uint32_t>(q);
  chain_at[order[q + 1]].position = static_cast<std::uint32_t>(q + 1);
  int winding = q > 0 ? chain_at[order[q - 1]].winding_right : 0;
  bool filled = is_filled(winding, rule);
  for (std::size_t r = q; r <= q + 1; ++r) {
    PlanarChain& chain = chain_at[order[r]];
    set_boundary(chain, step_winding(chain, winding, filled, rule), yc);
  }
}

/// The edge of open chain `chain` holding height y (y_top <= y < y_bot; the chain's bottom is below y);
/// the chain's cursor moves there. The sweep's heights never decrease, so a cursor passes each edge of its
/// chain once, however many events the chain stays open over, and only when the chain is read.
inline std::uint32_t cursor_at(const ClippedEdge* edges, PlanarChain& chain, double y) noexcept {
  std::uint32_t e = chain.cursor;
  while (edges[e].y_bot <= y) e = edges[e].below;
  chain.cursor = e;
  return e;
}

/// A walk down two neighbouring chains (first_crossing, first_crossing_by_blocks): the edges `a` (of the
/// left chain) and `b` holding the current height, and the difference of their x (left − right) at the
/// last height compared, `y_above`.
struct NeighbourWalk {
  std::uint32_t a;
  std::uint32_t b;
  double y_above;
  double d_above;

  /// The crossing inside [y_above, y] where the difference goes from d_above (at or left) to d (right).
  [[nodiscard]] double crossing_at(double y, double d) const noexcept {
    const double t = std::clamp(-d_above / (d - d_above), 0.0, 1.0);
    return std::clamp(y_above + t * (y - y_above), y_above, y);
  }

  /// Compares the two chains at the next joint height of either (or at y1, the end of the walk): true,
  /// with `answer` the crossing's height or +infinity (in order down to y1), when the walk ends there.
  /// At each joint height y (below the cursors' start) one of the two edges ends there, at its bottom x,
  /// and the other holds y above its top: the x values x_at would give, without its clamps.
  [[gnu::always_inline]] bool step(const ClippedEdge* edges, double y1, double& answer) noexcept {
    const ClippedEdge& ea = edges[a];
    const ClippedEdge& eb = edges[b];
    double y = 0.0;
    double d = 0.0;
    if (ea.y_bot <= eb.y_bot) {
      y = ea.y_bot;
      if (y >= y1) {
        d = ea.x_at(y1) - eb.x_at(y1);
        answer = d > kOrderSlack ? crossing_at(y1, d) : std::numeric_limits<double>::infinity();
        return true;
      }
      const double xb = eb.y_bot == y ? eb.x_bot : eb.x_top + (y - eb.y_top) * eb.dxdy;
      d = ea.x_bot - xb;
      if (eb.y_bot == y) b = eb.below;
      a = ea.below;
    } else {
      y = eb.y_bot;
      if (y >= y1) {
        d = ea.x_at(y1) - eb.x_at(y1);
        answer = d > kOrderSlack ? crossing_at(y1, d) : std::numeric_limits<double>::infinity();
        return true;
      }
      d = ea.x_top + (y - ea.y_top) * ea.dxdy - eb.x_bot;
      b = eb.below;
    }
    if (d > kOrderSlack) {
      answer = crossing_at(y, d);
      return true;
    }
    y_above = y;
    d_above = d;
    return false;
  }
};

/// Where chain `left` first passes right of chain `right` in [y0, y1] (both cursors hold y0), or +infinity
/// when it stays at or left of it over the whole interval. Both are linear between consecutive joint
/// heights of either, so their difference is too: it is looked at every joint height, and the first
/// joint interval at whose bottom `left` is right of `right` holds the crossing, at the zero of that
/// linear difference (clamped to the interval, rounding aside). Counts the joints walked into `steps`.
inline double first_crossing(const ClippedEdge* edges, const PlanarChain& left, const PlanarChain& right,
                             double y0, double y1, std::uint64_t& steps) {
  NeighbourWalk walk{left.cursor, right.cursor, y0,
                     edges[left.cursor].x_at(y0) - edges[right.cursor].x_at(y0)};
  if (walk.d_above > kOrderSlack) return y0;
  double answer = 0.0;
  while (true) {
    ++steps;
    if (walk.step(edges, y1, answer)) return answer;
  }
}

/// Writes the PlanarBlock entry of every edge of `chain` (ScanState::planar_blocks, `blocks`): its edges
/// cut into blocks of kPlanarBlockEdges from its head down, each edge's entry the x extent of the vertices
/// from its top to its block's last edge's bottom (linked edges share their joint's point, so each edge adds
/// its top).
inline void build_chain_blocks(const ClippedEdge* edges, PlanarBlock* blocks, PlanarChain& chain) noexcept {
  chain.blocks_built = true;
  std::uint32_t in_block[kPlanarBlockEdges];
  std::uint32_t e = chain.head;
  while (e != ClippedEdge::kNoEdge) {
    std::size_t n = 0;
    for (; n < kPlanarBlockEdges && e != ClippedEdge::kNoEdge; ++n, e = edges[e].below) in_block[n] = e;
    const std::uint32_t last = in_block[n - 1];
    const double y_end = edges[last].y_bot;
    double x_min = edges[last].x_bot;
    double x_max = x_min;
    for (std::size_t i = n; i-- > 0;) {
      const double x = edges[in_block[i]].x_top;
      x_min = std::min(x_min, x);
      x_max = std::max(x_max, x);
      blocks[in_block[i]] = {x_min, x_max, y_end, last};
    }
  }
}

/// first_crossing's answer (and its walk from the first joint where it does not pass the joints at once),
/// with the joints passed a block at a time where the two chains' blocks (build_chain_blocks) are apart in x:
/// left's x from its cursor's edge to its block's end at or left of right's from its cursor's edge to its
/// own, so down to the nearer of the two block ends every joint compared would be in order (the argument of
/// in_order_by_extent: every x the walk compares lies inside its edge's ends, up to an ulp of the
/// interpolation, far below kOrderSlack), and the walk goes on from the edges holding that height, where it
/// compares what first_crossing compares there. The same result as first_crossing; `steps` counts one
/// per pass of a block and per joint walked.
inline double first_crossing_by_blocks(const ClippedEdge* edges, const PlanarBlock* blocks,
                                       const PlanarChain& left, const PlanarChain& right, double y0,
                                       double y1, std::uint64_t& steps) {
  constexpr double kNever = std::numeric_limits<double>::infinity();
  NeighbourWalk walk{left.cursor, right.cursor, y0,
                     edges[left.cursor].x_at(y0) - edges[right.cursor].x_at(y0)};
  if (walk.d_above > kOrderSlack) return y0;
  double answer = 0.0;
  while (true) {
    const PlanarBlock& block_a = blocks[walk.a];
    const PlanarBlock& block_b = blocks[walk.b];
    if (block_a.x_max <= block_b.x_min) {
      ++steps;
      // In order down to the nearer block end: past y1, the pair is proven; else the walk resumes at the
      // joint at that height, from the edges that hold it (one of them ends there). Its comparison there
      // is in order too, so y_above and d_above are set by it before a crossing could read them.
      if (block_a.y_end <= block_b.y_end) {
        if (block_a.y_end >= y1) return kNever;
        walk.a = block_a.last;
        while (edges[walk.b].y_bot < block_a.y_end) walk.b = edges[walk.b].below;
      } else {
        if (block_b.y_end >= y1) return kNever;
        walk.b = block_b.last;
        while (edges[walk.a].y_bot < block_b.y_end) walk.a = edges[walk.a].below;
      }
    }
    ++steps;
    if (walk.step(edges, y1, answer)) return answer;
  }
}

/// The order of two chains meeting at height y (a from edge `a`, b from edge `b`, both holding y): by x at
/// y, and where they meet, by x at the first joint height below where they part (a contour's top tip
/// starts two chains at one point; the clipper puts coincident vertical pieces on the clip's left side
/// that part further down). Chains that never part are equal (any order of them bounds zero area). Only
/// the choice of an order: the proof checks it. Counts the joints walked into `steps`.
inline bool chain_before(const ClippedEdge* edges, std::uint32_t a, std::uint32_t b, double y,
                         std::uint64_t& steps) {
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

/// Whether the open chain at `at` (its cursor moved to y) goes before a chain starting at height y from edge
/// `head` whose x there is x_new: place_among's probe, the same comparisons.
inline bool goes_before(const ClippedEdge* edges, PlanarChain& at, std::uint32_t head, double x_new, double y,
                        std::uint64_t& steps) {
  const std::uint32_t a = cursor_at(edges, at, y);
  const double x = edges[a].x_at(y);
  return right_of(x_new, x) ? true : right_of(x, x_new) ? false : chain_before(edges, a, head, y, steps);
}

/// The place of a chain starting at height y (its first edge `head`) beside the chain just placed at
/// place `near` of `ids[0, count)` that starts at the same point (a contour's top tip starts two chains
/// there: a dash's two sides): place_among's answer where the probes on either side of the boundary
/// agree with it (the chain at `near` goes before and the one after it does not, or the other way
/// round), found with two probes instead of a binary search; kNoPlace when they do not, and place_among
/// is asked.
inline constexpr std::size_t kNoPlace = std::numeric_limits<std::size_t>::max();

inline std::size_t place_beside(const ClippedEdge* edges, PlanarChain* chain_at, const std::uint32_t* ids,
                                std::size_t count, std::size_t near, std::uint32_t head, double y,
                                std::uint64_t& steps) {
  const double x_new = edges[head].x_at(y);
  if (goes_before(edges, chain_at[ids[near]], head, x_new, y, steps)) {
    if (near + 1 == count || !goes_before(edges, chain_at[ids[near + 1]], head, x_new, y, steps))
      return near + 1;
  } else if (near == 0 || goes_before(edges, chain_at[ids[near - 1]], head, x_new, y, steps)) {
    return near;
  }
  return kNoPlace;
}

/// The place of a chain starting at height y (its first edge `head`) among the open chains `ids[0, count)`
/// in x order: std::partition_point of chain_before over them (the same probes, so the same place among
/// chains that meet it at y), with the new chain's x at y taken once (chain_before's first comparison,
/// made here; its walk below y only where the two meet). Moves the probed chains' cursors to y.
inline std::size_t place_among(const ClippedEdge* edges, PlanarChain* chain_at, const std::uint32_t* ids,
                               std::size_t count, std::uint32_t head, double y, std::uint64_t& steps) {
  const double x_new = edges[head].x_at(y);
  const std::uint32_t* first = ids;
  std::size_t len = count;
  while (len > 0) {
    const std::size_t half = len >> 1;
    const std::uint32_t a = cursor_at(edges, chain_at[first[half]], y);
    const double x = edges[a].x_at(y);
    const bool before = right_of(x_new, x)   ? true
                        : right_of(x, x_new) ? false
                                             : chain_before(edges, a, head, y, steps);
    if (before) {
      first += half + 1;
      len -= half + 1;
    } else {
      len = half;
    }
  }
  return static_cast<std::size_t>(first - ids);
}

}  // namespace curvescan::detail
