// Accumulate, then certify (essay in rasterizer.cpp, step 11; the argument is there).
//
// Every edge is accumulated with its direction, as FreeType and font-rs do: each cell then holds the
// integral of the winding number over the pixel. That is the exact coverage wherever the winding number
// takes only the values 0 and s for one sign s, under either fill rule. The same walk records each chain's
// x extent in each row; a row passes when its chains, grouped by overlapping extents, leave a winding number
// of 0 or s in every gap between groups and inside every group. A fill where some row does not pass is
// cleared and handed to the planar proof and the row scan, which resolve overlaps exactly.
#include "dense_certify.h"

#include <algorithm>
#include <array>

#include "rasterizer_impl.h"

namespace curvescan::detail {

namespace {

/// The most items of one cluster tested pair by pair (quadratic in them); a larger cluster fails the test.
/// A glyph's clusters hold one item, or the two chains of a contour's tip, or a few close chains.
constexpr std::size_t kMaxClusterItems = 16;

/// The order of chains a and b over the heights [lo, hi] both hold in the row (lo < hi): -1 when a is at or
/// left of b at every joint height of either (their difference is linear in between, so everywhere), +1
/// when b is at or left of a, 0 when they cross or coincide.
int pair_order(const ClippedEdge* edges, const CertifyItem& a, const CertifyItem& b) {
  const double hi = std::min(a.y1, b.y1);
  std::uint32_t ea = a.edge;
  std::uint32_t eb = b.edge;
  int order = 0;
  double y = std::max(a.y0, b.y0);
  while (true) {
    // The edges holding y (at a joint both neighbours give the joint's x; a chain's last edge is clamped).
    while (edges[ea].y_bot <= y && edges[ea].below != ClippedEdge::kNoEdge) ea = edges[ea].below;
    while (edges[eb].y_bot <= y && edges[eb].below != ClippedEdge::kNoEdge) eb = edges[eb].below;
    const double d = edges[ea].x_at(y) - edges[eb].x_at(y);
    if (d != 0.0) {
      const int side = d < 0.0 ? -1 : 1;
      if (order == 0) {
        order = side;
      } else if (order != side) {
        return 0;
      }
    }
    if (y >= hi) return order;
    // Both chains go on below y inside [lo, hi] (hi is at most each one's bottom), so y increases.
    y = std::min(hi, std::min(edges[ea].y_bot, edges[eb].y_bot));
  }
}

/// Whether items p and q both hold some height of the row (a set of positive height).
bool overlap(const CertifyItem& p, const CertifyItem& q) noexcept {
  return std::max(p.y0, q.y0) < std::min(p.y1, q.y1);
}

/// The sign the certified winding numbers share (0 until a non-zero one is met).
class WindingSign {
 public:
  /// Whether winding number v is 0 or the shared sign (which v fixes if it is the first ±1 met).
  bool admits(int v) noexcept {
    if (v == 0) return true;
    if (sign_ == 0 && (v == 1 || v == -1)) sign_ = v;
    return v == sign_;
  }
  [[nodiscard]] int sign() const noexcept { return sign_; }

 private:
  int sign_ = 0;
};

/// x of the chain whose edge at or above height y is `e` (y inside the chain's heights).
double chain_x(const ClippedEdge* edges, std::uint32_t e, double y) noexcept {
  while (edges[e].y_bot < y && edges[e].below != ClippedEdge::kNoEdge) e = edges[e].below;
  return edges[e].x_at(y);
}

/// The winding number of the gap left of a cluster at height y: g_base plus the steps at or above y.
int gap_winding_at(int g_base, const std::vector<std::pair<double, int>>& steps, double y) noexcept {
  int g = g_base;
  for (const auto& [height, change] : steps) {
    if (height > y) break;
    g += change;
  }
  return g;
}

/// A cluster of k >= 2 items (overlapping x extents), with the gap on its left given by g_base and
/// `steps` (gap_values). Where at most one item holds a height, the winding number inside the cluster is
/// the gap's on its left or on its right there, both tested by the caller. Where two or more hold a height,
/// no two of them may cross (pair_order, over the heights both hold), so at each height their x order is
/// the order at the middle of the sub-band between consecutive item ends holding it; the winding between
/// consecutive items there, the left gap's plus the directions of the items on the left, must be 0 or the
/// sign.
bool certify_cluster(const ClippedEdge* edges, const CertifyItem* items, std::size_t k, int g_base,
                     const std::vector<std::pair<double, int>>& steps, WindingSign& sign) {
  if (k > kMaxClusterItems) return false;
  bool stacked = false;
  for (std::size_t p = 0; p < k; ++p) {
    for (std::size_t q = p + 1; q < k; ++q) {
      if (!overlap(items[p], items[q])) continue;
      if (pair_order(edges, items[p], items[q]) == 0) return false;
      stacked = true;
    }
  }
  if (!stacked) return true;
  std::array<double, 2 * kMaxClusterItems> heights;  // NOLINT: written before read
  std::size_t height_count = 0;
  for (std::size_t p = 0; p < k; ++p) {
    heights[height_count++] = items[p].y0;
    heights[height_count++] = items[p].y1;
  }
  std::sort(heights.begin(), heights.begin() + static_cast<std::ptrdiff_t>(height_count));
  std::array<std::pair<double, int>, kMaxClusterItems> present;  // (x at the middle, direction)
  for (std::size_t h = 0; h + 1 < height_count; ++h) {
    if (!(heights[h] < heights[h + 1])) continue;
    const double middle = 0.5 * (heights[h] + heights[h + 1]);
    std::size_t count = 0;
    for (std::size_t p = 0; p < k; ++p) {
      if (items[p].y0 < middle && middle < items[p].y1) {
        present[count++] = {chain_x(edges, items[p].edge, middle), items[p].dir};
      }
    }
    if (count < 2) continue;
    std::sort(present.begin(), present.begin() + static_cast<std::ptrdiff_t>(count));
    int winding = gap_winding_at(g_base, steps, middle);
    for (std::size_t p = 0; p < count; ++p) {
      winding += present[p].second;
      if (!sign.admits(winding)) return false;
    }
  }
  return true;
}

/// The winding number G(y) in the gap right of the clusters seen so far, a step function of the height
/// inside the row: g_base just below the row's top, then `steps` (height, change). Sorts and merges the
/// steps, drops those that cancel, and tests every value.
bool gap_values(int g_base, std::vector<std::pair<double, int>>& steps, WindingSign& sign) {
  if (!sign.admits(g_base)) return false;
  if (steps.empty()) return true;
  std::sort(steps.begin(), steps.end());
  std::size_t kept = 0;
  int g = g_base;
  for (std::size_t i = 0; i < steps.size();) {
    const double y = steps[i].first;
    int change = 0;
    for (; i < steps.size() && steps[i].first == y; ++i) change += steps[i].second;
    if (change == 0) continue;  // a tip, a chain handing over to the next at one point
    steps[kept++] = {y, change};
    g += change;
    if (!sign.admits(g)) return false;
  }
  steps.resize(kept);
  return true;
}

}  // namespace

bool accumulate_certified_dense(ScanState& s, IntRect box, std::span<std::uint8_t> mask) {
  const ClippedEdge* edges = s.edges.data();
  const auto count = static_cast<std::uint32_t>(s.edges.size());
  const int height = box.y1 - box.y0;
  DenseCoverage& dense = s.dense;
  dense.reset(box.x0, box.y0, box.x1 - box.x0, height);
  CertifyScratch& scratch = s.certify;
  std::vector<CertifyItem>& items = scratch.items;
  items.clear();

  // Every chain, every edge, with its direction; each row piece extends its chain's item of that row.
  for (std::uint32_t head = 0; head < count; ++head) {
    if (edges[head].linked_above) continue;
    const std::size_t chain_first = items.size();
    for (std::uint32_t e = head; e != ClippedEdge::kNoEdge; e = edges[e].below) {
      const ClippedEdge& edge = edges[e];
      dense.add_edge(
          edge.x_top, edge.y_top, edge.x_bot, edge.y_bot, edge.dxdy, edge.y_top, edge.y_bot,
          static_cast<double>(edge.dir),
          [&](int row, double ua, double ub, double ya, double yb) __attribute__((always_inline)) {
            const double lo = ua < ub ? ua : ub;
            const double hi = ua < ub ? ub : ua;
            if (items.size() > chain_first && items.back().row == row) {
              CertifyItem& item = items.back();
              item.x_min = std::min(item.x_min, lo);
              item.x_max = std::max(item.x_max, hi);
              item.y1 = yb;
            } else {
              items.push_back({lo, hi, ya, yb, e, row, edge.dir});
            }
          });
    }
  }

  // Grouped by row (a counting sort): afterwards row_start[r] is where row r + 1 starts.
  std::vector<std::uint32_t>& row_start = scratch.row_start;
  row_start.assign(static_cast<std::size_t>(height) + 1, 0);
  for (const CertifyItem& item : items) ++row_start[static_cast<std::size_t>(item.row) + 1];
  for (std::size_t r = 1; r < row_start.size(); ++r) row_start[r] += row_start[r - 1];
  std::vector<CertifyItem>& by_row = scratch.by_row;
  by_row.resize(items.size());
  for (const CertifyItem& item : items) by_row[row_start[static_cast<std::size_t>(item.row)]++] = item;

  WindingSign sign;
  std::vector<std::pair<double, int>>& steps = scratch.steps;
  bool certified = true;
  for (int r = 0; r < height && certified; ++r) {
    const std::uint32_t begin = r == 0 ? 0 : row_start[static_cast<std::size_t>(r) - 1];
    const std::uint32_t end = row_start[static_cast<std::size_t>(r)];
    CertifyItem* row = by_row.data() + begin;
    const std::size_t m = end - begin;
    // By the left end of the extent: an insertion sort, a glyph's row holds a handful of chains.
    for (std::size_t i = 1; i < m; ++i) {
      const CertifyItem item = row[i];
      std::size_t j = i;
      for (; j > 0 && row[j - 1].x_min > item.x_min; --j) row[j] = row[j - 1];
      row[j] = item;
    }
    const double top = static_cast<double>(box.y0 + r);
    const double bottom = top + 1.0;
    int g_base = 0;  // the gap's winding number just below the row's top (0 left of everything)
    steps.clear();
    for (std::size_t i = 0; i < m && certified;) {
      // The cluster: items whose extents overlap or touch, one after another.
      std::size_t j = i + 1;
      double reach = row[i].x_max;
      for (; j < m && row[j].x_min <= reach; ++j) reach = std::max(reach, row[j].x_max);
      if (j - i > 1 && !certify_cluster(edges, row + i, j - i, g_base, steps, sign)) {
        certified = false;
        break;
      }
      for (std::size_t k = i; k < j; ++k) {
        const CertifyItem& item = row[k];
        if (item.y0 == top) {
          g_base += item.dir;
        } else {
          steps.push_back({item.y0, item.dir});
        }
        if (item.y1 < bottom) steps.push_back({item.y1, -item.dir});
      }
      certified = gap_values(g_base, steps, sign);
      i = j;
    }
  }
  if (!certified) {
    dense.clear();
    return false;
  }
  dense.write_mask(mask, sign.sign() < 0);
  return true;
}

}  // namespace curvescan::detail
