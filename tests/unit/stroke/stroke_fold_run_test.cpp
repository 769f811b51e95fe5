// Fold runs (stroker_outline.cpp): where the half-width exceeds the radius of curvature, consecutive
// normal segments cross; a run of such chords becomes one extra polygon (the fold side's lobes summed)
// and a fold side through the crossings, instead of three polygons per chord. These tests pin the shape
// of that output (contour counts that no longer grow with the chord count) and its area in closed form.
// Area tolerance as in stroke_area_test.cpp: the outline is within the stroke tolerance (0.05 px) of the
// exact stroke, so the area is within 0.05 · perimeter, plus 8-bit rounding of 0.5/255 per pixel.
#include <catch2/catch.hpp>
#include <cstddef>
#include <numbers>

#include "stroke_render.h"

namespace curvescan {
namespace {

using testing::render_stroke;

constexpr double kTolerance = 0.05;

double area_bound(double perimeter, const testing::CoverageMask& mask) {
  return kTolerance * perimeter + 0.5 / 255.0 * static_cast<double>(mask.values.size());
}

std::size_t contour_count(const Path& outline) {
  std::size_t count = 0;
  for (const PathElement& element : outline) count += element.verb == PathVerb::kMove ? 1 : 0;
  return count;
}

Path arc_path(Point center, double radius, double start, double sweep, bool closed) {
  PathBuilder builder;
  builder.arc(center, radius, radius, 0.0, start, sweep);
  if (closed) builder.close();
  const Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  return *path;
}

TEST_CASE("a circle stroked wider than its diameter is one fold run: three contours at any tolerance",
          "[stroke][strong]") {
  // Radius 15, half-width 40: every chord's normals cross. The outline is the left side (through the
  // crossings, near the centre), the right side (radius 55) and the run's fold polygon: 3 contours
  // however many chords the tolerance asks for (per-chord lobes gave 2 + 3 per chord: hundreds here).
  const Path circle = arc_path({60, 60}, 15, 0, 2 * std::numbers::pi, true);
  StrokeStyle style;
  style.width = 80.0;
  for (const double tolerance : {0.5, 0.05, 0.005}) {
    const Result<Path> outline = stroke_path(circle, style, tolerance);
    REQUIRE(outline.is_ok());
    INFO("tolerance " << tolerance << ": " << outline->verbs().size() << " elements");
    CHECK(contour_count(*outline) == 3);
  }
}

TEST_CASE("a half circle stroked wider than its diameter sweeps two half discs", "[stroke][strong]") {
  // Radius R = 10 about (60, 60), half-width h = 30, butt caps, the upper half (angles π..2π, y down).
  // Every normal segment passes through the centre: the outer halves sweep the half disc of radius
  // h + R above the diameter, the inner halves the half disc of radius h − R below it (the fold side).
  // One open contour plus one fold polygon.
  const double radius = 10.0, h = 30.0;
  const Path half = arc_path({60, 60}, radius, std::numbers::pi, std::numbers::pi, false);
  StrokeStyle style;
  style.width = 2 * h;
  style.cap = LineCap::kButt;
  const Result<Path> outline = stroke_path(half, style, kTolerance);
  REQUIRE(outline.is_ok());
  CHECK(contour_count(*outline) == 2);

  const testing::CoverageMask mask = render_stroke(half, style, 120, 120, kTolerance);
  const double outer = h + radius, inner = h - radius;
  const double area = 0.5 * std::numbers::pi * (outer * outer + inner * inner);
  const double perimeter = std::numbers::pi * (outer + inner) + 2 * (outer + inner);
  CHECK(mask.total() == Approx(area).margin(area_bound(perimeter, mask)));
  CHECK(mask.at(60, 60 - 35) == 255);  // inside the big half disc, above the centre
  CHECK(mask.at(60, 60 + 15) == 255);  // inside the small one, below it
  CHECK(mask.at(60, 60 + 25) == 0);    // beyond h − R below the centre
}

TEST_CASE("a bend that folds both ways gives one fold polygon per run", "[stroke][strong]") {
  // Two half circles of radius 8 turning opposite ways (an S), half-width 20: every chord folds, first
  // on the left, then on the right. A run ends where the turn changes sign, so: the outline and two
  // fold polygons. (The area is checked against the swept reference in tests/oracle.)
  PathBuilder builder;
  builder.arc({40, 60}, 8, 8, 0, std::numbers::pi, std::numbers::pi);
  builder.arc({56, 60}, 8, 8, 0, std::numbers::pi, -std::numbers::pi);
  const Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  StrokeStyle style;
  style.width = 40.0;
  const Result<Path> outline = stroke_path(*path, style, kTolerance);
  REQUIRE(outline.is_ok());
  CHECK(contour_count(*outline) == 3);
}

TEST_CASE("circle_fold_crossings_at_centre_slow: a circle's fold crossings are one point, not thousands",
          "[stroke][strong][regression]") {
  // The fuzz input fuzz/regressions/raster_stroke/circle_fold_crossings_at_centre_slow: a circle of
  // radius 5.5 about (10.5, 10.5) drawn seven times over (arc from -5.5 rad sweeping -5.5 rad), stroked
  // 21.25 wide at tolerance 0.01 on a 32 x 32 canvas. Every fold crossing is the centre in exact
  // arithmetic; each was kept as computed, scattered by rounding within 1e-10 px of it, and the thousands
  // of tiny edges between them crossed one another: 6.8 million crossings for the row scan to resolve
  // (1 s of CPU, 17 s under the sanitizers). Counts, not time: the outline's vertices near the centre
  // (one per fold run and side, where there were one per chord), and the crossings of the fill.
  const Point centre{10.5, 10.5};
  PathBuilder builder;
  for (int i = 0; i < 7; ++i) builder.arc(centre, -5.5, -5.5, -5.5, -5.5, -5.5);
  const Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  StrokeStyle style;
  style.width = 21.25;
  style.miter_limit = 4.0;
  const Result<Path> outline = stroke_path(*path, style, 0.01);
  REQUIRE(outline.is_ok());

  std::size_t near_centre = 0;
  for (const PathElement& element : *outline) {
    if (element.verb == PathVerb::kLine && (element.end - centre).length_squared() < 1e-12) ++near_centre;
  }
  Rasterizer rasterizer(IntRect{0, 0, 32, 32});
  rasterizer.set_sweep_crossing_budget(0.0);  // the row scan, which counts every crossing it resolves
  testing::add_polygon_path(rasterizer, *outline);
  testing::CoverageMask mask(32, 32);
  testing::MaskSink sink(mask);
  rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
  const RasterizerStats stats = rasterizer.stats();
  INFO(near_centre << " vertices near the centre, " << stats.crossings << " crossings, "
                   << stats.pieces_visited << " pieces visited, " << rasterizer.edge_count() << " edges");
  // Each circle is four conics, each at most a fold run with its crossing on the outline's fold side and
  // in its lobe polygon: 7 · 4 · 2 (measured 42; 5376 before).
  CHECK(near_centre <= 56);
  // Linear in the edges: the seven rings overlap along their offsets, so a crossing per edge at most
  // (measured 2317 for 5065 edges; 6 843 235 for 10 399 before), and the scan's visits within the
  // 16·⌈log2⌉ per edge of a row's own budget, far from the fill's shared pool (measured 12.8 per edge;
  // 3600 before).
  CHECK(stats.crossings <= rasterizer.edge_count());
  CHECK(stats.pieces_visited <= 64 * rasterizer.edge_count());
  CHECK(stats.sampled_bands + stats.sampled_rows == 0);
  CHECK(sink.violations == 0);
  // The stroke covers the disc of radius h - r about the centre (the folds) and the ring out to h + r.
  CHECK(mask.at(10, 10) == 255);
  CHECK(mask.at(10, 25) == 255);
  CHECK(mask.at(31, 31) == 0);
}

}  // namespace
}  // namespace curvescan
