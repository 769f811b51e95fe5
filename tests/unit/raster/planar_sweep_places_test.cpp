// The general sweep's work on the x order (raster/scan/rasterizer_planar.cpp) for a row of many small
// contours open at once, a dashed stroke's shape: each contour's top tip starts its two chains at one
// point, the second placed beside the first without a binary search (place_beside), and a chain that ends
// is found near its last numbered place rather than by numbering every open chain right of the first
// change again. Counts, not times: ScanState::planar_places_searched and planar_places_numbered.
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

/// `columns` x `rows` dash-like contours (convex octagons 2 px wide and 10 px tall, 1 px apart in a
/// row), the tops of a row staggered over 14.4 px (no two alike) so that two or three rows' contours are open
/// at every height: two chains each, from the top tip to the bottom tip.
std::vector<std::vector<Point>> rows_of_dashes(int columns, int rows) {
  std::vector<std::vector<Point>> shape;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < columns; ++c) {
      const double x = 2.0 + 3.0 * c;
      const double top = 1.0 + 12.0 * r + 0.37 * ((c * 7) % 40);
      shape.push_back({{x + 1.0, top},
                       {x + 1.8, top + 2.5},
                       {x + 2.0, top + 5.0},
                       {x + 1.8, top + 7.5},
                       {x + 1.0, top + 10.0},
                       {x + 0.2, top + 7.5},
                       {x, top + 5.0},
                       {x + 0.2, top + 2.5}});
    }
  }
  return shape;
}

constexpr int kColumns = 40;
constexpr int kRows = 10;
constexpr IntRect kClip{0, 0, 3 * kColumns + 8, 12 * kRows + 12};

void load(ScanState& s, const std::vector<std::vector<Point>>& shape, IntRect clip) {
  s.clip = clip;
  s.edges.clear();
  for (const std::vector<Point>& contour : shape) {
    for (std::size_t i = 0; i < contour.size(); ++i) {
      clip_edge(contour[i], contour[(i + 1) % contour.size()], clip, s.edges);
    }
  }
  link_edges_into_chains(s);
}

}  // namespace

TEST_CASE("a row of dashes: one binary search per contour, few places numbered", "[raster][planar]") {
  constexpr int kDashes = kColumns * kRows;
  const IntRect clip = kClip;
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    ScanState s;
    load(s, rows_of_dashes(kColumns, kRows), clip);
    REQUIRE(s.planar_chains.size() == 2 * kDashes);
    REQUIRE(sweep_planar_chains(s, rule));
    // Every dash is a boundary: its two sides, one piece each.
    CHECK(s.planar_pieces.size() == 2 * kDashes);
    // The first side of each dash is placed by a binary search, the second beside it (each of the 800
    // chains was searched for before).
    CHECK(s.planar_places_searched == kDashes);
    // Numbering every open chain right of the first change at each event (the chains that end are looked
    // up by their numbered places) numbered 10,430 places here; found near their last numbered places, the
    // chains that end need the numbering rarely: 1,258 places, bounded here by about twice that (the
    // count depends only on the order of the events, so it does not move unless the lookup does).
    CHECK(s.planar_places_numbered <= 2500);
  }
}

TEST_CASE("a row of dashes is drawn as the reference draws it", "[raster][planar]") {
  // The same dashes through the rasterizer and its plain reference: the same coverage (at most one
  // step of 255, the same area summed in another order).
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const testing::ReferenceComparison result =
        testing::compare_with_reference(rows_of_dashes(kColumns, kRows), kClip.x1, kClip.y1, rule);
    CHECK(result.stats.planar_fills == 1);
    CHECK(result.violations == 0);
    CHECK(result.max_diff <= 1);
  }
}
