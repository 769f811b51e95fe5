// The events of the whole-fill sweep (raster/scan/rasterizer_planar.cpp): an event touches only the chains
// that end or start at it. The chains that end are taken from the chains sorted by bottom once more than
// a few are open, their places in the x order are read from a numbering kept exact left of the first
// place changed since, the gaps they leave are closed in one pass, and the windings are recomputed from
// each changed place only until the winding number left of a chain is the one it had. Each of these has
// its own ways to go wrong, held here to the plain reference scan (rasterize_reference) under both fill
// rules: many chains open at once (with and without crossings among them, holes that cancel the windings
// and contours that do not), chains that end where others start at the same height (at the same point and
// elsewhere on the line), and coincident chains (one contour drawn many times, shared edges).
//
// Metric: as in rasterizer_sweep_crossings_test.cpp, the same exact area summed in another order, so an
// area within ~1e-12 of a rounding midpoint may round either way: at most 1 step of 255 per pixel.
#include <catch2/catch.hpp>
#include <random>
#include <string>
#include <vector>

#include "coverage_mask.h"
#include "polygon_scenes.h"
#include "sweep_checks.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

/// `count` small polygons (`sides` sides, radius r) in a row across the clip, their centres `step` apart
/// and at heights that go up and down, so that nearly all of them are open at once, every second one
/// reversed when `holes` (their windings cancel the ones beside them).
Shape row_of_polygons(int count, double step, double r, int sides, bool holes) {
  Shape shape;
  for (int i = 0; i < count; ++i) {
    const Point centre{4.0 + r + step * i, 12.0 + 1.7 * (i % 5) + 0.37 * (i % 3)};
    shape.push_back(regular_polygon(centre, r, r * 1.3, sides, 0.1 * i, holes && i % 2 == 1));
  }
  return shape;
}

}  // namespace

TEST_CASE("the sweep keeps many chains open at once", "[oracle][sweep]") {
  const IntRect clip{0, 0, 512, 32};
  SECTION("apart: 120 polygons, 240 chains open") {
    check_swept(row_of_polygons(120, 4.2, 1.6, 24, false), clip);
  }
  SECTION("apart, every second one reversed") {
    check_swept(row_of_polygons(120, 4.2, 1.6, 24, true), clip);
  }
  SECTION("inside one contour that spans them all (the windings right of a change change too)") {
    Shape shape = row_of_polygons(120, 4.2, 1.6, 24, false);
    shape.push_back(rect(1, 2, 510, 30));
    check_swept(shape, clip);
    shape.back() = {{1, 2}, {1, 30}, {510, 30}, {510, 2}};  // the other way round: a hole around them
    check_swept(shape, clip);
  }
  SECTION("overlapping their neighbours: crossings among many open chains") {
    const std::uint64_t crossings = check_swept(row_of_polygons(100, 2.9, 2.0, 24, false), clip);
    CHECK(crossings > 100);  // each neighbouring pair crosses
    check_swept(row_of_polygons(100, 2.9, 2.0, 24, true), clip);
  }
}

TEST_CASE("random rows of small shapes are swept exactly", "[oracle][sweep]") {
  // Small random simple polygons scattered along a strip: dozens open at once, some overlapping (crossing
  // chains), some reversed, ends and starts at every height.
  std::mt19937 rng(20261127);
  std::uniform_real_distribution<double> along(4.0, 252.0);
  std::uniform_real_distribution<double> across(6.0, 26.0);
  std::uniform_int_distribution<int> vertices(3, 12);
  int swept = 0;
  const int trials = 40;
  for (int trial = 0; trial < trials; ++trial) {
    INFO("trial " << trial);
    Shape shape;
    for (int i = 0; i < 60; ++i) {
      Contour c = random_simple_polygon(rng, {along(rng), across(rng)}, 0.5, 3.0, vertices(rng));
      if (i % 3 == 0) std::reverse(c.begin(), c.end());
      shape.push_back(c);
    }
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      const SpanAndMaskComparison run = compare_spans_and_mask_with_reference(shape, rule, {0, 0, 256, 32});
      CHECK(run.max_diff <= 1);
      CHECK(run.mask_max_diff <= 1);
      CHECK(run.violations == 0);
      swept += static_cast<int>(run.stats.planar_fills);
    }
  }
  // The sweep, not the row scan, resolved these (a fill whose crossings outrun its budget would go to the
  // row scan, with the same output; none of these does).
  CHECK(swept == 2 * trials);
}

TEST_CASE("chains that end where others start at the same height", "[oracle][sweep]") {
  const IntRect clip{0, 0, 64, 64};
  SECTION("diamonds touching tip to tip, in columns of different phase") {
    Shape shape;
    for (int column = 0; column < 6; ++column) {
      const double x = 6.0 + 9.0 * column;
      const double phase = 2.0 * (column % 3);
      for (double y = 2.0 + phase; y + 8.0 <= 62.0; y += 8.0) {
        shape.push_back({{x, y}, {x + 3.5, y + 4.0}, {x, y + 8.0}, {x - 3.5, y + 4.0}});
      }
    }
    check_swept(shape, clip);
  }
  SECTION("rectangles stacked on shared horizontal edges, some reversed") {
    Shape shape;
    for (int i = 0; i < 9; ++i) {
      Contour r = rect(8.0 + (i % 3), 4.0 + 6.0 * i, 40.0 - (i % 2), 10.0 + 6.0 * i);
      if (i % 4 == 1) std::reverse(r.begin(), r.end());
      shape.push_back(r);
    }
    check_swept(shape, clip);
  }
  SECTION("a staircase: one step's chains end on the line where the next step's start, elsewhere") {
    Shape shape;
    for (int i = 0; i < 8; ++i)
      shape.push_back(rect(4.0 + 6.0 * i, 4.0 + 7.0 * i, 12.0 + 6.0 * i, 11.0 + 7.0 * i));
    check_swept(shape, clip);
  }
  SECTION("triangles meeting at one vertex, one above and one below, among open chains") {
    Shape shape = {{{20, 4}, {44, 4}, {32, 32}},
                   {{32, 32}, {50, 60}, {14, 60}},
                   rect(2, 2, 10, 62),
                   rect(54, 2, 62, 62)};
    check_swept(shape, clip);
  }
}

TEST_CASE("coincident chains: one contour drawn many times, shared edges", "[oracle][sweep]") {
  const IntRect clip{0, 0, 64, 64};
  SECTION("a polygon drawn 40 times among others") {
    Shape shape;
    for (int i = 0; i < 40; ++i) shape.push_back(regular_polygon({32, 32}, 20, 24, 30));
    for (int i = 0; i < 8; ++i) shape.push_back(regular_polygon({4.0 + 7.5 * i, 4.0}, 2.5, 2.5, 12));
    check_swept(shape, clip);
  }
  SECTION("a polygon drawn 20 times and reversed 20 times (nothing left under nonzero)") {
    Shape shape;
    for (int i = 0; i < 20; ++i) {
      shape.push_back(regular_polygon({32, 32}, 20, 24, 30));
      shape.push_back(regular_polygon({32, 32}, 20, 24, 30, 0.0, true));
    }
    check_swept(shape, clip);
  }
  SECTION("a checkerboard of squares sharing their sides and corners") {
    Shape shape;
    for (int row = 0; row < 7; ++row) {
      for (int column = 0; column < 7; ++column) {
        if ((row + column) % 2 == 0)
          shape.push_back(rect(4 + 8 * column, 4 + 8 * row, 12 + 8 * column, 12 + 8 * row));
      }
    }
    check_swept(shape, clip);
  }
  SECTION("a grid of squares, every one drawn, neighbours' sides coincident and opposite") {
    Shape shape;
    for (int row = 0; row < 6; ++row) {
      for (int column = 0; column < 6; ++column)
        shape.push_back(rect(5 + 9 * column, 5 + 9 * row, 14 + 9 * column, 14 + 9 * row));
    }
    check_swept(shape, clip);
  }
}
