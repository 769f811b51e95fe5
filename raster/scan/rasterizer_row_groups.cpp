// Independent groups of a row (essay in rasterizer.cpp, step 9).
//
// A row is cut into bands wherever one of its edges starts or ends, and every band visits every chain or
// edge of the row: bands × pieces. A row of a dashed stroke holds hundreds of short dashes side by side,
// each with its own tips, so the whole row is cut at every tip of every dash although no dash sees
// another; a wide stroke's row holds many pieces of outline that overlap only here and there. Here the
// row's edges are split into groups that can be scanned alone:
//
// Sort the edges by the left end of their x extent inside the row; a gap (the extents so far all end
// strictly left of where the next one begins) is a vertical line that no edge of the row meets. Along such
// a line the winding number cannot change inside the row (it changes only across an edge), so it is one
// constant there. The winding number at a point is the sum of the directions of the edges crossing the
// horizontal line left of it; hence the edges left of the gap have a direction sum f(y) that is constant
// over the row's height — except where a horizontal edge, which the clipper dropped, crosses the gap line
// (it joins two chains at one height on either side of the gap, and the winding changes across it). A
// group is closed at a gap when its own direction sum is one constant c at every height of the row:
// then the winding number entering the next group is the one entering this group plus c, the same at
// every height, and each group's coverage is what a scan of its edges alone gives from that winding
// number on its left — the fill rule, the bands, the crossings all stay inside it. The direction sum is
// piecewise constant, changing only where an edge starts or ends inside the row, so "constant" is
// checked exactly: at every such height the starting directions cancel the ending ones (the joints of a
// contour do: two linked edges, or the two chains of a tip; a horizontal edge joining chains on either
// side of the gap does not, the check fails and the gap is not used).
//
// Cost: O(n) to order the extents as far as the gaps need (buckets by x_min, sorted only near a possible
// gap: sort_extents_where_gaps_may_be), O(n) for the gaps, and a
// sort of the group's chain tops and bottoms per check (joints cancel and are left out). A gap whose
// check fails is skipped (the group grows); after kMaxFailedChecks failures in a row the rest of the row
// is one group, so the checks never cost more than a few sorts of the row's events. Neighbouring groups
// without a chain top or bottom inside the row are then joined (RowGroupKind): only the groups with such
// tips gain from being scanned alone.
#include <algorithm>
#include <cmath>
#include <limits>

#include "band_sort.h"
#include "rasterizer_impl.h"

namespace curvescan::detail {

namespace {

/// Failed checks per row after which the rest of the row is left as one group.
constexpr int kMaxFailedChecks = 4;

/// Whether the edges of the group being built have one direction sum at every height of the row, given
/// `at_top`, the sum of the directions of its edges active at the row's top, and s.group_events, the
/// heights where its chains start (+dir) or end (-dir) inside the row, gathered as its extents were
/// walked (GroupExtent::flags: only a chain's top or bottom sends the walk to the edge itself).
///
/// A joint of a chain (an edge linked to the one below it, link_edges_into_chains) inside the row is an end
/// (-dir) and a start (+dir) at the same height, which cancel; both edges are in the group, since their
/// extents share the joint's x and a gap lies strictly between extents. So joints are left out, and only
/// the chains' own tops and bottoms (the contour's y-extrema, a few per group) are sorted and checked:
/// the sum at every height, and so the answer, is the one all the events give.
bool direction_sum_is_constant(ScanState& s, int at_top, int& sum) {
  std::sort(s.group_events.begin(), s.group_events.end(),
            [](const GroupEvent& a, const GroupEvent& b) { return a.y < b.y; });
  int change = 0;
  for (std::size_t k = 0; k < s.group_events.size(); ++k) {
    change += s.group_events[k].change;
    const bool height_ends = k + 1 == s.group_events.size() || s.group_events[k + 1].y != s.group_events[k].y;
    if (height_ends && change != 0) return false;
  }
  sum = at_top;
  return true;
}

/// Orders s.group_extents by x_min as far as the search for gaps needs: the extents are distributed into
/// buckets by x_min (a stable counting sort, about kExtentsPerBucket to a bucket where they are spread
/// evenly); a bucket whose every x_min lies at or left of the greatest x_max of the buckets before it can
/// hold no gap, nor have one before it, so its inner order does not matter and it is left unsorted; the
/// others are sorted. The walk over the result finds the gaps a full sort would give, at the same places,
/// and the groups hold the same edges. Cost O(n + buckets) plus the sorts of the buckets near a gap,
/// instead of O(n log n) for every row: a row of 3·10^5 mutually crossing edges has no gap at all.
void sort_extents_where_gaps_may_be(ScanState& s) {
  constexpr std::size_t kExtentsPerBucket = 4;
  std::vector<GroupExtent>& extents = s.group_extents;
  const std::size_t n = extents.size();
  double lo = INFINITY;
  double hi = -INFINITY;
  for (const GroupExtent& e : extents) {
    lo = std::min(lo, e.x_min);
    hi = std::max(hi, e.x_min);
  }
  const std::size_t buckets = std::max<std::size_t>(1, n / kExtentsPerBucket);
  const double per_unit = hi > lo ? static_cast<double>(buckets) / (hi - lo) : 0.0;
  const double last_bucket = static_cast<double>(buckets - 1);
  s.extent_bucket.resize(n);
  s.extent_bucket_start.assign(buckets + 1, 0);
  s.extent_bucket_x_max.assign(buckets, -INFINITY);
  s.extent_bucket_x_min_max.assign(buckets, -INFINITY);
  for (std::size_t p = 0; p < n; ++p) {
    // slice >= 0 (x_min >= lo), so the conversion's truncation is the floor; NaN (never here): bucket 0.
    const double slice = (extents[p].x_min - lo) * per_unit;
    const auto b = slice > 0.0 ? static_cast<std::uint32_t>(std::min(slice, last_bucket)) : 0u;
    s.extent_bucket[p] = b;
    ++s.extent_bucket_start[b + 1];
    s.extent_bucket_x_max[b] = std::max(s.extent_bucket_x_max[b], extents[p].x_max);
    s.extent_bucket_x_min_max[b] = std::max(s.extent_bucket_x_min_max[b], extents[p].x_min);
  }
  for (std::size_t b = 0; b < buckets; ++b) s.extent_bucket_start[b + 1] += s.extent_bucket_start[b];
  s.group_fill.assign(s.extent_bucket_start.begin(), s.extent_bucket_start.end() - 1);
  s.group_merged.resize(n);
  for (std::size_t p = 0; p < n; ++p) s.group_merged[s.group_fill[s.extent_bucket[p]]++] = extents[p];
  extents.swap(s.group_merged);
  std::uint64_t visited = 2 * n + buckets;
  double reach = -INFINITY;
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t first = s.extent_bucket_start[b];
    const std::size_t last = s.extent_bucket_start[b + 1];
    if (first == last) continue;
    if (!(s.extent_bucket_x_min_max[b] <= reach)) {
      visited += adaptive_sort(extents.data() + first, last - first,
                               [](const GroupExtent& a, const GroupExtent& c) { return a.x_min < c.x_min; });
    }
    reach = std::max(reach, s.extent_bucket_x_max[b]);
  }
  s.stats.pieces_visited += visited;
}

/// What a group's edges do inside the row, in the order of how much of the row scan's work they need.
/// Groups are worth scanning apart because a group's bands are cut only at its own chains' tops and
/// bottoms (the tips, essay step 6). A group without tips is one band whatever its neighbours are, so a
/// run of such neighbours is scanned as one group, with the same result: the row scan of a union of
/// groups separated by gaps visits each group's chains in the same order, and makes the same calls to the
/// row accumulator in the same order, as the scans of the groups one after the other — provided that the
/// groups take the same path of cover_row_group, hence the two kinds (kOneBand takes its fast path, the
/// others the chain path). Fewer groups: fewer calls, each with a fixed cost (its events, the chain
/// path's lists and sorts), which a wide stroke's or a dashed stroke's row makes by the dozen.
enum class RowGroupKind : std::uint8_t {
  kOneBand,  ///< every edge spans the whole row: no joint, no tip
  kJoints,   ///< some edge starts or ends inside the row, always at a joint of its chain
  kTips,     ///< some chain starts or ends inside the row
};

RowGroupKind row_group_kind(std::uint8_t flags) noexcept {
  if (flags & (kGroupEdgeChainTop | kGroupEdgeChainBottom)) return RowGroupKind::kTips;
  return flags & kGroupEdgeEndsInside ? RowGroupKind::kJoints : RowGroupKind::kOneBand;
}

}  // namespace

bool split_row_into_groups(ScanState& s, double ya, double yb, std::size_t first_new) {
  const ClippedEdge* edges = s.edges.data();
  const std::size_t n = s.active.size();
  s.group_extents.resize(n);
  GroupExtent* unsorted = s.group_extents.data();
  for (std::size_t p = 0; p < n; ++p) {
    const ClippedEdge& e = edges[s.active[p]];
    const double xa = e.x_at(ya);
    const double xb = e.x_at(yb);
    const bool starts = e.y_top > ya;
    const bool ends = e.y_bot < yb;
    const auto flags = static_cast<std::uint8_t>(
        (starts ? (e.linked_above ? kGroupEdgeEndsInside : kGroupEdgeChainTop | kGroupEdgeEndsInside)
                : kGroupEdgeAtTop) |
        (ends ? (e.below == ClippedEdge::kNoEdge ? kGroupEdgeChainBottom | kGroupEdgeEndsInside
                                                 : kGroupEdgeEndsInside)
              : 0));
    unsorted[p] = {std::min(xa, xb), std::max(xa, xb), static_cast<std::uint32_t>(p),
                   static_cast<std::int8_t>(e.dir), flags};
  }
  sort_extents_where_gaps_may_be(s);
  const std::vector<GroupExtent>& extents = s.group_extents;

  // Group of each active position, groups numbered left to right.
  s.group_of.resize(n);
  s.group_winding.clear();
  std::uint32_t groups = 0;
  std::size_t begin = 0;
  double reach = -std::numeric_limits<double>::infinity();
  int failed_checks = 0;
  int winding = 0;  // the winding number left of the group being built
  RowGroupKind last_kind = RowGroupKind::kTips;  // of the group before (none yet: joins nothing)
  // Of the group being built, gathered as its extents are walked (not again at each gap it is checked
  // at): the direction sum of its edges active at the row's top, its chains' tops and bottoms
  // (s.group_events), and its edges' flags together (its kind is that of the union of their flags: the
  // greatest of their kinds).
  int at_top = 0;
  std::uint8_t group_flags = 0;
  s.group_events.clear();
  for (std::size_t k = 0; k < n; ++k) {
    const GroupExtent& x = extents[k];
    reach = std::max(reach, x.x_max);
    group_flags |= x.flags;
    if (x.flags & kGroupEdgeAtTop) at_top += x.dir;
    if (x.flags & (kGroupEdgeChainTop | kGroupEdgeChainBottom)) {
      const ClippedEdge& e = edges[s.active[x.position]];
      if (x.flags & kGroupEdgeChainTop) s.group_events.push_back({e.y_top, x.dir});
      if (x.flags & kGroupEdgeChainBottom) s.group_events.push_back({e.y_bot, -x.dir});
    }
    const bool last = k + 1 == n;
    int sum = 0;
    if (!last) {
      if (!(reach < extents[k + 1].x_min) || failed_checks >= kMaxFailedChecks) continue;
      if (!direction_sum_is_constant(s, at_top, sum)) {
        ++failed_checks;
        continue;
      }
    }
    // Neighbouring groups of the same kind without tips are scanned as one (see RowGroupKind).
    const RowGroupKind kind = row_group_kind(group_flags);
    const bool joined = kind != RowGroupKind::kTips && kind == last_kind;
    const std::uint32_t group = joined ? groups - 1 : groups;
    for (std::size_t j = begin; j <= k; ++j) s.group_of[extents[j].position] = group;
    if (!joined) {
      s.group_winding.push_back(winding);
      ++groups;
    }
    winding += sum;
    last_kind = kind;
    begin = k + 1;
    failed_checks = 0;
    at_top = 0;
    group_flags = 0;
    s.group_events.clear();
  }
  if (groups < 2) return false;

  // The active list split by group (a stable counting sort, so each group keeps the row's order: its
  // edges carried from the row above first, in x order, then those starting in this row).
  s.group_offsets.assign(groups + 1, 0);
  s.group_carried.assign(groups, 0);
  for (std::size_t p = 0; p < n; ++p) {
    ++s.group_offsets[s.group_of[p] + 1];
    if (p < first_new) ++s.group_carried[s.group_of[p]];
  }
  for (std::uint32_t g = 0; g < groups; ++g) s.group_offsets[g + 1] += s.group_offsets[g];
  s.group_edges.resize(n);
  s.group_fill.assign(s.group_offsets.begin(), s.group_offsets.end() - 1);
  for (std::size_t p = 0; p < n; ++p) s.group_edges[s.group_fill[s.group_of[p]]++] = s.active[p];
  return true;
}

}  // namespace curvescan::detail
