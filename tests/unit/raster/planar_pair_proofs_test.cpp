// The general sweep's neighbour checks (raster/scan/rasterizer_planar.cpp) for two long chains parted
// again and again by short ones between them, a wide stroke's shape: its two sides, with a round join's
// piece between them here and there. A pair a walk of joints found in order is remembered
// (PlanarChain::proven_right), so the two sides are walked once, not again after each short chain.
// Counts, not times: ScanState::planar_pairs_walked.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdint>
#include <cstdlib>
#include <span>
#include <vector>

#include "coverage_mask.h"
#include "curvescan/raster/rasterizer.h"
#include "scan/edge_clip.h"
#include "scan/rasterizer_impl.h"

using namespace curvescan;
using namespace curvescan::detail;

namespace {

constexpr int kDiamonds = 9;
constexpr IntRect kClip{0, 0, 20, 220};

/// A band 210 px tall whose two sides zigzag by 0.5 px at every pixel height (many joints to walk), with
/// `kDiamonds` small diamonds between them one below the other. The sides' x extents overlap the
/// diamonds' (the left side swings right below the last diamond, the right side left above the first),
/// so no pair is settled by its extents alone and every new pair of neighbours is walked.
std::vector<std::vector<Point>> band_with_diamonds() {
  std::vector<Point> band;
  for (int y = 0; y <= 210; ++y) band.push_back({y >= 195 ? 8.0 : 1.0 + 0.5 * (y % 2), double(y)});
  for (int y = 210; y >= 0; --y) band.push_back({y < 5 ? 3.0 : 11.0 + 0.5 * (y % 2), double(y)});
  std::vector<std::vector<Point>> shape{band};
  for (int k = 0; k < kDiamonds; ++k) {
    const double top = 10.0 + 20.0 * k;
    shape.push_back({{5.0, top}, {5.5, top + 5.0}, {5.0, top + 10.0}, {4.5, top + 5.0}});
  }
  return shape;
}

}  // namespace

TEST_CASE("a band's two sides parted by short chains are walked once", "[raster][planar]") {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    ScanState s;
    s.clip = kClip;
    for (const std::vector<Point>& contour : band_with_diamonds()) {
      for (std::size_t i = 0; i < contour.size(); ++i) {
        clip_edge(contour[i], contour[(i + 1) % contour.size()], kClip, s.edges);
      }
    }
    link_edges_into_chains(s);
    REQUIRE(s.planar_chains.size() == 2 + 2 * kDiamonds);
    REQUIRE(sweep_planar_chains(s, rule));
    // The band's sides at the top, then per diamond its left side against the band's left and its right
    // side against the band's right (a diamond's own two sides are apart by their extents). The band's
    // sides meet again below every diamond: walked again each time, that was 1 + 3 * 9 = 28.
    CHECK(s.planar_pairs_walked == 1 + 2 * kDiamonds);
  }
}

TEST_CASE("a band parted by short chains is drawn as the reference draws it", "[raster][planar]") {
  // The same shape through the rasterizer and its plain reference: the same coverage (at most one step
  // of 255, the same area summed in another order).
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const testing::ReferenceComparison result =
        testing::compare_with_reference(band_with_diamonds(), kClip.x1, kClip.y1, rule);
    CHECK(result.stats.planar_fills == 1);
    CHECK(result.violations == 0);
    CHECK(result.max_diff <= 1);
  }
}
