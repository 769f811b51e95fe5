// Independent groups of a row (raster/scan/rasterizer_row_groups.cpp, essay step 9): a row of many edges is
// scanned group by group where vertical gaps with a zero direction sum on their left cut it. Held to the
// plain reference scan (rasterize_reference) on scenes that reach the split's corners: rows of hundreds
// of small separate shapes (dashes), shapes crossing each other inside a group, a wide rectangle whose top
// edge (dropped by the clipper as horizontal) joins two chains across the gaps between dashes, holes and
// opposite orientations, shapes cut by the clip's left side, dashes inside a rectangle (groups entered
// with a winding number of 1 or -1); and random rows of small polygons, alone or over a rectangle. And held
// to the work it exists to save: a row of 300 dashes visits a few pieces per dash, not dashes × tips.
//
// Metric: the same exact area summed in another order, so an area within ~1e-12 of a rounding midpoint
// may round either way: at most 1 step of 255 per pixel (as in rasterizer_planar_test.cpp). The random
// scenes are not planar (shapes overlap), so they take the row scan that the groups are part of.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "coverage_mask.h"
#include "polygon_scenes.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr int kWidth = 640;
constexpr int kHeight = 24;

// Both fills of `shape` on the test's canvas (coverage_mask.h).
ReferenceComparison compare_with_reference(const Shape& shape, FillRule rule) {
  return testing::compare_with_reference(shape, kWidth, kHeight, rule);
}

/// A dash: a thin quadrilateral from (x, y) along angle `a`, length `length`, width `width`.
Contour dash(double x, double y, double a, double length, double width) {
  const double dx = std::cos(a) * length, dy = std::sin(a) * length;
  const double nx = -std::sin(a) * width / 2, ny = std::cos(a) * width / 2;
  return {{x + nx, y + ny}, {x + dx + nx, y + dy + ny}, {x + dx - nx, y + dy - ny}, {x - nx, y - ny}};
}

/// A row of `count` dashes along y = 12, each tilted, with both ends inside the row's pixels.
Shape dash_row(int count, double pitch, double tilt) {
  Shape shape;
  for (int i = 0; i < count; ++i)
    shape.push_back(dash(2.0 + i * pitch, 11.2 + 0.3 * (i % 3), tilt, 0.6 * pitch, 0.7));
  return shape;
}

/// Under both rules: `shape` takes the row scan (not planar), exactly (no sampled row or band) and within
/// 1 step of the reference.
void check_row_scan_exact(const Shape& shape) {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const ReferenceComparison run = compare_with_reference(shape, rule);
    CHECK(run.stats.planar_fills == 0);
    CHECK(run.max_diff <= 1);
    CHECK(run.violations == 0);
    CHECK(run.stats.sampled_rows == 0);
    CHECK(run.stats.sampled_bands == 0);
  }
}

}  // namespace

TEST_CASE("a row of separate dashes is scanned dash by dash and exactly", "[oracle][groups]") {
  // Separate dashes alone are planar (the planar path takes them); two crossing dashes at the row's end
  // send the fill to the row scan, where the row splits into groups.
  Shape dashes = dash_row(300, 2.1, 0.4);
  dashes.push_back(dash(632.0, 10.5, 0.6, 5.0, 0.8));
  dashes.push_back(dash(632.0, 13.5, -0.6, 5.0, 0.8));
  check_row_scan_exact(dashes);
}

TEST_CASE("rows of dashes crossed by long bars: exact — separate dashes cost per dash", "[oracle][groups]") {
  // 300 dashes plus two long thin bars crossing the whole row: not planar (the bars cross the dashes), so
  // the row scan runs. The bars join everything into one group where they are; the rest splits per dash.
  Shape shape = dash_row(300, 2.1, 0.4);
  shape.push_back(dash(0.5, 3.0, 0.025, 630.0, 1.5));
  shape.push_back(dash(0.5, 20.0, -0.025, 630.0, 1.5));
  check_row_scan_exact(shape);
  // The work: without groups, each pixel row of a row of 300 dashes is cut into ~600 bands that each
  // look at all ~600 chains of the row (~360k visits per row); split, each dash is its own group of a few
  // bands and chains. Two crossing dashes at the end make the fill non-planar (the row scan runs). The
  // bound, 100 visits per edge of the whole fill (1208 edges), is far below one unsplit row.
  Shape crossed_dashes = dash_row(300, 2.1, 0.4);
  crossed_dashes.push_back(dash(632.0, 10.5, 0.6, 5.0, 0.8));
  crossed_dashes.push_back(dash(632.0, 13.5, -0.6, 5.0, 0.8));
  const ReferenceComparison run = compare_with_reference(crossed_dashes, FillRule::kNonZero);
  CHECK(run.max_diff <= 1);
  CHECK(run.stats.planar_fills == 0);
  CHECK(run.stats.pieces_visited < 100 * 1208);
  CHECK(run.stats.sampled_rows == 0);
  CHECK(run.stats.sampled_bands == 0);
}

TEST_CASE("dashes inside a filled rectangle are scanned dash by dash: the gaps' winding is not zero",
          "[oracle][groups]") {
  // The dashes of the test above inside a rectangle that spans their rows (and its reverse, a hole): the
  // winding number between the dashes is 1 (-1), the same at every height of a row, so the rows still
  // split into one group per dash, each scanned from that winding number. Without it, each pixel row would
  // be one group of ~600 chains cut into ~600 bands (~360k visits per row, as above). Bound: 100 visits
  // per edge of the whole fill (1212 edges), as above.
  for (const bool hole : {false, true}) {
    Shape shape = dash_row(300, 2.1, 0.4);
    shape.push_back(dash(632.0, 10.5, 0.6, 5.0, 0.8));
    shape.push_back(dash(632.0, 13.5, -0.6, 5.0, 0.8));
    const Contour rectangle{{0.5, 1.25}, {639.5, 1.25}, {639.5, 22.75}, {0.5, 22.75}};
    shape.push_back(hole ? reversed(rectangle) : rectangle);
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      const ReferenceComparison run = compare_with_reference(shape, rule);
      INFO((hole ? "reversed rectangle, " : "rectangle, ")
           << (rule == FillRule::kNonZero ? "nonzero" : "even-odd") << ", pieces visited "
           << run.stats.pieces_visited);
      CHECK(run.max_diff <= 1);
      CHECK(run.violations == 0);
      CHECK(run.stats.planar_fills == 0);
      CHECK(run.stats.pieces_visited < 100 * 1212);
      CHECK(run.stats.sampled_rows == 0);
      CHECK(run.stats.sampled_bands == 0);
    }
  }
}

TEST_CASE("a horizontal edge joining chains across gaps keeps the row exact", "[oracle][groups]") {
  // A wide rectangle whose top and bottom edges lie inside pixel rows that also hold dashes: its left and
  // right sides start (end) at the same height far apart, joined by a horizontal edge the clipper drops;
  // gaps between them have a non-zero direction sum on their left for part of the row and must not split.
  // Dashes inside it, a hole of the opposite orientation holding dashes, and shapes cut by the clip's
  // left side complete the scene.
  Shape shape = dash_row(250, 2.5, -0.3);
  shape.push_back({{1.5, 10.4}, {630.5, 10.4}, {630.5, 13.6}, {1.5, 13.6}});
  shape.push_back(reversed({{100.2, 10.9}, {300.7, 10.9}, {300.7, 13.1}, {100.2, 13.1}}));
  shape.push_back(dash(-5.0, 11.5, 0.2, 9.0, 0.8));
  shape.push_back(dash(-7.0, 12.5, -0.1, 8.0, 0.5));
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const ReferenceComparison run = compare_with_reference(shape, rule);
    CHECK(run.max_diff <= 1);
    CHECK(run.violations == 0);
  }
}

TEST_CASE("random rows of small polygons match the reference scan", "[oracle][groups]") {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> x(0.0, 630.0), y(2.0, 22.0), size(0.3, 6.0);
  std::uniform_int_distribution<int> vertices(3, 7), shapes(40, 160), coin(0, 3);
  for (int trial = 0; trial < 40; ++trial) {
    Shape shape;
    const int count = shapes(rng);
    for (int i = 0; i < count; ++i) {
      const double cx = x(rng), cy = y(rng), r = size(rng);
      // Small convex polygons of either orientation and small self-crossing ones, overlapping at random.
      Contour c = coin(rng) == 0 ? random_polygon(rng, cx - r, cy - r, cx + r, cy + r, vertices(rng))
                                 : regular_polygon({cx, cy}, r, 0.5 * r, vertices(rng), cx);
      shape.push_back(coin(rng) == 1 ? reversed(c) : c);
    }
    // Every third scene over a rectangle (either orientation) across the rows: the gaps between groups
    // then have a winding number of 1 or -1 instead of 0.
    if (trial % 3 == 1) shape.push_back({{0.5, 1.5}, {639.5, 1.5}, {639.5, 22.5}, {0.5, 22.5}});
    if (trial % 3 == 2) shape.push_back({{0.5, 1.5}, {0.5, 22.5}, {639.5, 22.5}, {639.5, 1.5}});
    const FillRule rule = trial % 2 == 0 ? FillRule::kNonZero : FillRule::kEvenOdd;
    INFO("trial " << trial);
    const ReferenceComparison run = compare_with_reference(shape, rule);
    CHECK(run.max_diff <= 1);
    CHECK(run.violations == 0);
  }
}
