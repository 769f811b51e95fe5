// The exact-area scanline rasterizer: clipped line edges -> coverage spans under a fill rule.
//
// ESSAY: the method, and where it is exact
// ----------------------------------------
// Coverage of a pixel is the area of the filled region inside the pixel square, where "filled" is decided
// by the fill rule from the winding number (nonzero: w != 0; even-odd: w odd). It is computed, not sampled.
//
// 1. Clipping (edge_clip.h). Every edge is cut against the clip box in double before anything else; parts
//    left of the box become vertical edges on its left side (winding preserved), parts above, below or to
//    the right are dropped, horizontal edges are dropped. No fixed point is used anywhere, so coordinates at
//    ±1e9 keep their winding and nothing overflows; the only error is double rounding (~1e-7 px at 1e9).
//
// 2. Rows and bands. Rows (strips y..y+1) are processed top to bottom with an active edge list (edges
//    sorted by top; an edge is active while it meets the row). Inside a row, the heights where an active
//    edge starts or ends cut the row into bands; inside a band every active piece spans the whole band.
//
// 3. Crossings. Inside a band the pieces are sorted by x at the band top (ties by x at the bottom). If that
//    order is also the order at the bottom, no two pieces cross inside the band. Otherwise an insertion sort
//    by bottom x visits exactly the pairs that change order (the inversions, each once); each such pair
//    crosses once inside the band, at a height computed from the two pieces, and the band is cut again at
//    those heights. Inside each resulting sub-band the pieces are ordered by x at mid-height, which is a
//    total order consistent with the order everywhere in the sub-band (pieces that touch only at an end
//    still compare correctly; coincident pieces tie, and any order of them bounds a zero-area trapezoid).
//    The sub-bands are not walked one by one (that cost O(pieces · crossings) per band, minutes for 10^5
//    crossing segments): a sweep (rasterizer_sweep.cpp) goes down the crossing heights, re-sorts only the
//    range of the order holding the crossing pair, recomputes the winding numbers inside that range (the
//    winding on either side of it cannot change), and emits a piece's boundary run as one trapezoid when
//    its state changes: O(n + k log k) per band of n pieces and k crossings.
//
// 4. Rule resolution. Between consecutive pieces of a sub-band the winding number is constant, so walking
//    the pieces left to right gives it exactly (sum of directions). A piece across which the rule's filled
//    state flips is a boundary of the filled region: +1 where it enters, -1 where it leaves; every other
//    piece contributes nothing. The filled part of the sub-band is then the disjoint union of the
//    trapezoids between an entering piece and the next leaving one.
//
// 5. Area. Each boundary piece adds, per pixel column, the area of the sub-band right of it (coverage_row.h:
//    font-rs / FreeType cell style accumulation, a prefix sum across the row at the end). The sum is the
//    exact area of the union of those trapezoids inside each pixel, i.e. the exact rule-resolved coverage.
//    It lies in [0, 1]; it is clamped only against rounding, and output as round(area·255).
//
// 6. Chains (the fast form of steps 2-4 for flattened curves). Consecutive edges of a contour that share a
//    joint and go the same way are linked into y-monotone polylines. At a joint the winding structure does
//    not change (one edge hands over to the next at the same point), so a row is cut into bands only where
//    chains start or end (the contour's y-extrema). Inside a band, chains sorted by x at the band top are
//    checked pairwise: disjoint x extents, or — when extents overlap — the left chain at or left of the
//    right one at every joint height of either (their difference is linear in between, so this is exact).
//    Then no two chains cross in the band, one walk gives the windings, and each edge of a boundary chain
//    adds its part (runs of one edge across bands are joined first). A band where some pair fails the
//    check is cut at its chains' joints and done by per-edge sub-bands and crossings (steps 2-4); the
//    other bands of the row stay chain bands (a dashed stroke's row crosses itself in a few bands, not in
//    all). Either way the result is the same exact area; the chain form only avoids cutting a row at
//    thousands of joints. Each band's chains are gathered in the x order of the band above (the chains
//    starting at its top merged in), so a band's sort costs its chains plus the crossings of the band
//    above, and every crossing of the row is paid for once, not once per band below it. The pieces of
//    every band are kept until the row is accumulated; a row that would keep more than 2^20 of them
//    (thousands of chains in thousands of bands: only mutually crossing input) takes the per-edge bands,
//    which hold one band at a time.
//
// Where it is exact: everything above is exact in real arithmetic for any set of straight edges, including
// overlapping, coincident and self-intersecting contours (a contour drawn twice: the second coincident edge
// does not flip the state under nonzero, 1 -> 2, and flips it back under even-odd; so "once" and
// "nothing"). In double arithmetic the errors are: rounding of crossing heights (the pieces of a sub-band
// may overlap by ~1e-16 relative, a sliver of that width mis-attributed), rounding in the per-column
// split of each piece (the last column takes the rest, so each piece's row total is exact up to one ulp),
// and the prefix sum across the row (~width · 1e-16). All are many orders of magnitude below 1/255.
// This is unlike the plain signed-area accumulation (font-rs, FreeType, Cairo's tor), which sums the
// winding number over the pixel: exact only where the winding is 0 or ±1 with one sign; it over-covers
// overlaps (two half-covering parts give a full pixel) and cannot do even-odd exactly.
//
// 7. Budget and fallback. Exact resolution costs at least one step per crossing, and k can be Θ(n²) (a
//    polyline through 10^5 random points crosses itself ~10^9 times). So each row gets a budget of
//    16·n·⌈log2(n + 2)⌉ piece visits (n its active edges; Rasterizer::set_crossing_budget scales the 16)
//    plus a pool of 2^26 visits shared by the rows of the fill (spent only by rows past their own budget,
//    so that ordinary heavy rows stay exact: the 223 stroke-corpus scenes and the 10^4-spike star never
//    reach the end of it): the chains' and the bands' gathering (bands ×
//    pieces) and the crossings found are charged to it. A row whose bands would exceed it, or a band whose
//    crossings do, is resolved instead by 16 sub-scanlines per pixel row, each exact in x (the filled
//    intervals along the sub-scanline, from a sorted walk of the winding numbers) and weighted 1/16: the
//    midpoint rule in y. A sampled band costs 16 sorts of n nearly sorted pieces, O(n log n) at worst
//    (band_sort.h, adaptive_sort), so a row never costs more than about twice its budget. A sampled row
//    works on a copy of its edges in x order: contiguous memory, whatever the size of the fill. Its
//    sub-scanlines count the edges' directions by column bucket and sort only the edges of the buckets
//    where the winding number may reach a boundary of the rule (sub_scanline_columns.cpp): O(n) per
//    sub-scanline where edges are spread out, however often they cross between sub-scanlines. Memory is
//    bounded apart from the budget: a band keeps at most 2^22 crossings for its sweep (more are sampled,
//    kMaxBandCrossings) and a row's chain path at most 2^20 chain pieces (step 6).
//    Error bound of a sampled row: inside one sub-scanline, the filled length within a pixel column is
//    linear in y unless an edge ends, two edges cross or an edge crosses a column line there; the midpoint
//    sample is exact for a linear length, and otherwise off by at most the change of that length across
//    the sub-scanline, ≤ 1/16 of the pixel. Measured against the exact scan: random polylines of 200-700
//    segments with every crossing band sampled, worst 7/255, mean 0.33/255; the star polygon
//    {10001/4999} worst 24/255 (pixels at the centre that every edge crosses), mean 0.012/255. Exact scenes
//    (the oracle corpora) never reach the budget: Rasterizer::stats() counts the sampled rows and bands, and
//    tests hold them at zero there.
//
// 8. The whole-fill sweep (rasterizer_planar.cpp). Before any row is scanned, one sweep over the whole
//    fill's chains (step 6, but from the top of the fill to its bottom, not per row) keeps them in x order,
//    checking each pair when it becomes neighbours (Shamos and Hoey). Where two neighbours cross, the
//    crossing becomes an event of the sweep (Bentley and Ottmann): the two swap places there, only the
//    winding number between them changes, and their new neighbours are checked. So each chain's winding
//    numbers are known per interval between events, the boundary pieces are known, and the rows only
//    accumulate those, with no bands, sorting or rule resolution: steps 2-4 done once for the fill instead
//    of once per row. The pieces are cut at the rounded crossing heights but stay on the fill's edges, so
//    the rounding misplaces a sliver of about ε² · (slope difference) of area per crossing. A small fill (a
//    box of at most 128 columns) and a coverage mask are accumulated densely over their box instead of row
//    by row. A fill of more crossings than the sweep's budget (32 per edge plus 4096, shrunk where edges
//    are long, Rasterizer::set_sweep_crossing_budget: measured, long straight edges cross more cheaply in
//    the row scan's bands; docs/benchmarks.md), or whose sweep outgrows 32·n + 4096 steps plus 16 per
//    allowed crossing, is scanned as above.
//
// 9. Independent groups of a row (rasterizer_row_groups.cpp). A row of 32 or more edges in which some chain
//    starts or ends (a row of joints only is one chain band already) is split at vertical lines that no
//    edge of the row meets, where the direction sum of the edges on the left is the same at every height
//    of the row: the winding number is one constant on each such line, so each group is scanned alone
//    (steps 3-7 on its edges only, from that winding number on its left) and its bands are cut only at
//    its own edges' ends. A dashed stroke's row of hundreds of dashes costs the sum over the dashes, not
//    dashes × all the row's tips, and so does a wide stroke's row of overlapping pieces of outline,
//    inside which the winding is not zero.
//    Neighbouring groups in which no chain starts or ends (each is one band of the chain path anyway)
//    are joined into one, which the scan visits in the same order with the same arithmetic.
//
// 10. Crossing clusters (cover_row_by_chains). Inside a band of the chain path where chains cross, the
//    chains are cut into clusters at positions of the x order where every chain on the left stays at or
//    left of every chain on the right over the band (the greatest x_max before, the least x_min after).
//    Only a cluster whose own chains cross is cut at its chains' joints and resolved by steps 3-4, from
//    the winding number on its left (the directions of the chains before it, each spanning the band); the
//    others take the chain walk. Where two pieces of a stroke's outline overlap, the exact crossing work
//    is confined to those two pieces, not spread over the band's other chains and their joints.
//
// Aliased mode (Antialias::kNone): a pixel is in when the winding number at its centre (x+0.5, y+0.5)
// satisfies the rule. Tie rule: an edge counts at height yc when y_top <= yc < y_bot (top-inclusive), and a
// centre exactly on an edge belongs to the region on the edge's right (left-inclusive spans).
//
// Cost: O(n + rows) to bucket the edges by their top row; per row O(active) to find the events, then per
// band the chains or edges covering it (tracked incrementally, so many short edges in one row cost
// O(their number)), plus per crossing band O(pieces + crossings · log) for the sweep; plus the columns
// each boundary piece crosses and one pass over the touched cells (a bitmap). Every row is bounded by
// step 7: at most about 2 · 16 · a·⌈log2(a + 2)⌉ piece visits (a its active edges), plus the pool of
// 2^26 once per fill, whatever the input; Rasterizer::stats() reports the visits, and tests/oracle/
// rasterizer_crossings_test.cpp holds pathological scenes to that bound. Ordinary shapes have no
// crossings and few events per row, and the insertion sorts run on nearly sorted lists. Memory: the
// clipped edges plus one double per clip column. The plain reference (rasterizer_reference.cpp) does the
// same decomposition without any of the shortcuts and is held to the same output by a test.
#include "curvescan/raster/rasterizer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "band_sort.h"
#include "rasterizer_impl.h"

namespace curvescan {

using detail::BandPiece;
using detail::ClippedEdge;

namespace detail {

void add_boundary_run(ScanState& s, std::uint32_t edge, double ya, double yb, double sign) {
  PendingBoundary& run = s.pending[edge];
  if (run.live) {
    if (run.y_end == ya && run.sign == sign) {
      run.y_end = yb;
      return;
    }
    const ClippedEdge& e = s.edges[edge];
    s.row.add_boundary(e.x_at(run.y_start), e.x_at(run.y_end), run.y_end - run.y_start, run.sign);
  } else {
    s.pending_edges.push_back(edge);
  }
  run = {ya, yb, sign, true};
}

}  // namespace detail

namespace {

using detail::add_boundary_run;

bool by_top_then_bottom(const BandPiece& a, const BandPiece& b) noexcept {
  return a.xa < b.xa || (a.xa == b.xa && a.xb < b.xb);
}

/// Sends every pending run of the row to the row accumulator.
void flush_boundary_runs(detail::ScanState& s) {
  for (const std::uint32_t i : s.pending_edges) {
    detail::PendingBoundary& run = s.pending[i];
    const ClippedEdge& e = s.edges[i];
    s.row.add_boundary(e.x_at(run.y_start), e.x_at(run.y_end), run.y_end - run.y_start, run.sign);
    run.live = false;
  }
  s.pending_edges.clear();
}

/// Fills s.pieces with the pieces of the edges `ids` over the band [ya, yb] (all of them cover it).
void gather_pieces(detail::ScanState& s, const std::vector<std::uint32_t>& ids, double ya, double yb) {
  s.pieces.resize(ids.size());
  BandPiece* out = s.pieces.data();
  const ClippedEdge* edges = s.edges.data();
  for (const std::uint32_t i : ids) *out++ = {edges[i].x_at(ya), edges[i].x_at(yb), edges[i].dir, i};
}

/// Resolves one band [ya, yb] whose pieces (x at the band top and bottom) are in s.pieces, with winding
/// number `winding_left` left of all of them. When the band is the whole row, boundaries go straight to
/// the row; otherwise they are joined into runs first.
void resolve_band(detail::ScanState& s, double ya, double yb, bool whole_row, FillRule rule,
                  int winding_left) {
  std::vector<BandPiece>& pieces = s.pieces;
  const double h = yb - ya;
  // Visits: the gather, the sort's moves and the walk (the cost model of the essay).
  s.stats.pieces_visited +=
      2 * pieces.size() + detail::insertion_sort(pieces.data(), pieces.size(), by_top_then_bottom);
  bool crossing = false;
  for (std::size_t i = 1; i < pieces.size() && !crossing; ++i) crossing = pieces[i].xb < pieces[i - 1].xb;
  if (!crossing) {
    if (whole_row) {
      detail::for_each_boundary(
          pieces.data(), pieces.size(), rule,
          [&](const BandPiece& p, double sign) { s.row.add_boundary(p.xa, p.xb, h, sign); }, winding_left);
    } else {
      detail::for_each_boundary(
          pieces.data(), pieces.size(), rule,
          [&](const BandPiece& p, double sign) { add_boundary_run(s, p.edge, ya, yb, sign); }, winding_left);
    }
    return;
  }

  // Crossings: the sweep (rasterizer_sweep.cpp), exact, while the row's budget lasts; past it the band
  // is sampled (essay, step 7).
  if (!detail::sweep_band(s, ya, yb, whole_row, rule, winding_left)) {
    detail::sample_band(s, ya, yb, rule, winding_left);
  }
}

/// Whether chain piece `left` is at or left of chain piece `right` at every height of their band (ending
/// at bb). Both are piecewise linear in y, so it suffices to compare them at every joint height of either
/// (their difference is linear in between): exact, O(joints of both).
bool chain_stays_left(const ClippedEdge* edges, const detail::ChainPiece& left,
                      const detail::ChainPiece& right, double bb) {
  std::uint32_t a = left.first_edge;
  std::uint32_t b = right.first_edge;
  if (left.xa > right.xa) return false;
  while (true) {
    const double y = std::min({edges[a].y_bot, edges[b].y_bot, bb});
    if (edges[a].x_at(y) > edges[b].x_at(y)) return false;
    if (y >= bb) return true;
    if (edges[a].y_bot == y) a = edges[a].below;
    if (edges[b].y_bot == y) b = edges[b].below;
  }
}

using detail::ChainPiece;
using detail::RowChain;

/// A crossing cluster of the band [ba, bb] (its chain pieces s.chain_pieces[begin, end) cross): cut at
/// every joint of those chains inside the band, and each sub-band resolved from its straight pieces
/// (resolve_band: crossings swept exactly while the row's budget lasts, sampled past it), its boundaries
/// joined into runs across sub-bands.
void resolve_cluster_by_edges(detail::ScanState& s, const detail::CrossingCluster& cluster, double ba,
                              double bb, FillRule rule) {
  const std::size_t begin = cluster.begin;
  const std::size_t end = cluster.end;
  const ClippedEdge* edges = s.edges.data();
  s.sub_events.clear();
  s.sub_cursors.clear();
  s.sub_events.push_back(ba);
  for (std::size_t p = begin; p < end; ++p) {
    const std::uint32_t first = s.chain_pieces[p].first_edge;
    s.sub_cursors.push_back(first);
    for (std::uint32_t j = first; edges[j].y_bot < bb; j = edges[j].below)
      s.sub_events.push_back(edges[j].y_bot);
  }
  s.sub_events.push_back(bb);
  std::sort(s.sub_events.begin(), s.sub_events.end());
  s.sub_events.erase(std::unique(s.sub_events.begin(), s.sub_events.end()), s.sub_events.end());
  for (std::size_t k = 0; k + 1 < s.sub_events.size(); ++k) {
    const double sa = s.sub_events[k];
    const double sb = s.sub_events[k + 1];
    s.pieces.clear();
    for (std::size_t p = begin; p < end; ++p) {
      std::uint32_t& j = s.sub_cursors[p - begin];
      while (edges[j].y_bot <= sa) j = edges[j].below;
      s.pieces.push_back({edges[j].x_at(sa), edges[j].x_at(sb), edges[j].dir, j});
    }
    resolve_band(s, sa, sb, false, rule, cluster.winding_left);
  }
}

/// The most chain pieces a row's chain path may hold at once (48 bytes each: 48 MB).
constexpr std::uint64_t kMaxChainPieces = std::uint64_t{1} << 20;

/// The row by chains (essay, steps 6 and 10), from winding number `winding_left` left of every chain:
/// bands are cut only where chains start or end (tips of the contour), not at every joint; inside a band
/// every chain spans the band. Where the chains' x extents are disjoint in their left-to-right order
/// (touching allowed), or chain_stays_left() shows that neighbours keep their order, no two chains cross
/// there, so the band's winding numbers are given by one walk over the chains, exactly as for straight
/// pieces (essay, step 4). A cluster of chains that do cross is cut at its own joints and resolved by
/// straight pieces. Returns false, having accumulated nothing, when the row's budget cannot pay for that:
/// the caller then uses the per-edge bands, which sample past the budget.
bool cover_row_by_chains(detail::ScanState& s, double ya, double yb, FillRule rule, int winding_left) {
  const ClippedEdge* edges = s.edges.data();
  s.chains.clear();
  s.events.clear();
  for (const std::uint32_t i : s.active) {
    const ClippedEdge& e = edges[i];
    if (e.linked_above && e.y_top > ya) continue;  // continues a chain that starts higher in this row
    std::uint32_t j = i;
    while (edges[j].y_bot < yb && edges[j].below != ClippedEdge::kNoEdge) j = edges[j].below;
    const RowChain chain{i, std::max(e.y_top, ya), std::min(edges[j].y_bot, yb), e.dir, i};
    if (chain.top > ya) s.events.push_back(chain.top);
    if (chain.bottom < yb) s.events.push_back(chain.bottom);
    s.chains.push_back(chain);
  }
  // Every band visits every chain: past the row's budget, leave the row to the per-edge path (which
  // samples it when that is dearer still). Pass 1 also keeps every band's pieces until pass 2, so a row
  // of more than kMaxChainPieces of them (thousands of chains cut into thousands of bands, as only
  // mutually crossing input has) goes to the per-edge path too, which holds one band at a time: memory
  // stays O(edges) whatever the budget (10^5 crossing segments once took 340 MB here).
  const std::uint64_t band_cost = (s.events.size() + 1) * s.chains.size();
  if (band_cost > s.row_budget_left || band_cost > kMaxChainPieces) return false;
  s.row_budget_left -= std::min(s.row_budget_left, band_cost);
  s.stats.pieces_visited += band_cost;  // pass 1 looks at every chain in every band
  s.events.push_back(ya);
  s.events.push_back(yb);
  std::sort(s.events.begin(), s.events.end());
  s.events.erase(std::unique(s.events.begin(), s.events.end()), s.events.end());
  // Chains carried from the row above come in x order, new ones in bucket order: sort them by x at their
  // top, so that the first band's pieces (and each band's new ones, below) come nearly sorted (a sort
  // then costs O(chains + changes of order), not O(chains · new chains)). Nearly sorted already:
  // adaptive_sort. A few chains (a glyph's row) sort as cheaply per band as here: left alone.
  constexpr std::size_t kSortChainsFrom = 256;
  if (s.chains.size() >= kSortChainsFrom)
    s.stats.pieces_visited +=
        detail::adaptive_sort(s.chains.data(), s.chains.size(), [&](const RowChain& a, const RowChain& b) {
          return edges[a.first].x_at(a.top) < edges[b.first].x_at(b.top);
        });

  // Pass 1: the pieces of every band, sorted, and the disjointness check. Each band's pieces are gathered
  // in the x order of the band above (s.chain_order), which at this band's top is off only by the
  // crossings inside the band above; the chains starting at the band's top are sorted apart and merged in.
  // So the sorts of a row cost O(chains + its crossings) per band, not the crossings of every band above
  // again (gathering each band in the row's top order did that: bands × crossings per row). Each chain
  // keeps its edge at the current band (RowChain::cursor), so a long chain is walked once per row, not
  // once per band.
  s.chain_pieces.clear();
  s.band_offsets.clear();
  s.crossing_clusters.clear();
  s.band_clusters.clear();
  s.chain_order.clear();
  s.chain_starts.clear();
  for (std::uint32_t c = 0; c < s.chains.size(); ++c)
    (s.chains[c].top > ya ? s.chain_starts : s.chain_order).push_back(c);
  // By top, ties in chain order (chain_starts is in increasing c): the order a stable sort gives, without
  // the stable sort's buffer, which it allocated and freed on every call (once per group of a row).
  std::sort(s.chain_starts.begin(), s.chain_starts.end(), [&](std::uint32_t a, std::uint32_t b) {
    return s.chains[a].top < s.chains[b].top || (s.chains[a].top == s.chains[b].top && a < b);
  });
  std::size_t next_start = 0;
  const auto by_top_then_bottom_x = [](const ChainPiece& a, const ChainPiece& b) {
    return a.xa < b.xa || (a.xa == b.xa && a.xb < b.xb);
  };
  // The piece of chain c over the band [ba, bb] (the chain covers it).
  const auto cut_chain = [&](std::uint32_t c, double ba, double bb) {
    RowChain& chain = s.chains[c];
    std::uint32_t j = chain.cursor;
    while (edges[j].y_bot <= ba) j = edges[j].below;  // the chain covers ba, so this stops in the chain
    chain.cursor = j;
    ChainPiece piece{edges[j].x_at(ba), 0.0, 0.0, 0.0, chain.dir, j, c};
    piece.x_min = piece.x_max = piece.xa;
    while (edges[j].y_bot < bb) {
      piece.x_min = std::min(piece.x_min, edges[j].x_bot);
      piece.x_max = std::max(piece.x_max, edges[j].x_bot);
      j = edges[j].below;
    }
    piece.xb = edges[j].x_at(bb);
    piece.x_min = std::min(piece.x_min, piece.xb);
    piece.x_max = std::max(piece.x_max, piece.xb);
    return piece;
  };
  for (std::size_t k = 0; k + 1 < s.events.size(); ++k) {
    const double ba = s.events[k];
    const double bb = s.events[k + 1];
    const std::size_t begin = s.chain_pieces.size();
    s.band_offsets.push_back(begin);
    s.band_clusters.push_back(s.crossing_clusters.size());
    for (const std::uint32_t c : s.chain_order) {
      if (s.chains[c].bottom < bb) continue;  // ended above (every chain bottom is an event)
      s.chain_pieces.push_back(cut_chain(c, ba, bb));
    }
    const std::size_t carried = s.chain_pieces.size() - begin;
    // The sort is charged to the row's budget; past it, the row goes to the per-edge bands, which sample.
    const std::size_t moves = detail::insertion_sort_bounded(
        s.chain_pieces.data() + begin, carried, by_top_then_bottom_x,
        [](const ChainPiece&, const ChainPiece&) {},
        static_cast<std::size_t>(std::min<std::uint64_t>(s.row_budget_left, SIZE_MAX - 2)));
    s.stats.pieces_visited += carried + moves;
    if (moves > s.row_budget_left) return false;
    s.row_budget_left -= moves;
    s.new_pieces.clear();
    for (; next_start < s.chain_starts.size() && s.chains[s.chain_starts[next_start]].top <= ba; ++next_start)
      s.new_pieces.push_back(cut_chain(s.chain_starts[next_start], ba, bb));
    if (!s.new_pieces.empty()) {
      // The pieces of the chains starting here (gathered in the order of their tops' x, nearly sorted),
      // merged into the carried ones: O(band) instead of moving each one across the band.
      const std::size_t sort_cost =
          detail::adaptive_sort(s.new_pieces.data(), s.new_pieces.size(), by_top_then_bottom_x);
      s.stats.pieces_visited += sort_cost + carried;
      if (sort_cost > s.row_budget_left) return false;
      s.row_budget_left -= sort_cost;
      s.merged_pieces.resize(carried + s.new_pieces.size());
      std::merge(s.chain_pieces.begin() + static_cast<std::ptrdiff_t>(begin), s.chain_pieces.end(),
                 s.new_pieces.begin(), s.new_pieces.end(), s.merged_pieces.begin(), by_top_then_bottom_x);
      s.chain_pieces.resize(begin);
      s.chain_pieces.insert(s.chain_pieces.end(), s.merged_pieces.begin(), s.merged_pieces.end());
    }
    ChainPiece* band = s.chain_pieces.data() + begin;
    const std::size_t count = s.chain_pieces.size() - begin;
    s.chain_order.resize(count);
    for (std::size_t p = 0; p < count; ++p) s.chain_order[p] = band[p].chain;
    // Clusters: the band is cut between positions i - 1 and i where every piece before lies at or left
    // of every piece from i on over the whole band (the greatest x_max before <= the least x_min after).
    // No chain of one side can meet a chain of the other, so each cluster is resolved alone. Inside a
    // cluster, neighbours in the top order that keep their order down the band (disjoint extents, or
    // chain_stays_left) keep the whole cluster's order: no crossing, and the chain walk of pass 2 applies.
    // A cluster whose chains do cross is cut at its own chains' joints only (pass 2), so a band where two
    // pieces of a stroke's outline overlap does not cut the band's other chains at their joints.
    s.suffix_x_min.resize(count + 1);
    s.suffix_x_min[count] = INFINITY;
    for (std::size_t i = count; i-- > 0;) s.suffix_x_min[i] = std::min(s.suffix_x_min[i + 1], band[i].x_min);
    int winding = winding_left;
    std::size_t i = 0;
    while (i < count) {
      const std::size_t first = i;
      const int cluster_left = winding;
      double reach = band[i].x_max;
      bool crossing = false;
      winding += band[i].dir;
      for (++i; i < count && reach > s.suffix_x_min[i]; ++i) {
        crossing = crossing ||
                   (band[i - 1].x_max > band[i].x_min && !chain_stays_left(edges, band[i - 1], band[i], bb));
        reach = std::max(reach, band[i].x_max);
        winding += band[i].dir;
      }
      if (!crossing) continue;
      // This cluster is cut at its chains' joints and resolved by straight pieces (pass 2): charge that
      // to the row's budget now, so that a row too dear for it goes to the per-edge path before anything
      // is accumulated.
      std::uint64_t joints = 0;
      for (std::size_t p = first; p < i; ++p) {
        for (std::uint32_t j = band[p].first_edge; edges[j].y_bot < bb; j = edges[j].below) ++joints;
      }
      const std::uint64_t cost = (joints + 1) * (i - first) + joints;
      if (cost > s.row_budget_left) return false;
      s.row_budget_left -= cost;
      s.crossing_clusters.push_back({begin + first, begin + i, cluster_left});
    }
  }
  s.band_offsets.push_back(s.chain_pieces.size());
  s.band_clusters.push_back(s.crossing_clusters.size());

  // Pass 2: walk each band; every edge of a boundary chain adds its part inside the band. A cluster
  // whose chains cross is cut at their joints instead, and each sub-band resolved from straight pieces
  // (the per-edge path, steps 2-4, on this cluster only).
  for (std::size_t k = 0; k + 1 < s.events.size(); ++k) {
    const double ba = s.events[k];
    const double bb = s.events[k + 1];
    std::size_t next_cluster = s.band_clusters[k];
    const std::size_t clusters_end = s.band_clusters[k + 1];
    int winding = winding_left;
    bool filled = detail::is_filled(winding, rule);
    std::size_t p = s.band_offsets[k];
    while (p < s.band_offsets[k + 1]) {
      if (next_cluster < clusters_end && s.crossing_clusters[next_cluster].begin == p) {
        const detail::CrossingCluster& cluster = s.crossing_clusters[next_cluster++];
        resolve_cluster_by_edges(s, cluster, ba, bb, rule);
        for (; p < cluster.end; ++p) winding += s.chain_pieces[p].dir;
        filled = detail::is_filled(winding, rule);
        continue;
      }
      const ChainPiece& piece = s.chain_pieces[p++];
      winding += piece.dir;
      const bool now = detail::is_filled(winding, rule);
      if (now == filled) continue;
      filled = now;
      const double sign = now ? 1.0 : -1.0;
      std::uint32_t j = piece.first_edge;
      while (true) {
        const ClippedEdge& e = edges[j];
        if (e.y_top >= ba && e.y_bot <= bb) {
          // The whole edge lies in this band, so this is its only run in the row: straight to the row,
          // without the run bookkeeping (most edges of a finely flattened curve take this path).
          s.row.add_boundary(e.x_top, e.x_bot, e.y_bot - e.y_top, sign);
        } else {
          add_boundary_run(s, j, std::max(ba, e.y_top), std::min(bb, e.y_bot), sign);
        }
        if (e.y_bot >= bb) break;
        j = e.below;
      }
    }
  }
  // The edges that go on below this row are the last edges of the chains of the last band: they become
  // the active list, in that band's x order, so the next row's chains and pieces come nearly sorted.
  const std::size_t last = s.events.size() - 2;
  s.band_active.clear();
  for (std::size_t p = s.band_offsets[last]; p < s.band_offsets[last + 1]; ++p) {
    std::uint32_t j = s.chain_pieces[p].first_edge;
    while (edges[j].y_bot < yb) j = edges[j].below;
    if (edges[j].y_bot > yb) s.band_active.push_back(j);
  }
  s.active.swap(s.band_active);
  return true;
}

/// Exact coverage of row y (the strip y..y+1) from the active edges; s.active[first_new..] are the edges
/// that start in this row, `winding_left` the winding number left of all of them. All of them as one
/// group (see cover_row).
void cover_row_group(detail::ScanState& s, int y, std::size_t first_new, FillRule rule, int winding_left) {
  const double ya = y;
  const double yb = ya + 1.0;
  const ClippedEdge* edges = s.edges.data();
  // Whether some edge starts or ends inside the row: only that is asked here (the paths below gather
  // their own events), so the look stops at the first one.
  const bool has_events = std::any_of(s.active.begin(), s.active.end(), [&](std::uint32_t i) {
    return edges[i].y_top > ya || edges[i].y_bot < yb;
  });

  if (!has_events) {
    // Fast path: every active edge spans the whole row, one band. The active list is written back in
    // the band's sorted order, so that the next row starts nearly sorted.
    gather_pieces(s, s.active, ya, yb);
    resolve_band(s, ya, yb, true, rule, winding_left);
    for (std::size_t k = 0; k < s.pieces.size(); ++k) s.active[k] = s.pieces[k].edge;
    return;
  }

  // Joints of chains are not real events: try the row by chains first.
  s.stats.pieces_visited += s.active.size();
  if (cover_row_by_chains(s, ya, yb, rule, winding_left)) return;
  s.events.clear();
  for (const std::uint32_t i : s.active) {
    if (edges[i].y_top > ya) s.events.push_back(edges[i].y_top);
    if (edges[i].y_bot < yb) s.events.push_back(edges[i].y_bot);
  }
  // A row cut into many bands by many active edges would cost bands × edges on the exact path (every
  // band gathers and sorts all its pieces): past the row's budget, sample it instead (essay, step 7).
  const std::uint64_t band_cost = (s.events.size() + 1) * s.active.size();
  if (band_cost > s.row_budget_left) {
    detail::sample_row_exact_in_x(s, y, rule, winding_left);
    return;
  }
  s.row_budget_left -= std::min(s.row_budget_left, band_cost);

  // Bands between events. The edges covering a band are tracked incrementally (added when their top is
  // reached, dropped when their bottom is), so a row holding thousands of short edges (the top of a
  // finely flattened circle) costs O(edges in the row + Σ edges per band), not O(events · edges).
  s.events.push_back(ya);
  s.events.push_back(yb);
  std::sort(s.events.begin(), s.events.end());
  s.events.erase(std::unique(s.events.begin(), s.events.end()), s.events.end());
  // The edges that start in this row are added as the bands reach their tops.
  std::sort(s.active.begin() + static_cast<std::ptrdiff_t>(first_new), s.active.end(),
            [&](std::uint32_t a, std::uint32_t b) { return edges[a].y_top < edges[b].y_top; });
  // Edges carried from the rows above cover the first band; they are in x order from the last row.
  s.band_active.assign(s.active.begin(), s.active.begin() + static_cast<std::ptrdiff_t>(first_new));
  std::size_t next_new = first_new;
  for (std::size_t k = 0; k + 1 < s.events.size(); ++k) {
    const double ba = s.events[k];
    const double bb = s.events[k + 1];
    while (next_new < s.active.size() && edges[s.active[next_new]].y_top <= ba) {
      s.band_active.push_back(s.active[next_new++]);
    }
    std::erase_if(s.band_active, [&](std::uint32_t i) { return edges[i].y_bot <= ba; });
    if (s.band_active.empty()) continue;
    // Every edge left covers [ba, bb]: its top is at or above ba and its bottom, an event, is below ba.
    gather_pieces(s, s.band_active, ba, bb);
    resolve_band(s, ba, bb, false, rule, winding_left);
    for (std::size_t p = 0; p < s.pieces.size(); ++p) s.band_active[p] = s.pieces[p].edge;
  }
  // The edges that go on below this row are exactly those of the last band: keep them, in x order.
  std::erase_if(s.band_active, [&](std::uint32_t i) { return edges[i].y_bot <= ya; });
  s.active.swap(s.band_active);
}

/// Rows of fewer active edges than this are scanned as one group: a glyph's or an icon's row has few
/// bands, and looking for independent groups would cost more than it saves.
constexpr std::size_t kGroupsFrom = 32;

/// Exact coverage of row y from the active edges (s.active[first_new..] start in this row): group by group
/// where the row splits into independent groups (step 9), else as one.
void cover_row(detail::ScanState& s, int y, std::size_t first_new, FillRule rule) {
  const double ya = y;
  const double yb = ya + 1.0;
  // A row in which no chain starts or ends is one band already (cover_row_group's fast path when no edge
  // starts or ends in it either, else one band of the chain path): groups would cut no fewer bands.
  // Chain tops are among the edges new in this row: those are looked at first.
  const auto is_tip = [&](std::uint32_t i) {
    const ClippedEdge& e = s.edges[i];
    return (e.y_top > ya && !e.linked_above) || (e.y_bot < yb && e.below == ClippedEdge::kNoEdge);
  };
  const auto carried_end = s.active.begin() + static_cast<std::ptrdiff_t>(first_new);
  const bool has_tips =
      std::any_of(carried_end, s.active.end(), is_tip) || std::any_of(s.active.begin(), carried_end, is_tip);
  if (s.active.size() < kGroupsFrom || !has_tips || !detail::split_row_into_groups(s, ya, yb, first_new)) {
    cover_row_group(s, y, first_new, rule, 0);
    return;
  }
  s.next_active.clear();
  for (std::size_t g = 0; g + 1 < s.group_offsets.size(); ++g) {
    const auto begin = s.group_edges.begin() + s.group_offsets[g];
    const auto end = s.group_edges.begin() + s.group_offsets[g + 1];
    s.active.assign(begin, end);
    cover_row_group(s, y, s.group_carried[g], rule, s.group_winding[g]);
    // What goes on below, group after group: still left to right.
    s.next_active.insert(s.next_active.end(), s.active.begin(), s.active.end());
  }
  s.active.swap(s.next_active);
}

/// Aliased row y: pixels whose centre's winding number satisfies the rule.
void sample_row(detail::ScanState& s, int y, FillRule rule) {
  const double yc = y + 0.5;
  s.pieces.clear();
  for (const std::uint32_t i : s.active) {
    const ClippedEdge& e = s.edges[i];
    if (e.y_top <= yc && yc < e.y_bot) s.pieces.push_back({e.x_at(yc), 0.0, e.dir, i});
  }
  s.stats.pieces_visited +=
      s.active.size() +
      detail::adaptive_sort(s.pieces.data(), s.pieces.size(),
                            [](const BandPiece& a, const BandPiece& b) { return a.xa < b.xa; });
  const IntRect& clip = s.clip;
  // Centre c + 0.5 is right of (or on) a crossing at x when c >= x - 0.5.
  const auto first_pixel_from = [&](double x) {
    return static_cast<int>(
        std::clamp(std::ceil(x - 0.5), static_cast<double>(clip.x0), static_cast<double>(clip.x1)));
  };
  const std::size_t row_begin = s.spans.size();
  const auto emit = [&](int x0, int x1) {
    if (x1 <= x0) return;
    if (s.spans.size() > row_begin && s.spans.back().x + s.spans.back().len == x0) {
      s.spans.back().len += x1 - x0;  // two filled runs less than a pixel centre apart: one span
      return;
    }
    s.spans.push_back({x0, y, x1 - x0, 255});
  };
  int winding = 0;
  bool filled = false;
  int start = clip.x0;
  for (const BandPiece& p : s.pieces) {
    winding += p.dir;
    const bool now = detail::is_filled(winding, rule);
    if (now == filled) continue;
    if (now) {
      start = first_pixel_from(p.xa);
    } else {
      emit(start, first_pixel_from(p.xa));
    }
    filled = now;
  }
  if (filled) emit(start, clip.x1);  // the leaving edges lie right of the clip (dropped by the clipper)
}

/// The pieces a row of `active` edges may visit on the exact path before it is sampled (essay, step 7):
/// factor·n·⌈log2(n + 2)⌉ (the cost of the sampled fallback for factor 16) plus what is left of the
/// fill's shared pool; factor 0 gives 0 (every crossing band sampled, for tests), +infinity never samples.
std::uint64_t row_budget(std::size_t active, double factor, std::uint64_t pool_left) noexcept {
  if (factor == 0.0) return 0;
  const double budget =
      factor * static_cast<double>(active) * static_cast<double>(detail::sort_depth(active));
  if (!(budget < 1e18)) return UINT64_MAX;
  const std::uint64_t own = static_cast<std::uint64_t>(budget);
  return own > UINT64_MAX - pool_left ? UINT64_MAX : own + pool_left;
}

/// Orders the edges by the row of their top: a counting sort, O(n + rows the edges start in) — the
/// buckets span only the rows between the highest and the lowest top, so a small shape in a large clip
/// does not pay for the clip's height.
void bucket_edges_by_row(detail::ScanState& s) {
  const std::size_t count = s.edges.size();
  double top_min = s.edges[0].y_top;
  double top_max = top_min;
  for (std::size_t i = 0; i < count; ++i) {
    top_min = std::min(top_min, s.edges[i].y_top);
    top_max = std::max(top_max, s.edges[i].y_top);
  }
  // Clipped tops lie in [clip.y0, clip.y1), which may be negative (a glyph box above its baseline), so
  // rows are floors, not truncations: truncating -0.5 to 0 once put y0 past the clip's last
  // row, made `rows` zero and wrote past the buckets. The clamps only guard against rounding.
  const int last_row = s.clip.y1 - 1;
  const int y0 = std::clamp(static_cast<int>(std::floor(top_min)), s.clip.y0, last_row);
  const std::size_t rows =
      static_cast<std::size_t>(std::clamp(static_cast<int>(std::floor(top_max)), y0, last_row) - y0) + 1;
  const auto row_of = [&](const ClippedEdge& e) {
    return std::min(static_cast<std::size_t>(std::max(std::floor(e.y_top) - y0, 0.0)), rows - 1);
  };
  s.bucket_start.assign(rows + 1, 0);
  s.edge_row.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t row = row_of(s.edges[i]);
    s.edge_row[i] = static_cast<std::uint32_t>(row);
    ++s.bucket_start[row + 1];
  }
  for (std::size_t r = 0; r < rows; ++r) s.bucket_start[r + 1] += s.bucket_start[r];
  // Positions are assigned bucket by bucket, in input order inside a bucket (the per-edge band path sorts
  // a row's new edges by top when it needs them so; most rows never do).
  s.bucket_fill.assign(s.bucket_start.begin(), s.bucket_start.end() - 1);
  s.bucket_keys.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    s.bucket_keys[s.bucket_fill[s.edge_row[i]]++] = static_cast<std::uint32_t>(i);
  }
  s.new_index.resize(count);
  for (std::size_t k = 0; k < count; ++k) s.new_index[s.bucket_keys[k]] = static_cast<std::uint32_t>(k);
  s.sorted_edges.resize(count);
  for (std::size_t k = 0; k < count; ++k) {
    ClippedEdge e = s.edges[s.bucket_keys[k]];
    if (e.below != ClippedEdge::kNoEdge) e.below = s.new_index[e.below];
    s.sorted_edges[k] = e;
  }
  s.edges.swap(s.sorted_edges);
}

}  // namespace

IntRect Rasterizer::clip() const noexcept {
  return impl_ ? impl_->clip : IntRect{};
}

RasterizerStats Rasterizer::stats() const noexcept {
  return impl_ ? impl_->stats : RasterizerStats{};
}

void Rasterizer::set_crossing_budget(double factor) {
  if (!impl_) reset(IntRect{});
  impl_->crossing_budget = factor > 0.0 ? factor : 0.0;  // NaN and negative: 0
}

void Rasterizer::set_sweep_crossing_budget(double factor) {
  if (!impl_) reset(IntRect{});
  impl_->sweep_crossing_budget = factor > 0.0 ? factor : 0.0;  // NaN and negative: 0
}

void Rasterizer::ImplDeleter::operator()(Impl* impl) const noexcept {
  delete impl;
}

void Rasterizer::reset(IntRect clip) {
  if (!impl_) impl_.reset(new Impl);
  impl_->clip = clip;
  impl_->edges.clear();
}

std::pair<int, int> Rasterizer::edge_rows() const noexcept {
  if (!impl_ || impl_->edges.empty()) return {0, 0};
  double top = impl_->edges.front().y_top;
  double bottom = impl_->edges.front().y_bot;
  for (const ClippedEdge& e : impl_->edges) {
    top = std::min(top, e.y_top);
    bottom = std::max(bottom, e.y_bot);
  }
  // Clipped edges lie inside the clip box's rows, so these fit in int.
  return {static_cast<int>(std::floor(top)), static_cast<int>(std::ceil(bottom))};
}

void Rasterizer::split_at_rows(std::span<const int> cuts, std::span<Rasterizer> lower) {
  if (!impl_) reset(IntRect{});
  if (cuts.empty() || lower.size() != cuts.size()) return;
  Impl& s = *impl_;
  const IntRect clip = s.clip;
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    const int bottom = k + 1 < cuts.size() ? cuts[k + 1] : clip.y1;
    lower[k].reset(IntRect{clip.x0, std::clamp(cuts[k], clip.y0, clip.y1), clip.x1,
                           std::clamp(bottom, clip.y0, clip.y1)});
  }
  s.clip.y1 = std::clamp(cuts[0], clip.y0, clip.y1);
  // Band 0 is this rasterizer (rows above cuts[0]), band b >= 1 is lower[b - 1].
  const auto edges_of = [&](std::size_t band) -> std::vector<ClippedEdge>& {
    return lower[band - 1].impl_->edges;
  };
  std::size_t kept = 0;
  for (std::size_t i = 0, count = s.edges.size(); i < count; ++i) {
    const ClippedEdge e = s.edges[i];
    const auto first =
        static_cast<std::size_t>(std::upper_bound(cuts.begin(), cuts.end(), e.y_top) - cuts.begin());
    const auto last =
        static_cast<std::size_t>(std::lower_bound(cuts.begin(), cuts.end(), e.y_bot) - cuts.begin());
    if (first >= last) {
      (first == 0 ? s.edges[kept++] : edges_of(first).emplace_back()) = e;
      continue;
    }
    double x0 = e.x_top, y0 = e.y_top;
    for (std::size_t band = first; band <= last; ++band) {
      const double y1 = band < last ? cuts[band] : e.y_bot;
      const double x1 = band < last ? e.x_at(y1) : e.x_bot;
      const ClippedEdge piece{x0, y0, x1, y1, (x1 - x0) / (y1 - y0), e.dir, false, ClippedEdge::kNoEdge};
      (band == 0 ? s.edges[kept++] : edges_of(band).emplace_back()) = piece;
      x0 = x1;
      y0 = y1;
    }
  }
  s.edges.resize(kept);
}

std::size_t Rasterizer::edge_count() const noexcept {
  return impl_ ? impl_->edges.size() : 0;
}

void Rasterizer::add_line(Point a, Point b) {
  if (!impl_) reset(IntRect{});  // a default-constructed rasterizer has an empty clip: nothing is visible
  detail::clip_edge(a, b, impl_->clip, impl_->edges);
}

void Rasterizer::add_polyline(std::span<const Point> points) {
  if (!impl_) reset(IntRect{});  // as add_line
  detail::clip_polyline(points, impl_->clip, impl_->edges);
}

namespace {

/// Steps 1-7 of the essay: the row scan of the edges in s (linked), for any fill.
void scan_rows(detail::ScanState& s, FillRule rule, Antialias antialias, SpanSink& sink) {
  const IntRect clip = s.clip;
  const std::size_t count = s.edges.size();
  bucket_edges_by_row(s);  // s.edges now in bucket order; the input order is restored at the end
  s.pending.assign(count, detail::PendingBoundary{});
  s.pending_edges.clear();
  if (antialias == Antialias::kExact) s.row.reset(clip.x0, clip.x1 - clip.x0);
  s.active.clear();
  s.spans.clear();
  s.pool_left = s.crossing_budget == 0.0 ? 0 : detail::kWorkPool;

  std::size_t next = 0;
  int y = clip.y0;
  while (y < clip.y1) {
    if (s.active.empty()) {
      if (next == count) break;
      // Skip the empty rows up to the next edge (clipped, so its top is inside the clip rows).
      y = std::max(y, static_cast<int>(std::floor(s.edges[next].y_top)));
    }
    const double row_top = y;
    const double row_bottom = row_top + 1.0;
    std::erase_if(s.active, [&](std::uint32_t i) { return s.edges[i].y_bot <= row_top; });
    const std::size_t first_new = s.active.size();
    while (next < count && s.edges[next].y_top < row_bottom)
      s.active.push_back(static_cast<std::uint32_t>(next++));

    if (antialias == Antialias::kExact) {
      s.row_budget_left = row_budget(s.active.size(), s.crossing_budget, s.pool_left);
      cover_row(s, y, first_new, rule);
      s.pool_left = std::min(s.pool_left, s.row_budget_left);  // a row spends its own budget first
      flush_boundary_runs(s);
      s.row.emit(y, s.spans);
    } else {
      sample_row(s, y, rule);
    }
    detail::hand_over_spans(s, sink, false);
    ++y;
  }
  detail::hand_over_spans(s, sink, true);
  s.edges.swap(s.sorted_edges);  // back to the input order (the links are recomputed on every scan)
}

/// Writes spans into an 8-bit mask of the clip box (the mask starts at zero; spans never overlap).
class MaskWriter final : public SpanSink {
 public:
  MaskWriter(std::span<std::uint8_t> mask, IntRect box) : mask_(mask), box_(box) {}
  void blend(std::span<const Span> spans) override {
    const auto width = static_cast<std::size_t>(box_.x1 - box_.x0);
    for (const Span& span : spans) {
      std::uint8_t* row = mask_.data() + static_cast<std::size_t>(span.y - box_.y0) * width;
      std::memset(row + (span.x - box_.x0), span.coverage, static_cast<std::size_t>(span.len));
    }
  }

 private:
  std::span<std::uint8_t> mask_;
  IntRect box_;
};

}  // namespace

void Rasterizer::rasterize(FillRule rule, Antialias antialias, SpanSink& sink) {
  if (!impl_ || impl_->clip.empty() || impl_->edges.empty()) return;
  Impl& s = *impl_;
  s.stats = {};
  detail::link_edges_into_chains(s);  // the links every scan needs, and the planar proof's chains
  if (antialias == Antialias::kExact && detail::prove_planar_chains(s, rule)) {
    ++s.stats.planar_fills;
    if (!detail::accumulate_small_planar(s, sink)) detail::accumulate_planar(s, sink);
    return;
  }
  scan_rows(s, rule, antialias, sink);
}

void Rasterizer::rasterize_mask(FillRule rule, std::span<std::uint8_t> mask) {
  if (!impl_ || impl_->clip.empty()) return;
  Impl& s = *impl_;
  const int width = s.clip.x1 - s.clip.x0;
  const int height = s.clip.y1 - s.clip.y0;
  if (mask.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) return;
  s.stats = {};
  bool planar = false;
  if (!s.edges.empty()) {
    detail::link_edges_into_chains(s);
    planar = detail::prove_planar_chains(s, rule);
  }
  if (planar) {
    ++s.stats.planar_fills;
    if (detail::DenseCoverage::fits(width, height)) {
      detail::accumulate_planar_dense(s, s.clip, mask);
      return;
    }
  }
  // The span paths write covered pixels only.
  std::fill(mask.begin(), mask.end(), std::uint8_t{0});
  if (s.edges.empty()) return;
  MaskWriter writer(mask, s.clip);
  if (planar) {
    detail::accumulate_planar(s, writer);
  } else {
    scan_rows(s, rule, Antialias::kExact, writer);
  }
}

}  // namespace curvescan
