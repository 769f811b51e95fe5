// Accumulate, then certify: a coverage mask from the plain signed-area accumulation of every edge, kept
// only where a cheap per-row test proves that accumulation exact (essay in rasterizer.cpp, step 11).
#pragma once

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "curvescan/raster/rasterizer.h"

namespace curvescan::detail {

struct ScanState;

/// One chain (edges linked end to end, a y-monotone polyline) inside one row of the box: its x extent
/// there (box columns, as accumulated), the heights where it enters and leaves the row, its direction,
/// and its edge at y0 (for the pair test).
struct CertifyItem {
  double x_min = 0.0;
  double x_max = 0.0;
  double y0 = 0.0;
  double y1 = 0.0;
  std::uint32_t edge = 0;
  int row = 0;  ///< box row, 0 = the box's top
  int dir = 0;
};

/// The scratch of accumulate_certified_dense, kept between fills.
struct CertifyScratch {
  std::vector<CertifyItem> items;             // in the order the chains were walked
  std::vector<CertifyItem> by_row;            // the same, grouped by row
  std::vector<std::uint32_t> row_start;       // where each row's items start in by_row
  std::vector<std::pair<double, int>> steps;  // the winding left of a gap, as steps in y inside the row
};

/// Accumulates every edge of s (linked: link_contour_edges) with its direction into s.dense over `box`
/// (the clip box; DenseCoverage::fits it) and tests, row by row, that the winding number takes only the
/// values 0 and one sign s = ±1 inside the box. Then the accumulation is s times the exact coverage under
/// either fill rule: writes `mask` and returns true. Otherwise clears the cells and returns false, having
/// written nothing (the caller takes the exact path).
bool accumulate_certified_dense(ScanState& s, IntRect box, std::span<std::uint8_t> mask);

}  // namespace curvescan::detail
