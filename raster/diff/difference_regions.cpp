// Difference regions: clusters of differing pixels, the boxes of the HTML report (contract in
// image_diff.h, find_difference_regions).
//
// Two differing pixels p and q are linked when their Chebyshev distance max(|dx|, |dy|) is at most
// g + 1, g the region gap; a region is a connected component of that relation. Testing every pair of
// pixels within that distance costs (2g + 3)² per pixel. Instead each differing pixel is grown into the
// (g + 1) × (g + 1) square it anchors at its top-left corner (a morphological dilation with a square
// structuring element, separable into a row pass and a column pass of running counts, so linear in the
// pixels whatever g), and the 8-connected components of the grown mask are the regions:
// - two squares anchored at p and q touch or overlap (8-adjacent cells) exactly when |dx| ≤ g + 1 and
//   |dy| ≤ g + 1, so the components join the pixels the relation links and no others;
// - clipping the squares at the right and bottom edges of the image loses no link: the two touching cells
//   lie at columns and rows no greater than those of the lower-right pixel, inside the image;
// - every grown cell belongs to the square of some differing pixel, so every component holds one.
// The components are found by a breadth-first search that clears each cell of the grown mask as it is
// queued (the mask is its own visited set), so the extra memory is the grown mask and the frontier.
// The statistics of a region (box, pixel count, largest channel delta) are gathered from the original
// pixels only, so the grown cells never widen a box.
#include <algorithm>
#include <deque>
#include <queue>

#include "curvescan/diff/image_diff.h"

namespace curvescan {
namespace {

/// The grown mask: cell (x, y) is 1 when some differing pixel lies in [x − g, x] × [y − g, y].
std::vector<std::uint8_t> grow_mask(const std::vector<std::uint8_t>& deltas, int width, int height, int gap) {
  const auto w = static_cast<std::size_t>(width);
  std::vector<std::uint8_t> grown(deltas.size(), 0);
  // Row pass: cell x covered when a differing pixel lies in [x − g, x] of the same row.
  for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
    const std::uint8_t* in = deltas.data() + y * w;
    std::uint8_t* out = grown.data() + y * w;
    int in_window = 0;
    for (std::size_t x = 0; x < w; ++x) {
      in_window += in[x] != 0 ? 1 : 0;
      if (x >= static_cast<std::size_t>(gap) + 1 && in[x - static_cast<std::size_t>(gap) - 1] != 0)
        --in_window;
      out[x] = in_window > 0 ? 1 : 0;
    }
  }
  if (gap == 0) return grown;
  // Column pass, in place: the running count of each column needs the row pass's value of the row leaving
  // the window, which the pass has overwritten by then, so the last g + 1 rows of the row pass are kept
  // in a ring.
  const auto ring_rows = static_cast<std::size_t>(gap) + 1;
  std::vector<std::uint8_t> ring(ring_rows * w, 0);
  std::vector<int> in_window(w, 0);
  for (std::size_t y = 0; y < static_cast<std::size_t>(height); ++y) {
    std::uint8_t* row = grown.data() + y * w;
    std::uint8_t* slot = ring.data() + (y % ring_rows) * w;  // the row g + 1 above, about to be replaced
    for (std::size_t x = 0; x < w; ++x) {
      if (y >= ring_rows) in_window[x] -= slot[x];
      slot[x] = row[x];
      in_window[x] += row[x];
      row[x] = in_window[x] > 0 ? 1 : 0;
    }
  }
  return grown;
}

/// Listing order: most pixels first, then top to bottom, then left to right.
bool listed_before(const DifferenceRegion& a, const DifferenceRegion& b) noexcept {
  if (a.pixels != b.pixels) return a.pixels > b.pixels;
  if (a.box.y != b.box.y) return a.box.y < b.box.y;
  return a.box.x < b.box.x;
}

}  // namespace

std::vector<DifferenceRegion> find_difference_regions(const std::vector<std::uint8_t>& deltas, int width,
                                                      int height, int region_gap, std::size_t max_regions,
                                                      std::uint64_t& region_count) {
  region_count = 0;
  if (width <= 0 || height <= 0 ||
      deltas.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    return {};
  }
  const int gap = std::clamp(region_gap, 0, 64);
  std::vector<std::uint8_t> grown = grow_mask(deltas, width, height, gap);
  const auto w = static_cast<std::size_t>(width);

  // The listed regions: a heap whose top is the region listed last, so that a better one replaces it.
  std::priority_queue<DifferenceRegion, std::vector<DifferenceRegion>, decltype(&listed_before)> kept(
      &listed_before);
  std::deque<std::size_t> frontier;
  for (std::size_t start = 0; start < grown.size(); ++start) {
    if (grown[start] == 0) continue;
    ++region_count;
    int min_x = width, min_y = height, max_x = -1, max_y = -1;
    DifferenceRegion region;
    grown[start] = 0;
    frontier.push_back(start);
    while (!frontier.empty()) {
      const std::size_t cell = frontier.front();
      frontier.pop_front();
      const int x = static_cast<int>(cell % w), y = static_cast<int>(cell / w);
      if (const std::uint8_t delta = deltas[cell]; delta != 0) {
        ++region.pixels;
        region.max_channel_delta = std::max<int>(region.max_channel_delta, delta);
        min_x = std::min(min_x, x);
        max_x = std::max(max_x, x);
        min_y = std::min(min_y, y);
        max_y = std::max(max_y, y);
      }
      for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, height - 1); ++ny) {
        for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, width - 1); ++nx) {
          const std::size_t next = static_cast<std::size_t>(ny) * w + static_cast<std::size_t>(nx);
          if (grown[next] == 0) continue;
          grown[next] = 0;
          frontier.push_back(next);
        }
      }
    }
    region.box = {min_x, min_y, max_x - min_x + 1, max_y - min_y + 1};
    if (max_regions == 0) continue;
    if (kept.size() < max_regions) {
      kept.push(region);
    } else if (listed_before(region, kept.top())) {
      kept.pop();
      kept.push(region);
    }
  }
  std::vector<DifferenceRegion> listed;
  listed.reserve(kept.size());
  for (; !kept.empty(); kept.pop()) listed.push_back(kept.top());
  std::reverse(listed.begin(), listed.end());
  return listed;
}

}  // namespace curvescan
