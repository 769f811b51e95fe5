// Rasterizer::Impl: the state shared by the optimised scan (rasterizer.cpp) and the plain reference scan
// (rasterizer_reference.cpp). The method is described in the essay at the top of rasterizer.cpp.
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "coverage_row.h"
#include "dense_coverage.h"
#include "curvescan/raster/rasterizer.h"
#include "edge_clip.h"

namespace curvescan {

namespace detail {

/// A piece of an edge inside a band [ya, yb] of a row: x at the top and bottom of the band.
struct BandPiece {
  double xa = 0.0;
  double xb = 0.0;
  int dir = 0;
  std::uint32_t edge = 0;  ///< index into Impl::edges
};

/// Whether winding number `w` is inside under `rule`.
[[nodiscard]] inline bool is_filled(int winding, FillRule rule) noexcept {
  return rule == FillRule::kNonZero ? winding != 0 : (winding & 1) != 0;
}

/// Walks the pieces of a band, given in left-to-right order with no two crossing inside the band, and
/// calls on_boundary(piece, sign) for every piece across which the rule's filled state flips: sign +1
/// where the filled region starts (entering), -1 where it ends (leaving). `winding_left` is the winding
/// number left of the first piece (0 for a whole band; a cluster of a band, below, starts from the
/// directions of the chains left of it).
template <class OnBoundary>
inline void for_each_boundary(const BandPiece* pieces, std::size_t count, FillRule rule,
                              OnBoundary on_boundary, int winding_left = 0) {
  int winding = winding_left;
  bool filled = is_filled(winding, rule);
  for (std::size_t i = 0; i < count; ++i) {
    winding += pieces[i].dir;
    const bool now = is_filled(winding, rule);
    if (now != filled) {
      on_boundary(pieces[i], now ? 1.0 : -1.0);
      filled = now;
    }
  }
}

/// A chain: edges of the row joined end to end (ClippedEdge::below), a y-monotone polyline from `top` to
/// `bottom` inside the row.
struct RowChain {
  std::uint32_t first = 0;
  double top = 0.0;
  double bottom = 0.0;
  int dir = 0;
  std::uint32_t cursor = 0;  ///< while the row's bands are cut: the chain's edge at the current band's top
};

/// A chain cut to one band: x at the band's top and bottom, and its x extent inside the band.
struct ChainPiece {
  double xa = 0.0;
  double xb = 0.0;
  double x_min = 0.0;
  double x_max = 0.0;
  int dir = 0;
  std::uint32_t first_edge = 0;  ///< the chain's edge at the band's top
  std::uint32_t chain = 0;       ///< index of the chain in ScanState::chains
};

/// A y-monotone chain of the whole fill for the planar proof (rasterizer_planar.cpp): edges joined end to end
/// from `head` (top) down to `bottom`.
struct PlanarChain {
  std::uint32_t head = 0;
  std::uint32_t cursor = 0;  ///< the edge holding the sweep height (y_top <= y < y_bot)
  double top = 0.0;
  double bottom = 0.0;
  /// The least and greatest x of its vertices: a chain whose x_max is at or left of another's x_min stays
  /// at or left of it at every height (planar_checks.h, in_order_by_extent).
  double x_min = 0.0;
  double x_max = 0.0;
  int dir = 0;
  std::uint32_t open_piece = 0;  ///< its last boundary piece (index into ScanState::planar_pieces), or kNone
  /// The chain proven to stay at or right of this one down to the lower of their bottoms (its right
  /// neighbour when they last became neighbours), or kNone: that pair is not checked again.
  std::uint32_t checked_right = kNone;
  /// Where it crosses the chain checked_right (the height of that pair's queued crossing event), or
  /// +infinity when that chain stays at or right of it.
  double cross_y = 0.0;
  /// The last two chains a walk of their joints (first_crossing) proved to stay at or right of this one
  /// down to the lower of their bottoms, newest first, or kNone: a pair parted by a short chain (a round
  /// join's piece between a stroke's two sides) and neighbours again below it is not walked again
  /// (planar_checks.h, proven_in_order).
  std::uint32_t proven_right[2] = {kNone, kNone};
  /// Its place in the x order (ScanState::planar_active) when it was last numbered; exact while it is
  /// left of the first place changed since (prove_planar_chains' `numbered`).
  std::uint32_t position = 0;
  /// The winding number just right of it, as of the last event or crossing that changed it.
  int winding_right = 0;
  /// The sign of its open boundary piece (open_piece; its y1 not yet final), or 0 when none is open.
  std::int8_t boundary = 0;
  /// Whether its edges' PlanarBlock entries (ScanState::planar_blocks) are written: when it is first
  /// walked by the general sweep (planar_checks.h, first_crossing_by_blocks).
  bool blocks_built = false;
  static constexpr std::uint32_t kNone = 0xffffffffu;
};

/// Per edge of a chain, what the rest of its block of kPlanarBlockEdges consecutive edges spans: the least
/// and greatest x of the vertices from this edge's top down to the block's last edge's bottom, that height,
/// and the block's last edge. A neighbour walk (first_crossing_by_blocks) whose two chains' entries are
/// apart in x passes every joint down to the nearer block end at once.
struct PlanarBlock {
  double x_min = 0.0;
  double x_max = 0.0;
  double y_end = 0.0;
  std::uint32_t last = 0;
};

/// How many edges of a chain a PlanarBlock covers. Measured on the 20 px stroke of 50 cubics
/// (docs/benchmarks.md): the walk's joints fall with the block's size up to a point, then the extents
/// of a long block overlap where a short one's would not.
inline constexpr std::size_t kPlanarBlockEdges = 16;

/// A crossing of two neighbouring chains of the whole-fill sweep (rasterizer_planar.cpp): `left` passes
/// right of `right` at height y.
struct PlanarCrossing {
  double y = 0.0;
  std::uint32_t left = 0;
  std::uint32_t right = 0;
};

/// A boundary piece found by the planar proof: chain edges from `first_edge` (which holds y0) down to y1,
/// across which the filled state flips with `sign` (+1 enter, -1 leave).
struct PlanarPiece {
  std::uint32_t first_edge = 0;
  double y0 = 0.0;
  double y1 = 0.0;
  double sign = 0.0;
};

/// An active edge's x extent inside the current row, and its position in ScanState::active
/// (rasterizer_row_groups.cpp).
struct GroupExtent {
  double x_min = 0.0;
  double x_max = 0.0;
  std::uint32_t position = 0;
  // What the groups' checks need of the edge in this row, read once with its extent (the edges
  // themselves lie scattered through the fill's edges): its direction, and kGroupEdge* flags.
  std::int8_t dir = 0;
  std::uint8_t flags = 0;
};

/// GroupExtent::flags: the edge is active at the row's top; it starts inside the row without an edge
/// above it in its chain (a chain top); it ends inside the row without one below (a chain bottom); it
/// starts or ends inside the row at all (a joint or a tip).
constexpr std::uint8_t kGroupEdgeAtTop = 1;
constexpr std::uint8_t kGroupEdgeChainTop = 2;
constexpr std::uint8_t kGroupEdgeChainBottom = 4;
constexpr std::uint8_t kGroupEdgeEndsInside = 8;

/// Where an edge of a row group starts (+dir) or ends (-dir) inside the row.
struct GroupEvent {
  double y = 0.0;
  int change = 0;
};

/// A run of a band's chain pieces (positions [begin, end) of ScanState::chain_pieces, in x order) that
/// some chain outside it cannot meet: every piece left of the run lies at or left of every piece of the
/// run, and every piece right of it at or right of them, over the whole band. Only such a run whose own
/// chains cross is stored (rasterizer.cpp, cover_row_by_chains); it is resolved alone, from the winding
/// number on its left, which the chains left of it fix for the whole band (each spans the band).
struct CrossingCluster {
  std::size_t begin = 0;
  std::size_t end = 0;
  int winding_left = 0;
};

/// A pair of pieces of a band (indices into ScanState::pieces) that cross at height y.
struct BandCrossing {
  double y = 0.0;
  std::uint32_t left_at_top = 0;
  std::uint32_t right_at_top = 0;
};

/// An edge at one sub-scanline of a sampled row (sample_row_exact_in_x): its x there, its position in the
/// row's copy of its edges, and its direction there (0 where it does not meet the sub-scanline).
struct SampleItem {
  double x = 0.0;
  std::uint32_t slot = 0;
  int dir = 0;
};

/// The edges of a sampled row's column bucket at one sub-scanline, by direction.
struct ColumnCounts {
  std::uint32_t falling = 0;  ///< direction +1 (going down)
  std::uint32_t rising = 0;   ///< direction −1 (going up)
};

/// The default of Rasterizer::set_crossing_budget().
inline constexpr double kDefaultCrossingBudget = 16.0;

/// The default of Rasterizer::set_sweep_crossing_budget(): the whole-fill sweep (rasterizer_planar.cpp)
/// resolves up to this many crossings per edge (plus kSweepCrossingsBase) before the fill is scanned row
/// by row instead.
inline constexpr double kDefaultSweepCrossingBudget = 32.0;
inline constexpr std::uint64_t kSweepCrossingsBase = 4096;
/// Above this mean edge height (rows) the sweep's crossing budget shrinks in proportion (rasterizer.cpp,
/// sweep_crossing_limit).
inline constexpr double kSweepMeanEdgeRows = 16.0;
/// The sweep's steps allowed per crossing allowed (a crossing checks three pairs of neighbours and
/// reorders the queue).
inline constexpr std::uint64_t kSweepStepsPerCrossing = 16;
/// The crossings the sweep resolves before it estimates a fill's total from the height swept so far
/// (rasterizer_planar.cpp).
inline constexpr std::uint64_t kSweepCrossingsSample = 1024;

/// A boundary run of one edge inside the current row: consecutive bands where the edge is a boundary with
/// the same sign join into one straight piece, so the row accumulator sees each edge about once per row
/// however many bands other edges cut the row into.
struct PendingBoundary {
  double y_start = 0.0;
  double y_end = 0.0;
  double sign = 0.0;
  bool live = false;
};

}  // namespace detail

namespace detail {

/// Everything the scans need: the clipped edges and the scratch they reuse.
struct ScanState {
  IntRect clip;
  std::vector<detail::ClippedEdge> edges;  // clipped, top to bottom, horizontal ones dropped

  // Scratch reused across rasterize() calls, so that steady-state rendering does not allocate.
  detail::CoverageRow row;
  std::vector<std::size_t> bucket_start;  // first edge of each row's bucket (counting sort by row)
  std::vector<std::size_t> bucket_fill;   // fill cursor per bucket
  std::vector<std::uint32_t> edge_row;                        // bucket (row of the top) of each edge
  std::vector<std::uint32_t> bucket_keys;                     // old edge index, in bucket order
  std::vector<std::uint32_t> new_index;                       // old edge index -> bucketed index
  std::vector<detail::ClippedEdge> sorted_edges;  // the edges in bucket order (swapped into `edges`)
  std::vector<std::uint32_t> active;              // edges meeting the current row
  std::vector<std::uint32_t> band_active;         // the edges covering the current band, kept in x order
  std::vector<double> events;                     // heights inside the row where an edge starts or ends
  std::vector<Span> spans;                        // spans waiting to be sent to the sink
  std::vector<detail::BandPiece> pieces;          // the pieces of the current band
  std::vector<detail::PendingBoundary> pending;   // per edge: its boundary run in the current row
  std::vector<std::uint32_t> pending_edges;       // the edges with a live run
  std::vector<detail::RowChain> chains;           // the chains of the current row
  std::vector<detail::ChainPiece> chain_pieces;   // the chains cut to each band, band after band
  std::vector<std::size_t> band_offsets;          // where each band's chain pieces start
  std::vector<detail::CrossingCluster> crossing_clusters;  // the chain path's crossing clusters, band after band
  std::vector<std::size_t> band_clusters;         // where each band's crossing clusters start in them
  std::vector<std::uint32_t> chain_order;       // the chains of the previous band, in its x order
  std::vector<std::uint32_t> chain_starts;      // the chains starting inside the row, by top
  std::vector<detail::ChainPiece> new_pieces;   // a band's pieces of the chains starting at its top
  std::vector<detail::ChainPiece> merged_pieces;  // a band's carried and new pieces, merged
  std::vector<double> suffix_x_min;               // a band's least x_min from each position to its end
  std::vector<double> sub_events;                 // a crossing band of the chain path: its chains' joints
  std::vector<std::uint32_t> sub_cursors;         // and each chain's edge at the current sub-band
  std::vector<unsigned char> row_coverage;        // reference path: one row of 8-bit coverage

  // The crossing sweep of a band (rasterizer_sweep.cpp), indexed by piece (position in `pieces`) or by
  // position in the band's current x order.
  std::vector<std::uint32_t> order;               // piece at each position, current x order
  std::vector<std::uint32_t> position;            // position of each piece
  std::vector<int> winding_before;                // winding number left of each position
  std::vector<signed char> boundary_sign;         // per piece: +1 enter, -1 leave, 0 not a boundary
  std::vector<double> run_start;                  // per piece: height where its current boundary run began
  std::vector<BandCrossing> band_crossings;       // the band's crossing pairs, by height
  std::vector<std::uint32_t> carried_crossings;   // crossings (indices) whose pair has not swapped yet
  std::vector<std::pair<std::size_t, std::size_t>> repair_ranges;  // position ranges to re-sort at a height
  // The planar proof and its accumulation (rasterizer_planar.cpp).
  std::vector<detail::PlanarChain> planar_chains;
  std::vector<detail::PlanarBlock> planar_blocks;  // per edge: its chain's block from it down (PlanarBlock)
  std::vector<std::uint32_t> planar_order;        // chains by top
  std::vector<std::uint32_t> planar_active;       // chains meeting the sweep height, in x order
  std::vector<detail::PlanarPiece> planar_pieces; // boundary pieces, by y0
  std::vector<detail::PlanarCrossing> planar_crossings;  // the sweep's queued crossings, a heap by height
  std::vector<std::uint32_t> planar_by_bottom;           // chains by bottom
  std::vector<std::uint32_t> planar_changed;      // places in planar_active whose neighbour an event changed
  std::vector<std::uint32_t> planar_row_pieces;   // pieces meeting the current row
  std::vector<std::uint32_t> planar_cursor;       // per piece: its edge holding the current row's top
  std::vector<Span> planar_repeat_spans;          // accumulate_planar: the last row's spans, to repeat
  detail::DenseCoverage dense;                    // rasterize_mask of a planar fill: the whole box's cells
  bool planar_open_right = false;                 // the proof found the region filled right of every chain
  // What the general sweep's last run did with the x order (tests hold its shape to these): the places it
  // numbered (PlanarChain::position) and the chains it placed by a binary search (place_among), and the
  // neighbour pairs whose joints it walked (first_crossing).
  std::uint64_t planar_places_numbered = 0;
  std::uint64_t planar_places_searched = 0;
  std::uint64_t planar_pairs_walked = 0;
  std::uint64_t planar_joints_walked = 0;  // the steps of those walks (joints, and blocks passed at once)
  std::vector<std::uint8_t> planar_mask;          // a small planar fill's coverage box, before its spans
  // The independent groups of a row (rasterizer_row_groups.cpp).
  std::vector<detail::GroupExtent> group_extents; // the row's edges by the left end of their x extent
  std::vector<detail::GroupExtent> group_merged; // group_extents distributed by bucket of x_min
  std::vector<std::uint32_t> extent_bucket;       // per extent: its bucket of x_min
  std::vector<std::size_t> extent_bucket_start;   // where each bucket of extents starts
  std::vector<double> extent_bucket_x_max;        // per bucket: the greatest x_max of its extents
  std::vector<double> extent_bucket_x_min_max;    // per bucket: the greatest x_min of its extents
  std::vector<detail::GroupEvent> group_events;   // a group's start and end heights, for its check
  std::vector<std::uint32_t> group_of;            // per active position: its group
  std::vector<std::uint32_t> group_offsets;       // where each group's edges start in group_edges
  std::vector<std::uint32_t> group_fill;          // fill cursor per group
  std::vector<std::uint32_t> group_carried;       // per group: how many of its edges come from the row above
  std::vector<int> group_winding;                 // per group: the winding number on its left
  std::vector<std::uint32_t> group_edges;         // the active edges, group after group
  std::vector<std::uint32_t> next_active;         // the groups' edges that go on below the row
  std::vector<double> sample_x;                   // sampled bands: x of each piece at the sample height
  std::vector<std::uint32_t> sample_order;        // sampled bands: pieces in x order
  std::vector<detail::ClippedEdge> sample_edges;  // sampled rows: the row's edges, copied in x order
  std::vector<detail::SampleItem> sample_items;   // sampled rows: the edges at a sub-scanline, in x order
  std::vector<std::uint32_t> sample_active;       // sampled rows: the active list in the last x order
  std::vector<detail::SampleItem> sample_scratch; // sampled rows: a sub-scanline's items, by column
  std::vector<std::uint32_t> item_column;         // sampled rows: the column bucket of each item
  std::vector<std::size_t> column_start;          // sampled rows: where each column bucket starts
  std::vector<std::size_t> column_fill;           // sampled rows: fill cursor per column bucket
  std::vector<detail::ColumnCounts> column_counts;  // sampled rows: items of either direction per bucket
  std::vector<int> column_winding;                // sampled rows: winding number left of a marked bucket
  std::vector<unsigned char> column_marked;       // sampled rows: 1 where a bucket may hold a boundary
  std::vector<signed char> sample_dir;            // sampled rows: each edge's direction at the sub-scanline

  // Work accounting and the budget that bounds it (the cost model in the essay of rasterizer.cpp).
  RasterizerStats stats;
  double crossing_budget = kDefaultCrossingBudget;
  double sweep_crossing_budget = kDefaultSweepCrossingBudget;
  std::uint64_t row_budget_left = 0;  // pieces the current row may still visit before it is sampled
  std::uint64_t pool_left = 0;        // what is left of the fill's shared pool (kWorkPool)
};

/// Records that edge `edge` bounds the filled region over [ya, yb] of the current row with `sign`:
/// extends its run when it continues the previous one, else flushes that run to the row and starts a new
/// one (rasterizer.cpp).
void add_boundary_run(ScanState& s, std::uint32_t edge, double ya, double yb, double sign);

/// The exact crossing sweep of one band [ya, yb] whose pieces are in s.pieces, sorted by x at the top
/// (ties by x at the bottom) and not in the same order at the bottom (rasterizer_sweep.cpp). Returns
/// false, having emitted nothing, when the band holds more crossings than s.row_budget_left allows.
/// `winding_left` is the winding number left of every piece (as for for_each_boundary).
bool sweep_band(ScanState& s, double ya, double yb, bool whole_row, FillRule rule, int winding_left);

/// The bounded fallback: the band's coverage from sub-scanlines, exact in x, sampled in y
/// (rasterizer_sweep.cpp). Error bound in the essay of rasterizer.cpp.
void sample_band(ScanState& s, double ya, double yb, FillRule rule, int winding_left);

/// The same fallback for a whole row y from its active edges (rasterizer_sweep.cpp), with winding number
/// `winding_left` left of all of them.
void sample_row_exact_in_x(ScanState& s, int y, FillRule rule, int winding_left);

/// One sub-scanline of a sampled row at height yc, through the row's edges s.sample_edges: adds a
/// vertical piece of height `weight` at every boundary of the filled set along it; returns the pieces
/// visited (sub_scanline_columns.cpp).
std::uint64_t add_sub_scanline_by_columns(ScanState& s, double yc, FillRule rule, double weight,
                                          int winding_left);
/// Rewrites s.active (whose edges s.sample_edges copies, slot for slot) in x order at height yc, ties by
/// slot; returns the pieces visited (sub_scanline_columns.cpp).
std::uint64_t order_row_by_x(ScanState& s, double yc);

/// The planar fast path (essay in rasterizer.cpp, step 8), rasterizer_planar.cpp: whether no two monotone
/// chains of the fill cross (false too when the proof outgrows its budget); if so it leaves the boundary
/// pieces of the filled region in s.planar_pieces, and one of the two accumulations below turns them into
/// coverage: row by row into spans for `sink`, or densely into an 8-bit mask of the clip box
/// (DenseCoverage::fits the box).
///
/// link_edges_into_chains: links each edge to the one continuing it below (ClippedEdge::below,
/// linked_above: consecutive add_line calls of a contour going the same way and sharing the joint exactly)
/// and puts the fill's monotone chains into s.planar_chains, fresh (each cursor at its head, nothing
/// checked, no boundary), in one pass over the edges. Then: the budget of steps of the proof (32 per edge
/// plus 4096); the general sweep of those chains, through crossings (rasterizer_planar.cpp).
void link_edges_into_chains(ScanState& s);
/// The proof on the chains already in s.planar_chains (fresh, by link_edges_into_chains).
bool prove_planar_chains(ScanState& s, FillRule rule);
std::uint64_t planar_proof_budget(const ScanState& s);
bool sweep_planar_chains(ScanState& s, FillRule rule);
/// Up to how many chains a fill is swept by prove_planar_few: the general sweep's kFewOpenChains, below
/// which it makes the same passes over every open chain.
inline constexpr std::size_t kFewChains = 16;
/// prove_planar_chains for a fill of at most kFewChains chains, already built in s.planar_chains (fresh,
/// by link_edges_into_chains), without the general sweep's bookkeeping (rasterizer_planar_few.cpp): the same
/// outcome, the same boundary pieces in the same order, the same crossings resolved.
bool prove_planar_few(ScanState& s, FillRule rule);
/// The crossings the whole-fill sweep may resolve for the current edges (set_sweep_crossing_budget):
/// factor·n, scaled down by kSweepMeanEdgeRows / (the mean edge height in rows) where edges are longer than
/// that on average, plus kSweepCrossingsBase (rasterizer_planar.cpp).
std::uint64_t sweep_crossing_limit(const ScanState& s);
void accumulate_planar(ScanState& s, SpanSink& sink);
void accumulate_planar_dense(ScanState& s, IntRect box, std::span<std::uint8_t> mask);

/// accumulate_planar for a small fill (rasterizer_planar.cpp): when the fill's edges lie in a box of at
/// most kSmallFillColumns columns and kSmallFillPixels pixels and the region is closed on the right, its
/// coverage is accumulated densely over that box (accumulate_planar_dense) and the box's rows are cut
/// into spans; returns false, having done nothing, otherwise. Per row, a pass over a few dozen bytes costs
/// less than the row accumulator's bookkeeping (live pieces, touched cells across the clip's width).
bool accumulate_small_planar(ScanState& s, SpanSink& sink);
inline constexpr int kSmallFillColumns = 128;
inline constexpr std::int64_t kSmallFillPixels = 32768;
inline constexpr std::size_t kSmallFillEdges = 2048;

/// The row [ya, yb) of the active edges (s.active[first_new..] start in it) split into groups that can
/// be scanned alone (rasterizer_row_groups.cpp): false when there is one group only; else the groups'
/// edges are s.group_edges[s.group_offsets[g], s.group_offsets[g + 1]), left to right, each group in the
/// active list's order with its s.group_carried[g] edges from the row above first, and s.group_winding[g]
/// the winding number left of group g (the same at every height of the row).
bool split_row_into_groups(ScanState& s, double ya, double yb, std::size_t first_new);

/// Spans are handed to the sink in batches of about this many: one virtual call per batch, and a batch
/// small enough to stay in cache while the compositor blends it.
inline constexpr std::size_t kSpanBatch = 1024;

/// Hands the spans gathered so far to `sink` once a batch is full (after each row), or all that is left
/// (`last`: after the last row), so that every scan sends rows in the same batches.
inline void hand_over_spans(ScanState& s, SpanSink& sink, bool last) {
  if (s.spans.empty() || (!last && s.spans.size() < kSpanBatch)) return;
  sink.blend(s.spans);
  s.spans.clear();
}

/// The most crossings the sweep of one band keeps (24 bytes each: 96 MB); a band with more is sampled.
inline constexpr std::uint64_t kMaxBandCrossings = std::uint64_t{1} << 22;

/// Sub-scanlines per pixel row of the sampled fallback.
inline constexpr int kSubScanlines = 16;
/// A pool of piece visits shared by the rows of one fill, on top of each row's own budget, so that the few
/// heavy rows of ordinary content (stroke outlines: thousands of overlapping pieces) stay exact: about
/// 0.1-0.3 s of work. Rows draw on it only once their own budget is spent.
inline constexpr std::uint64_t kWorkPool = std::uint64_t{1} << 26;

}  // namespace detail

// The pimpl is the scan state; helpers in the .cpp files work on detail::ScanState (Impl is private).
struct Rasterizer::Impl : detail::ScanState {};
}  // namespace curvescan
