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

}  // namespace
}  // namespace curvescan
