// The whole-fill sweep of the exact scan (essay in rasterizer.cpp, step 8): the planar proof below, and its
// continuation through crossings (at the end of this comment).
//
// Most fills are planar: no two of their edges cross (glyphs, icons, most shapes). Then the filled region's
// boundary is known before any row is scanned, and the rows need no bands, no sorting and no rule
// resolution: each boundary edge just adds its signed area to the rows it crosses (coverage_row.h), the
// plain accumulation of font-rs and FreeType, which is exact here because only the true boundary is added.
//
// The proof. Edges linked end to end (link_edges_into_chains) form y-monotone chains; a chain starts and ends
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
// clipper puts on the clip's left side stay on this path. A pair found out of order has crossed: the
// sweep goes on through that crossing (below), or, with a crossing budget of 0, the caller falls back to
// the row scan, which resolves crossings.
//
// Each pair is checked once: when the two become neighbours (at an event, by an insertion or a removal
// between them), from that height down to where the first of them ends, and remembered
// (PlanarChain::checked_right), so a pair that stays neighbours over many events, or that is parted by a
// hole and meets again below it, is not walked again. A pair a walk found in order is also kept among the
// left chain's last two such proofs (PlanarChain::proven_right), so a pair parted by a short chain between
// them (a round join's piece between a stroke's two sides) and neighbours again below it is not walked
// again either. That covers every interval: a pair that is
// neighbours in an interval became neighbours at its top or earlier, and was checked from then down to
// below the interval. This is the argument of Shamos and Hoey ("Geometric intersection problems", 1976:
// only segments that become adjacent in the sweep order need testing), for monotone chains.
//
// Cost: O(n) to build the chains, O(c log c) to order their tops (and their bottoms, once more than
// kFewOpenChains are open). An event touches the chains that end or start at it: a chain that ends is
// found in the x order by its position (PlanarChain::position, exact left of the first place changed
// since the last numbering; elsewhere mostly a few places off, so looked for there first, and only then
// numbered again from that first place: about three instructions a place, far less than the pass over
// every open chain the proof first made), the gaps are closed in one pass of block moves, a chain that
// starts is placed by a binary search (the second chain from a contour's top tip beside the first, by
// two comparisons), and the windings are recomputed from each changed place only
// until the winding number left of a chain is the one it had (the changes so far sum to zero: a dash's
// two sides end together). Cursors move down when a chain is read. Among at most kFewOpenChains open
// chains the passes over all of them are cheaper and are made instead, and a fill of at most kFewChains
// chains in all (most fills: a circle, a glyph) is swept by rasterizer_planar_few.cpp, the same passes
// on a small array, without the vectors and lists the general sweep keeps. Plus the joints walked by the
// checks (each joint about twice per neighbour the chain has over its life), except for a pair whose x
// extents are apart (in_order_by_extent, planar_checks.h: the two sides of a convex shape, shapes side
// by side); in a fill of long chains (a wide stroke's sides) a walk passes a block of kPlanarBlockEdges
// edges of each at once where the two blocks' x extents are apart (first_crossing_by_blocks, the same
// answer), plus per crossing O(log) for its queue and three checks. The proof is abandoned (row scan
// instead) once it has done 32·n + 4096 steps (the chains it visits, places it numbers, ids it moves, joints
// it walks), plus 16 per crossing it may resolve once it has found one, so a fill whose events each see
// thousands of chains (a fine comb) costs at most a constant times its edge count here before taking the
// usual path. The accumulation is O(edge pieces per row + touched cells), like the row scan's cheapest case;
// a chain's pieces that stay in one column of a row are summed before they reach the row
// (CoverageRow::add_chain_piece).
//
// Through crossings (Bentley and Ottmann, "Algorithms for reporting and counting geometric intersections",
// 1979, on monotone chains). A neighbour check that finds the left chain right of the right one (beyond
// kOrderSlack) at some joint height returns the first crossing: the zero of their difference, linear in the
// joint interval where it changes sign. It is queued as an event (a heap by height); at an event whose pair
// is still neighbours and still holds that crossing (else it is stale: the pair was parted or re-checked)
// the two swap places, the winding number between them is recomputed from the one left of them (nothing
// else changes), their boundary states change there, and the three neighbour pairs around them are checked
// from there down. The chain starts and ends stay events, handled as above; the
// crossings between two such events are processed between the passes. The proof's argument carries over:
// every neighbouring pair is checked down to its first crossing, so the order is sorted at every height
// between events. The boundary pieces are cut at the crossing heights, which are rounded, but lie on the
// fill's own edges; a crossing height off by ε moves a triangle of area about ε² · |difference of the
// slopes| between the two chains' sides. A fill of more crossings than its budget (or whose crossings so
// far foretell more, or a pair that crosses back at the height it just swapped at, which rounding allows
// under a nearly horizontal edge) gives up and is scanned row by row.
//
// In double arithmetic, a neighbour check compares x values computed at joint heights: a pair crossing by
// less than one rounding error may pass and adds a sliver of that width to the wrong side (the same class
// of error as the crossing heights of the row scan, far below 1/255); a touching pair that rounds apart
// fails the proof and is resolved by the row scan. Either way the output is the exact coverage up to
// rounding.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "planar_checks.h"
#include "rasterizer_impl.h"

namespace curvescan::detail {

namespace {

/// Up to how many open chains an event is handled by passes over all of them, as the proof first did:
/// removals by one pass, the windings from the first changed place to the end. Among so few the passes
/// cost less than finding the places of the chains that end and sorting the changed places.
constexpr std::size_t kFewOpenChains = 16;

/// How far either side of its stale position a chain's place is looked for before the open chains right
/// of the first changed place are numbered again (place_of in sweep_planar_chains). Each event moves the
/// places right of it by the chains it adds less those it removes (a dash's two sides: +2, then -2), so
/// between two lookups a place drifts by a few; a wider window costs more than the numbering it saves.
constexpr std::size_t kNearPlaces = 8;

/// Sorts the few places an event changed (most events change one to four): insertion sort there, where
/// std::sort's set-up costs more than the sort.
inline void sort_places(std::vector<std::uint32_t>& places) {
  if (places.size() > 16) {
    std::sort(places.begin(), places.end());
    return;
  }
  for (std::size_t i = 1; i < places.size(); ++i) {
    const std::uint32_t p = places[i];
    std::size_t j = i;
    for (; j > 0 && places[j - 1] > p; --j) places[j] = places[j - 1];
    places[j] = p;
  }
}

/// Above how many edges per chain, on average, a fill's walks pass joints by blocks: where chains are
/// shorter (a 1 px dash's sides, 3 to 4 edges; a 20 px dash of a cubic's, 10 to 12) a walk is a few joints,
/// and the blocks' set-up and the test at each joint cost more than they pass (measured on stroke_bench,
/// docs/benchmarks.md: above 8 the 20 px dashed cubics were 1 % dearer, above 12 0.7 % cheaper).
constexpr std::size_t kBlockWalkEdges = 12;

/// The general sweep's walk of a pair of neighbours (first_crossing_by_blocks), their blocks written first if
/// not yet; counts its steps into ScanState::planar_joints_walked too. Out of line: the sweep inlines its
/// neighbour check at four places, and the blocks' set-up there cost the sweep more than it saved.
__attribute__((noinline)) double walk_by_blocks(ScanState& s, PlanarChain& left, PlanarChain& right,
                                                double y0, double y1, std::uint64_t& steps) {
  const ClippedEdge* const edges = s.edges.data();
  PlanarBlock* const blocks = s.planar_blocks.data();
  if (!left.blocks_built) build_chain_blocks(edges, blocks, left);
  if (!right.blocks_built) build_chain_blocks(edges, blocks, right);
  const std::uint64_t before = steps;
  const double y = first_crossing_by_blocks(edges, blocks, left, right, y0, y1, steps);
  s.planar_joints_walked += steps - before;
  return y;
}

}  // namespace

// Measured (docs/benchmarks.md): the sweep pays less for a crossing than the row scan among short edges
// (flattened curves, stroke outlines, whose bands the joints cut finely) and more among long straight
// edges (a random polyline), where a band's crossings are cheap inversions; a fill of long edges therefore
// gives up early, which bounds the work wasted before the row scan.
std::uint64_t sweep_crossing_limit(const ScanState& s) {
  if (s.sweep_crossing_budget == 0.0) return 0;
  double rows = 0.0;
  for (const ClippedEdge& e : s.edges) rows += e.y_bot - e.y_top;
  const double n = static_cast<double>(s.edges.size());
  const double mean_rows = rows / n;
  const double scale = mean_rows > kSweepMeanEdgeRows ? kSweepMeanEdgeRows / mean_rows : 1.0;
  const double limit = s.sweep_crossing_budget * n * scale + static_cast<double>(kSweepCrossingsBase);
  return limit >= 1e15 ? std::uint64_t{1} << 50 : static_cast<std::uint64_t>(limit);
}

void link_edges_into_chains(ScanState& s) {
  const std::size_t count = s.edges.size();
  ClippedEdge* const edges = s.edges.data();
  std::vector<PlanarChain>& chains = s.planar_chains;
  chains.clear();
  // Only consecutive edges are linked, so a chain is a maximal run [a, b] of edges, each
  // linked to the next: downward, its head is a and its bottom edge b; upward, the reverse. Each run is
  // read once, front to back, where linking and then walking down from each head read every edge three
  // times (the links, the search for heads, the walk down each chain: the two-pass reference in
  // tests/unit/raster/link_edges_into_chains_test.cpp): on a fill of 10^6 edges, 48 MB each time.
  std::size_t a = 0;
  while (a < count) {
    const int dir = edges[a].dir;
    std::size_t b = a;
    PlanarChain& chain = chains.emplace_back();
    if (dir > 0) {
      // The extent a walk down from the head takes, in its order: the head's top, then each bottom.
      double x_min = edges[a].x_top;
      double x_max = x_min;
      edges[a].linked_above = false;
      while (true) {
        ClippedEdge& p = edges[b];
        x_min = std::min(x_min, p.x_bot);
        x_max = std::max(x_max, p.x_bot);
        if (b + 1 < count) {
          ClippedEdge& q = edges[b + 1];
          if (q.dir == dir && q.y_top == p.y_bot && q.x_top == p.x_bot) {
            p.below = static_cast<std::uint32_t>(b + 1);
            q.linked_above = true;
            ++b;
            continue;
          }
        }
        p.below = ClippedEdge::kNoEdge;
        break;
      }
      chain.head = static_cast<std::uint32_t>(a);
      chain.top = edges[a].y_top;
      chain.bottom = edges[b].y_bot;
      chain.x_min = x_min;
      chain.x_max = x_max;
    } else {
      // Upward, a walk down from the head folds the head's (b's) top, then the bottoms from b down to a.
      // This pass meets them in the reverse order, so a tie goes to the later value (`<=`, `>=`): the
      // first of equal values in the walk's order, which std::min and std::max keep. Only the sign of
      // a zero could tell the two apart; it is the same here too.
      double x_min = edges[a].x_bot;
      double x_max = x_min;
      edges[a].below = ClippedEdge::kNoEdge;
      while (true) {
        ClippedEdge& p = edges[b];
        if (b + 1 < count) {
          ClippedEdge& q = edges[b + 1];
          if (q.dir == dir && p.y_top == q.y_bot && p.x_top == q.x_bot) {
            q.below = static_cast<std::uint32_t>(b);
            p.linked_above = true;
            x_min = q.x_bot <= x_min ? q.x_bot : x_min;
            x_max = q.x_bot >= x_max ? q.x_bot : x_max;
            ++b;
            continue;
          }
        }
        p.linked_above = false;
        break;
      }
      x_min = edges[b].x_top <= x_min ? edges[b].x_top : x_min;
      x_max = edges[b].x_top >= x_max ? edges[b].x_top : x_max;
      chain.head = static_cast<std::uint32_t>(b);
      chain.top = edges[b].y_top;
      chain.bottom = edges[a].y_bot;
      chain.x_min = x_min;
      chain.x_max = x_max;
    }
    chain.cursor = chain.head;
    chain.dir = dir;
    a = b + 1;
  }
}

std::uint64_t planar_proof_budget(const ScanState& s) {
  return 32 * std::uint64_t{s.edges.size()} + 4096;
}

bool prove_planar_chains(ScanState& s, FillRule rule) {
  if (s.planar_chains.empty()) return false;
  // A fill of few chains (most fills: a circle, a glyph, an icon's shape) is swept without the
  // bookkeeping that keeps an event's work to the chains it touches (rasterizer_planar_few.cpp); it
  // leaves the same pieces.
  if (s.planar_chains.size() <= kFewChains) return prove_planar_few(s, rule);
  return sweep_planar_chains(s, rule);
}

namespace {

/// sweep_planar_chains with its neighbour walks by blocks (first_crossing_by_blocks, `kByBlocks`) or joint by
/// joint (first_crossing): two copies of the sweep, so that the one without blocks is the sweep as it was,
/// instruction for instruction (a choice made at each walk cost the 1 px dashed strokes 0.3 %).
template <bool kByBlocks>
bool sweep_chains(ScanState& s, FillRule rule) {
  const ClippedEdge* edges = s.edges.data();
  std::vector<PlanarChain>& chains = s.planar_chains;
  double fill_bottom = -std::numeric_limits<double>::infinity();
  for (const PlanarChain& chain : chains) fill_bottom = std::max(fill_bottom, chain.bottom);
  // The proof's budget grows by kSweepStepsPerCrossing per crossing allowed once a crossing is found: a
  // fill that outgrows it before any (a fine comb, a star of 500 spikes) gives up where the proof alone did.
  const std::uint64_t base_budget = planar_proof_budget(s);
  std::vector<std::uint32_t>& order = s.planar_order;
  order.resize(chains.size());
  for (std::uint32_t c = 0; c < chains.size(); ++c) order[c] = c;
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return chains[a].top < chains[b].top; });
  // The chains by bottom: the chains that end at an event, and the next event, without visiting the
  // others. Sorted once more than kFewOpenChains chains are open; until then one pass over the open
  // chains at each event finds them (as the proof first did), cheaper there than this sort.
  bool track_ends = false;
  std::vector<std::uint32_t>& ending = s.planar_by_bottom;

  // Sizes and data pointers read once: the loops below write chains and pieces through references, so
  // the compiler would otherwise reload every vector's bounds at each use.
  const std::size_t chain_count = order.size();
  const std::uint32_t* const by_top = order.data();
  const std::uint32_t* by_bottom = nullptr;
  PlanarChain* const chain_at = chains.data();
  // The crossing limit (sweep_crossing_limit, a pass over the edges) is found at the first crossing: most
  // fills have none.
  constexpr std::uint64_t kNotYet = ~std::uint64_t{0};
  std::uint64_t crossing_limit = kNotYet;
  std::uint64_t budget = base_budget;
  std::uint64_t steps = 0;
  // Counted as they are resolved, so a fill that gives up below still reports how far it went.
  std::uint64_t& crossings = s.stats.sweep_crossings;
  const auto over_budget = [&] { return steps > budget; };
  const double fill_top = chains.empty() ? 0.0 : chains[order[0]].top;
  std::vector<std::uint32_t>& active = s.planar_active;
  active.clear();
  std::vector<PlanarCrossing>& pending = s.planar_crossings;
  pending.clear();
  const auto later = [](const PlanarCrossing& a, const PlanarCrossing& b) { return a.y > b.y; };
  std::vector<std::uint32_t>& changed = s.planar_changed;
  s.planar_pieces.clear();
  s.planar_open_right = false;
  s.planar_places_numbered = 0;
  s.planar_places_searched = 0;
  s.planar_pairs_walked = 0;

  // The places of the x order below `numbered` hold their chain's PlanarChain::position; an insertion or
  // removal renumbers nothing, it only lowers `numbered` to its place.
  std::size_t numbered = 0;
  // The place of chain `c` in the x order, or kNotFound when it is not open (its crossing event is
  // stale). The places from `numbered` on are numbered first if `c` may be among them: a pass of about
  // three instructions per place, from the first place changed since the last pass. Measured against a
  // binary search by x at the sweep height (docs/benchmarks.md): this is cheaper at the few hundred chains
  // a row of dashes keeps open, and much cheaper where crossings, each looked up, outnumber the events.
  constexpr std::size_t kNotFound = std::numeric_limits<std::size_t>::max();
  // A chain that moved since it was numbered: looked for a few places either side of its stale position
  // first, outwards (places right of an insertion or a removal move by one each, so a chain is mostly
  // found there), then the places from `numbered` on are numbered. Not inlined: most lookups end at once.
  const auto place_of_moved = [&](std::uint32_t c, std::size_t stale) __attribute__((noinline)) {
    const std::size_t size = active.size();
    const std::uint32_t* const ids = active.data();
    if (stale < size + kNearPlaces) {
      for (std::size_t d = 1; d <= kNearPlaces; ++d) {
        if (stale + d < size && ids[stale + d] == c) {
          steps += d + 1;
          chain_at[c].position = static_cast<std::uint32_t>(stale + d);
          return stale + d;
        }
        if (d <= stale && stale - d < size && ids[stale - d] == c) {
          steps += d + 1;
          chain_at[c].position = static_cast<std::uint32_t>(stale - d);
          return stale - d;
        }
      }
      steps += kNearPlaces + 1;
    }
    const std::size_t from = std::min(numbered, size);
    steps += size - from;
    s.planar_places_numbered += size - from;
    for (std::size_t p = from; p < size; ++p) chain_at[ids[p]].position = static_cast<std::uint32_t>(p);
    numbered = size;
    const std::size_t at = chain_at[c].position;
    return at < size && ids[at] == c ? at : kNotFound;
  };
  // The place of chain `c` in the x order, or kNotFound when it is not open. A chain that holds the
  // place it was last numbered at (always so below `numbered`) is there: an id is at one place only.
  const auto place_of = [&](std::uint32_t c) __attribute__((always_inline)) {
    const std::size_t stale = chain_at[c].position;
    if (stale < active.size() && active[stale] == c) return stale;
    return place_of_moved(c, stale);
  };

  // The chain (right of `filled`, whose state it follows) bounds the region
  // with sign `boundary` from height y down: its open piece (if any) closes at y and a new one opens.
  // Inlined (GCC otherwise calls it): it is called once per chain visited, and mostly returns at once.
  const auto set_boundary = [&](PlanarChain& chain, std::int8_t boundary, double y) __attribute__((always_inline)) {
    if (boundary == chain.boundary) return;  // the same as just above: its open piece (if any) goes on
    if (chain.boundary != 0) s.planar_pieces[chain.open_piece].y1 = y;
    chain.boundary = boundary;
    if (boundary == 0) return;
    chain.open_piece = static_cast<std::uint32_t>(s.planar_pieces.size());
    // y1 is written when the piece is closed, at the latest where the chain ends.
    s.planar_pieces.push_back({cursor_at(edges, chain, y), y, chain.bottom, static_cast<double>(boundary)});
  };
  // Checks that neighbours `l` (left) and `r` stay in order from y down to where the first of them ends;
  // where they do not, their first crossing becomes an event (false when crossings are not resolved).
  // Inlined at its four calls: a crossing makes three, and the call's own cost (the lambda's captures
  // reloaded, its frame) was about 40 instructions of the 170 a check costs in a row of dashes.
  const auto check_pair = [&](std::uint32_t l, std::uint32_t r, double y) __attribute__((always_inline)) {
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
    ++s.planar_pairs_walked;
    const double y1 = std::min(left.bottom, right.bottom);
    if constexpr (kByBlocks) {
      left.cross_y = walk_by_blocks(s, left, right, y, y1, steps);
    } else {
      left.cross_y = first_crossing(edges, left, right, y, y1, steps);
    }
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

  std::size_t next = 0;      // the next chain to start, in by_top
  std::size_t next_end = 0;  // the next chain to end, in by_bottom
  double y = chains[order[0]].top;
  while (true) {
    // Only the chains that end or start at y are touched (the others keep their place, and their cursors
    // move down when they are next read). `changed` gathers the places whose left neighbour is new.
    changed.clear();
    // The chains that end at this event (bottoms are events) leave; their boundary pieces, if open, end
    // here too. The chain after each gap gets a new left neighbour: its place goes to `changed`.
    double y_next = std::numeric_limits<double>::infinity();
    // The first place whose chain or left neighbour this event changes.
    std::size_t first_changed = std::numeric_limits<std::size_t>::max();
    // Few open chains: one pass over them finds those that end (and, without the chains by bottom, the
    // next bottom).
    const auto drop_ended = [&] {
      // Through locals: the store to a closed piece's y1 (a double) could otherwise be y_next's.
      const double at = y;
      double lowest = y_next;
      std::uint32_t* const ids = active.data();
      const std::size_t count = active.size();
      steps += count;
      std::size_t kept = 0;
      for (std::size_t i = 0; i < count; ++i) {
        const std::uint32_t c = ids[i];
        const PlanarChain& chain = chain_at[c];
        const double bottom = chain.bottom;
        if (bottom <= at) {
          if (chain.boundary != 0) s.planar_pieces[chain.open_piece].y1 = at;
          first_changed = std::min(first_changed, kept);
          if (track_ends && (changed.empty() || changed.back() != kept))
            changed.push_back(static_cast<std::uint32_t>(kept));
          continue;
        }
        lowest = std::min(lowest, bottom);
        ids[kept++] = c;
      }
      y_next = lowest;
      active.resize(kept);
    };
    if (!track_ends) {
      drop_ended();
    } else if (next_end < chain_count && chain_at[by_bottom[next_end]].bottom <= y) {
      if (active.size() <= kFewOpenChains) {
        drop_ended();
        while (next_end < chain_count && chain_at[by_bottom[next_end]].bottom <= y) ++next_end;
      } else {
        // Many: the places of those that end, found before any is removed, then the gaps closed in one
        // pass, left to right.
        for (; next_end < chain_count && chain_at[by_bottom[next_end]].bottom <= y; ++next_end) {
          PlanarChain& chain = chain_at[by_bottom[next_end]];
          const std::size_t at = place_of(by_bottom[next_end]);
          if (at == kNotFound) return false;  // cannot happen: a chain that started and has not ended is open
          if (chain.boundary != 0) s.planar_pieces[chain.open_piece].y1 = y;
          changed.push_back(static_cast<std::uint32_t>(at));
        }
        if (changed.size() > 1) sort_places(changed);
        std::size_t out = changed[0];
        for (std::size_t k = 0; k < changed.size(); ++k) {
          const std::size_t from = changed[k] + 1;
          const std::size_t to = k + 1 < changed.size() ? changed[k + 1] : active.size();
          changed[k] = static_cast<std::uint32_t>(out);
          // One block move per gap (memmove): the ids right of the first chain that ends, a few hundred
          // in a row of dashes, move at every event where chains end.
          if (to > from)
            std::memmove(active.data() + out, active.data() + from, (to - from) * sizeof(std::uint32_t));
          out += to - from;
        }
        steps += active.size() - changed[0];
        active.resize(out);
        first_changed = changed[0];
      }
    }
    // Chains that start at y enter at their place in the x order at y. A chain that starts at the point
    // where the chain placed just before it starts (a contour's top tip: the two sides of a dash) is
    // looked for beside it first (place_beside).
    constexpr std::uint32_t kNoHead = ClippedEdge::kNoEdge;
    std::uint32_t placed_head = kNoHead;
    std::size_t placed_at = 0;
    for (; next < chain_count && chain_at[by_top[next]].top <= y; ++next) {
      const std::uint32_t c = by_top[next];
      const PlanarChain& chain = chain_at[c];
      std::size_t found = kNoPlace;
      if (placed_head != kNoHead && edges[placed_head].x_top == edges[chain.head].x_top &&
          edges[placed_head].y_top == edges[chain.head].y_top) {
        found = place_beside(edges, chain_at, active.data(), active.size(), placed_at, chain.head, y, steps);
      }
      if (found == kNoPlace) {
        found = place_among(edges, chain_at, active.data(), active.size(), chain.head, y, steps);
        ++s.planar_places_searched;
      }
      const auto place = static_cast<std::uint32_t>(found);
      placed_head = chain.head;
      placed_at = place;
      const auto at = active.begin() + place;
      first_changed = std::min<std::size_t>(first_changed, place);
      if (track_ends) {
        for (std::uint32_t& p : changed) p += p >= place ? 1 : 0;
        changed.push_back(place);
        changed.push_back(place + 1);
      }
      active.insert(at, c);
      y_next = std::min(y_next, chain.bottom);
      steps += active.size();
      // Checked per insertion: placing a chain among coincident ones walks them until they part.
      if (over_budget()) return false;
    }
    // Whether `changed` lists every changed place (else only first_changed is known).
    const bool changes_listed = track_ends;
    if (!track_ends && active.size() > kFewOpenChains) {
      ending.assign(order.begin(), order.end());
      std::sort(ending.begin(), ending.end(),
                [&](std::uint32_t a, std::uint32_t b) { return chain_at[a].bottom < chain_at[b].bottom; });
      by_bottom = ending.data();
      // Every chain that ended at or above y has left.
      next_end = static_cast<std::size_t>(
          std::partition_point(ending.begin(), ending.end(),
                               [&](std::uint32_t c) { return chain_at[c].bottom <= y; }) -
          ending.begin());
      track_ends = true;
    }
    if (track_ends && next_end < chain_count) y_next = chain_at[by_bottom[next_end]].bottom;
    if (next < chain_count) y_next = std::min(y_next, chain_at[by_top[next]].top);
    if (active.empty()) {
      pending.clear();  // only crossings of chains that have ended, none to resolve
      if (next == chain_count) return true;
      y = y_next;
      continue;
    }

    // Left to right from each changed place: the chain's check against its left neighbour, then the
    // winding number right of it and whether it bounds the filled region. Only neighbours that were not
    // neighbours before are checked, each down to where the first of them ends (Shamos and Hoey's
    // argument, in the essay above). A chain's boundary piece stays open (its end not yet written) while
    // the chain bounds the region with the same sign, so an interval that changes nothing for the chain
    // writes nothing; the piece is closed where that changes or where the chain ends.
    // Elsewhere nothing changed: the same neighbours, and, once the winding number left of a chain is the
    // one it had (the changes so far sum to zero), the same windings and boundary states up to the next
    // changed place (a crossing keeps its pair's up to date).
    const std::uint32_t* const in_order = active.data();
    const std::size_t active_count = active.size();
    // Among few open chains the pass goes from the first changed place to the end, without sorting the
    // changed places or comparing windings (cheaper there than what it saves).
    numbered = std::min(numbered, first_changed);
    const bool to_the_end = !changes_listed || active_count <= kFewOpenChains;
    if (to_the_end) {
      changed.clear();
      if (first_changed < active_count) changed.push_back(static_cast<std::uint32_t>(first_changed));
    } else if (changed.size() > 1) {
      sort_places(changed);
    }
    // Among few open chains (one changed place, every chain to its right visited): the same checks and
    // windings without the changed places' bookkeeping, and a pair whose x extents are apart is settled
    // here without the call (check_pair would find the same, in_order_by_extent).
    if (to_the_end) {
      const std::size_t start = changed.empty() ? active_count : changed[0];
      std::size_t p = start;
      int winding = p > 0 ? chain_at[in_order[p - 1]].winding_right : 0;
      bool filled = is_filled(winding, rule);
      PlanarChain* left = p > 0 ? &chain_at[in_order[p - 1]] : nullptr;
      for (; p < active_count; ++p) {
        const std::uint32_t c = in_order[p];
        PlanarChain& chain = chain_at[c];
        if (left != nullptr && left->checked_right != c && !settled_by_extent(*left, c, chain) &&
            !check_pair(in_order[p - 1], c, y)) {
          return false;
        }
        set_boundary(chain, step_winding(chain, winding, filled, rule), y);
        left = &chain;
      }
      steps += active_count - start;
      changed.clear();
    }
    std::size_t k = 0;
    while (k < changed.size() && changed[k] < active_count) {
      std::size_t p = changed[k];
      int winding = p > 0 ? chain_at[in_order[p - 1]].winding_right : 0;
      bool filled = is_filled(winding, rule);
      for (; p < active_count; ++p) {
        PlanarChain& chain = chain_at[in_order[p]];
        if (k < changed.size() && changed[k] == p) {
          while (k < changed.size() && changed[k] == p) ++k;
        } else if (!to_the_end && chain.winding_right - chain.dir == winding) {
          break;
        }
        if (p > 0 && chain_at[in_order[p - 1]].checked_right != in_order[p] &&
            !check_pair(in_order[p - 1], in_order[p], y)) {
          return false;
        }
        set_boundary(chain, step_winding(chain, winding, filled, rule), y);
        ++steps;
      }
    }
    // Still filled right of the last chain: the region goes on past the clip's right side (the clipper
    // dropped its right edges).
    if (is_filled(chain_at[in_order[active_count - 1]].winding_right, rule)) s.planar_open_right = true;

    // The crossings above the next start or end, in height order (Bentley and Ottmann): the two chains
    // swap places, only the winding number between them changes (so only their boundary states), and
    // their new neighbours are checked from there down. An event whose pair is no longer neighbours,
    // or was checked again since, is stale: the pair's current crossing (if any) is queued anew.
    while (!pending.empty() && pending.front().y < y_next) {
      std::pop_heap(pending.begin(), pending.end(), later);
      const PlanarCrossing event = pending.back();
      pending.pop_back();
      if (!crossing_stands(event, chain_at, y)) continue;
      const double yc = event.y;
      const std::size_t p = place_of(event.left);
      if (p == kNotFound || p + 1 >= active.size() || active[p + 1] != event.right) continue;
      if (++crossings > crossing_limit) return false;
      swap_at_crossing(active.data(), p, chain_at, rule, yc, set_boundary);
      if (p > 0) check_pair(active[p - 1], active[p], yc);
      check_pair(active[p], active[p + 1], yc);
      // The pair that just swapped crosses back at the same height: the crossing lies between yc and a
      // joint less than a rounding step below it (a nearly horizontal edge across the other chain), where
      // no height between can be represented, and the two would swap back and forth at yc until the
      // budget ran out (thousands of crossings: three fills of the tiger did this). Give up at once.
      if (chain_at[active[p]].cross_y <= yc) return false;
      if (p + 2 < active.size()) check_pair(active[p + 1], active[p + 2], yc);
      steps += 8;
      if (over_budget()) return false;
    }
    if (over_budget()) return false;
    // Crossings spread over the fill's height (long edges crossing at random) show their total early: once
    // kSweepCrossingsSample are resolved, a fill whose crossings so far, in proportion to the height swept,
    // foretell more than its limit gives up now rather than at the limit (which would waste about as much
    // as the row scan then spends). Only where to give up is estimated; the output does not depend on it.
    const double height = fill_bottom - fill_top;
    const double swept = y_next - fill_top;
    if (crossings >= kSweepCrossingsSample && height > swept &&
        static_cast<double>(crossings) * height > static_cast<double>(crossing_limit) * swept) {
      return false;
    }
    y = y_next;
  }
}

}  // namespace

bool sweep_planar_chains(ScanState& s, FillRule rule) {
  s.planar_joints_walked = 0;
  // The walks pass joints a block at a time (first_crossing_by_blocks) in fills of more chains than the
  // few-chain sweep takes (a fill of fewer is swept here only by the tests that hold the two sweeps to the
  // same steps, and walks every joint as that sweep does) and of long chains.
  const std::size_t chains = s.planar_chains.size();
  if (chains > kFewChains && s.edges.size() > kBlockWalkEdges * chains) {
    // Grown, never shrunk: an entry is written before it is read (build_chain_blocks).
    if (s.planar_blocks.size() < s.edges.size()) s.planar_blocks.resize(s.edges.size());
    return sweep_chains<true>(s, rule);
  }
  return sweep_chains<false>(s, rule);
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
  // A piece's first edge holds its top (set_boundary takes the chain's cursor there).
  for (const PlanarPiece& piece : s.planar_pieces) {
    dense.add_chain_piece(edges, piece.first_edge, piece.y0, piece.y1, piece.sign);
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
