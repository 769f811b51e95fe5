// The whole-fill sweep through crossings (raster/scan/rasterizer_planar.cpp; essay in rasterizer.cpp,
// step 8): where two neighbouring monotone chains cross, the crossing is an event of the sweep (Bentley and
// Ottmann), so a self-crossing fill still has its exact boundary found once for the whole fill and is
// accumulated without the row scan. Held to the plain reference scan (rasterize_reference) on random
// self-crossing polygons, star polygons, stroke outlines (wide, dashed, self-crossing), and the corner
// cases of the crossing events: crossings at a joint, at a shared vertex, collinear overlapping edges,
// touching contours, contours drawn twice or reversed, crossings past the clip's left side; under both
// fill rules. And held to the route it is for (RasterizerStats::planar_fills and sweep_crossings), and to
// the budget that sends fills of far more crossings than edges to the row scan.
//
// Metric: the same exact area summed in another order, so an area within ~1e-12 of a rounding midpoint
// may round either way: at most 1 step of 255 per pixel (as in rasterizer_planar_test.cpp). The crossing
// heights are rounded; the boundary pieces are cut there but stay on the fill's own edges, so a rounding
// of a crossing height by ε moves a sliver of area at most ε · (width between the two chains within ε of
// their crossing), ~1e-26 of a pixel here, far below that step.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "coverage_mask.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/stroke.h"
#include "outline_shape.h"
#include "polygon_scenes.h"
#include "sweep_checks.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

}  // namespace

TEST_CASE("self-crossing fills are swept through their crossings and match the reference",
          "[oracle][sweep]") {
  struct Scene {
    std::string name;
    Shape shape;
    bool crosses = true;  // whether two chains cross (overlapping rectangles only overlap: their vertical
                          // chains never cross, the planar case of the sweep)
  };
  const std::vector<Scene> scenes = {
      {"star polygon {7/3}", {star_polygon({32, 32}, 28, 7, 3)}},
      {"star polygon {17/8}, crossings near the centre", {star_polygon({31.7, 32.2}, 29, 17, 8, 0.1)}},
      {"bow tie", {{{8, 8}, {56, 56}, {56, 8}, {8, 56}}}},
      {"two overlapping contours", {rect(8, 8, 40, 40), {{24, 20}, {60, 24}, {50, 60}, {20, 44}}}},
      {"crossing at a joint of one chain", {{{8, 8}, {32, 32}, {56, 56}, {56, 8}, {8, 56}}}},
      {"crossing exactly at a vertex of both", {{{8, 8}, {32, 32}, {56, 56}, {56, 8}, {32, 32}, {8, 56}}}},
      {"collinear overlapping edges", {rect(8, 8, 40, 40), rect(20, 8, 56, 40), rect(14, 20, 30, 56)}, false},
      {"collinear overlapping edges, crossed by a slanted contour",
       {rect(8, 8, 40, 40), rect(20, 8, 56, 40), {{4, 60}, {30, 2}, {60, 50}}}},
      {"a crossing contour drawn twice",
       {star_polygon({32, 32}, 28, 7, 3), star_polygon({32, 32}, 28, 7, 3)}},
      {"a crossing contour and its reverse",
       {star_polygon({32, 32}, 28, 7, 3), reversed(star_polygon({32, 32}, 28, 7, 3))}},
      {"opposite windings overlapping", {rect(6, 10, 50, 30), reversed(rect(20, 4, 36, 60))}, false},
      {"opposite windings crossing",
       {star_polygon({30, 30}, 24, 5, 2), reversed(star_polygon({34, 33}, 22, 7, 2))}},
      {"crossings left of the clip", {{{-30, 8}, {40, 56}, {40, 8}, {-30, 56}}}},
      {"crossings in one pixel", {{{30.1, 30.1}, {30.9, 30.9}, {30.9, 30.1}, {30.1, 30.9}}}},
      {"many sub-pixel edges crossing (overlapping circles)",
       {regular_polygon({26, 30}, 18, 18, 700), reversed(regular_polygon({38, 34}, 17, 19, 650, 0.2))}},
  };
  for (const Scene& scene : scenes) {
    INFO(scene.name);
    check_swept(scene.shape, {0, 0, 64, 64}, scene.crosses ? SweptCrossings::kSome : SweptCrossings::kAny);
  }
}

TEST_CASE("random self-crossing polygons are swept exactly", "[oracle][sweep]") {
  std::mt19937 rng(20261127);
  std::uniform_int_distribution<int> vertices(3, 80);
  std::uint64_t crossings = 0;
  for (int trial = 0; trial < 150; ++trial) {
    INFO("trial " << trial);
    Shape shape{random_polygon(rng, 1.0, 1.0, 63.0, 63.0, vertices(rng))};
    if (trial % 3 == 0) shape.push_back(random_polygon(rng, -10.0, 5.0, 70.0, 60.0, vertices(rng)));
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      const SpanAndMaskComparison run = compare_spans_and_mask_with_reference(shape, rule, {0, 0, 64, 64});
      CHECK(run.stats.planar_fills == 1);
      CHECK(run.max_diff <= 1);
      CHECK(run.mask_max_diff <= 1);
      CHECK(run.violations == 0);
      crossings += run.stats.sweep_crossings;
    }
  }
  CHECK(crossings > 1000);  // the scenes do cross, often
}

TEST_CASE("random polygons on a grid: crossings at vertices and on shared lines", "[oracle][sweep]") {
  // Vertices on a coarse integer grid: many edges meet at shared vertices, run along the same lines and
  // cross exactly at grid points, where the crossing events and the chain ends coincide.
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coordinate(0, 8);
  std::uniform_int_distribution<int> vertices(3, 30);
  for (int trial = 0; trial < 150; ++trial) {
    INFO("trial " << trial);
    Shape shape;
    for (int c = 0; c < 1 + trial % 3; ++c) {
      Contour contour;
      const int n = vertices(rng);
      for (int i = 0; i < n; ++i)
        contour.push_back({4.0 + 7.0 * coordinate(rng), 4.0 + 7.0 * coordinate(rng)});
      shape.push_back(contour);
    }
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      const SpanAndMaskComparison run = compare_spans_and_mask_with_reference(shape, rule, {0, 0, 64, 64});
      CHECK(run.max_diff <= 1);
      CHECK(run.mask_max_diff <= 1);
      CHECK(run.violations == 0);
    }
  }
}

TEST_CASE("stroke outlines are swept through their self-overlaps", "[oracle][sweep]") {
  // A zigzag polyline and a looping cubic, stroked wide (the outline's sides cross at every sharp
  // corner), round-joined, and dashed (dashes overlapping at the corners).
  PathBuilder zigzag;
  zigzag.move_to({10, 20});
  for (int i = 1; i < 12; ++i) zigzag.line_to({10.0 + 16.0 * i, i % 2 == 0 ? 20.0 : 100.0});
  PathBuilder loop;
  loop.move_to({20, 100});
  loop.cubic_to({200, 0}, {0, 0}, {180, 100});
  const Result<Path> zigzag_path = zigzag.build();
  const Result<Path> loop_path = loop.build();
  REQUIRE(zigzag_path);
  REQUIRE(loop_path);
  const IntRect clip{0, 0, 200, 120};
  StrokeStyle wide;
  wide.width = 14.0;
  StrokeStyle round = wide;
  round.join = LineJoin::kRound;
  round.cap = LineCap::kRound;
  StrokeStyle dashed;
  dashed.width = 6.0;
  dashed.dash_array = {9.0, 3.0};
  for (const StrokeStyle* style : {&wide, &round, &dashed}) {
    INFO("width " << style->width << (style->dash_array.empty() ? "" : ", dashed"));
    check_swept(outline_shape(*zigzag_path, *style), clip, SweptCrossings::kSome);
    check_swept(outline_shape(*loop_path, *style), clip, SweptCrossings::kSome);
  }
}

TEST_CASE("fills of far more crossings than edges go to the row scan, with the same output",
          "[oracle][sweep]") {
  // 400 long segments across the whole clip as a zigzag polyline: tens of thousands of crossings, far
  // above the sweep's budget (32 per edge, scaled by 16 / their mean height of ~43 rows, plus 4096), so
  // the fill is scanned row by row.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> along(0.0, 128.0);
  Contour zigzag;
  for (int i = 0; i < 400; ++i)
    zigzag.push_back(i % 2 == 0 ? Point{0.5, along(rng)} : Point{127.5, along(rng)});
  const SpanAndMaskComparison dense =
      compare_spans_and_mask_with_reference({zigzag}, FillRule::kEvenOdd, {0, 0, 128, 128});
  CHECK(dense.stats.planar_fills == 0);
  CHECK(dense.max_diff <= 1);
  CHECK(dense.violations == 0);
  // The same fill with the sweep's budget raised far enough: the sweep resolves it, as exactly.
  Rasterizer rasterizer(IntRect{0, 0, 128, 128});
  rasterizer.set_sweep_crossing_budget(1e6);
  add_shape(rasterizer, {zigzag});
  CoverageMask swept(128, 128);
  MaskSink swept_sink(swept);
  rasterizer.rasterize(FillRule::kEvenOdd, Antialias::kExact, swept_sink);
  CHECK(rasterizer.stats().planar_fills == 1);
  CHECK(rasterizer.stats().sweep_crossings > 32 * 400 + 4096);  // more than the default budget allows
  CoverageMask reference(128, 128);
  MaskSink reference_sink(reference);
  rasterizer.rasterize_reference(FillRule::kEvenOdd, Antialias::kExact, reference_sink);
  CHECK(max_abs_diff(swept, reference) <= 1);
  CHECK(swept_sink.violations == 0);
}

TEST_CASE("a crossing no height can separate from its joint gives up at once, with the same output",
          "[oracle][sweep]") {
  // A chain steps across a vertical one on a nearly horizontal edge whose two ends are `ulps` rounding
  // steps of y apart: the crossing lies inside that step, its height rounds to the step's top, and there
  // the swapped pair is out of order again. Swapping back and forth at one height, the sweep used to run
  // to its budget (4096 + 32 per edge crossings) before the row scan took over; it now gives up at the
  // first such crossing. The fill goes to the row scan either way: the output is the reference's.
  for (const double offset : {1e-4, 1e-2, 0.4}) {
    for (const int ulps : {1, 2, 3}) {
      double y_step = 16.0;
      for (int i = 0; i < ulps; ++i) y_step = std::nextafter(y_step, 100.0);
      const Shape shape = {
          rect(4, 2, 10, 30),
          {{10 + offset, 2}, {10 + offset, 16}, {10 - offset, y_step}, {10 - offset, 30}, {20, 30}, {20, 2}}};
      for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
        INFO("offset " << offset << ", step of " << ulps << " ulps, "
                       << (rule == FillRule::kNonZero ? "nonzero" : "even-odd"));
        const SpanAndMaskComparison run = compare_spans_and_mask_with_reference(shape, rule, {0, 0, 32, 32});
        INFO("sweep crossings " << run.stats.sweep_crossings);
        // Two crossings at most: the pair's swap and the one it gives up at (the budget would be 4096+).
        CHECK(run.stats.sweep_crossings <= 2);
        CHECK(run.max_diff <= 1);
        CHECK(run.mask_max_diff <= 1);
        CHECK(run.violations == 0);
      }
    }
  }
}

TEST_CASE("a zero sweep budget sends every crossing fill to the row scan", "[oracle][sweep]") {
  Rasterizer rasterizer(IntRect{0, 0, 64, 64});
  rasterizer.set_sweep_crossing_budget(0.0);
  add_shape(rasterizer, {star_polygon({32, 32}, 28, 7, 3)});
  CoverageMask mask(64, 64);
  MaskSink sink(mask);
  rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
  CHECK(rasterizer.stats().planar_fills == 0);
  CHECK(rasterizer.stats().sweep_crossings == 0);
  // A planar fill still takes the sweep.
  rasterizer.reset(IntRect{0, 0, 64, 64});
  add_shape(rasterizer, {regular_polygon({32, 32}, 20, 20, 50)});
  rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
  CHECK(rasterizer.stats().planar_fills == 1);
}
