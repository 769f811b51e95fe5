// Fills of few chains (at most 16: raster/scan/rasterizer_planar_few.cpp proves them planar without the
// general sweep's bookkeeping) held to the plain reference scan (rasterize_reference) under both fill
// rules, through both accumulations (spans, and the dense mask of rasterize_mask): shapes that nearly touch,
// touch at a vertex, share a side, cross once (the general sweep then goes on through the crossing, or the
// row scan takes the fill when crossings are not resolved) and coincide; at 16 chains and at 17 (the
// general sweep's side of the line).
//
// Metric: as in rasterizer_planar_test.cpp, the same exact area summed in another order, so an area within
// ~1e-12 of a rounding midpoint may round either way: at most 1 step of 255 per pixel, no SpanSink
// contract violation.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "coverage_mask.h"
#include "polygon_scenes.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr IntRect kClip{0, 0, 64, 64};

/// Under both rules: which path the fill took (the whole-fill sweep, planar_fills == 1, or the row scan)
/// and the spans and the mask within 1 step of the reference. `sweep_crossing_budget` as in
/// Rasterizer::set_sweep_crossing_budget; 0 sends a crossing fill to the row scan.
void check_fill(const Shape& shape, bool swept, std::optional<double> sweep_crossing_budget = std::nullopt) {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    INFO((rule == FillRule::kNonZero ? "nonzero" : "even-odd"));
    const SpanAndMaskComparison run =
        compare_spans_and_mask_with_reference(shape, rule, kClip, sweep_crossing_budget);
    CHECK(run.stats.planar_fills == (swept ? 1u : 0u));
    CHECK(run.mask_planar_fills == (swept ? 1u : 0u));
    CHECK(run.max_diff <= 1);
    CHECK(run.mask_max_diff <= 1);
    CHECK(run.violations == 0);
  }
}

/// A diamond: four chains' worth of tips (top, bottom) and sides.
Contour diamond(Point centre, double r) {
  return {
      {centre.x, centre.y - r}, {centre.x + r, centre.y}, {centre.x, centre.y + r}, {centre.x - r, centre.y}};
}

}  // namespace

TEST_CASE("fills of few chains match the reference scan", "[oracle][planar]") {
  SECTION("one contour: a circle, a triangle, a rectangle, a star") {
    check_fill({regular_polygon({30, 30}, 20, 20, 96)}, true);
    check_fill({{{5, 3}, {40, 30}, {2, 50}}}, true);
    check_fill({rect(3.5, 4.25, 50.75, 40.5)}, true);
    check_fill({star({32, 32}, 28, 12, 5, 0.3)}, true);  // 10 chains
  }
  SECTION("holes of either orientation, nested rings (winding 2 under nonzero)") {
    check_fill({regular_polygon({30, 30}, 20, 18, 40), regular_polygon({30, 30}, 10, 9, 40, 0.1, true)},
               true);
    check_fill({regular_polygon({30, 30}, 20, 18, 40), regular_polygon({30, 30}, 10, 9, 40, 0.1)}, true);
    check_fill({regular_polygon({32, 32}, 28, 28, 48), regular_polygon({32, 32}, 20, 20, 48, 0.2),
                regular_polygon({32, 32}, 12, 12, 48, 0.3, true), regular_polygon({32, 32}, 4, 4, 48, 0.4)},
               true);
  }
  SECTION("nearly touching: apart by 1e-6 px, and by less than the proof's slack") {
    check_fill({{{5, 5}, {20, 30}, {5, 55}}, {{20.000001, 30}, {40, 5}, {40, 55}}}, true);
    check_fill({diamond({20, 30}, 10), diamond({40 + 1e-9, 30}, 10)}, true);
    check_fill({rect(5, 5, 20, 40), rect(20 + 1e-6, 10, 35, 50)}, true);
  }
  SECTION("touching at a vertex") {
    check_fill({{{5, 5}, {20, 30}, {5, 55}}, {{20, 30}, {40, 5}, {40, 55}}}, true);
    check_fill({diamond({20, 30}, 10), diamond({40, 30}, 10)}, true);  // side tips meet
    check_fill({diamond({30, 20}, 10), diamond({30, 40}, 10)}, true);  // one's bottom tip, the other's top
    check_fill({diamond({20, 20}, 10), diamond({40, 40}, 10)}, true);  // corner to corner
  }
  SECTION("sharing a side, either way round") {
    check_fill({rect(5, 5, 20, 40), rect(20, 10, 35, 50)}, true);
    check_fill({rect(5, 5, 20, 40), reversed(rect(20, 10, 35, 50))}, true);
    check_fill({{{5, 5}, {30, 30}, {5, 55}}, {{30, 30}, {5, 5}, {55, 5}}}, true);
  }
  SECTION("coincident: a contour drawn twice, drawn and reversed") {
    const Contour triangle{{5, 3}, {40, 30}, {2, 50}};
    check_fill({triangle, triangle}, true);
    check_fill({triangle, reversed(triangle)}, true);
    check_fill({regular_polygon({30, 30}, 20, 20, 33), regular_polygon({30, 30}, 20, 20, 33)}, true);
  }
  SECTION("crossing once: swept through the crossing, or scanned by rows") {
    const Shape bow_tie{{{5, 5}, {50, 45}, {50, 5}, {5, 45}}};
    check_fill(bow_tie, true);
    check_fill(bow_tie, false, 0.0);
    const Shape lens{regular_polygon({24, 30}, 15, 15, 24), regular_polygon({36, 30}, 15, 15, 24)};
    check_fill(lens, true);
    check_fill(lens, false, 0.0);
    // One crossing far below where the chains became neighbours, after the proof has passed many events.
    const Shape late{{{10, 2}, {12, 60}, {8, 60}},
                     {{14, 2}, {16, 10}, {14, 20}, {16, 30}, {14, 40}, {9, 59}, {18, 59}}};
    check_fill(late, true);
    check_fill(late, false, 0.0);
  }
  SECTION("clipped: the clip's left side, open on its right") {
    check_fill({regular_polygon({2, 30}, 20, 20, 32)}, true);
    check_fill({regular_polygon({60, 30}, 20, 20, 32)}, true);
    check_fill({rect(-10, 5, 80, 20), rect(-5, 30, 70, 50)}, true);
  }
  SECTION("16 chains and 17: the few-chain proof's limit") {
    for (const bool seventeen : {false, true}) {
      Shape shape;
      for (int i = 0; i < 8; ++i) shape.push_back(diamond({4.0 + 6.5 * i, 20.0 + 2.5 * (i % 3)}, 3.5));
      // Started at its right tip, the last diamond's contour is three chains (its first and last edges
      // both go down the right side but are not linked): 17 in all.
      if (seventeen) std::rotate(shape.back().begin(), shape.back().begin() + 1, shape.back().end());
      check_fill(shape, true);
      shape.push_back(rect(1, 1, 63, 40));  // around them all: windings right of every change change
      check_fill(shape, true);
    }
  }
}
