// The size of a stroke's outline follows the flattening bound, and a budget refuses the rest.
//
// stroker.cpp cuts curves so that the true tangent turns by at most Δ = sqrt(2·tolerance/h) along a chord
// (h = width/2), and the flattener's own chords number ~ turn / sqrt(8·tolerance/R) (R the radius of
// curvature): both grow like tolerance^(-1/2), so the outline of a fixed curve grows by sqrt(10) ≈ 3.16
// per decade of tolerance. Regression of fuzz/regressions/raster_stroke/round_join_circle_under_scale_1e7_oom:
// a circle of radius 5 stroked 11 wide (h > R: the normals cross on every chord) under scale(1e7) at
// 0.25 px, i.e. user tolerance 2.5e-8, made 6.2M outline elements (130x per decade below 2.5e-6) once
// the per-curve cut limit was reached and every further chord got a disc.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <string>

#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/stroke.h"

namespace curvescan {
namespace {

Path circle(double radius) {
  PathBuilder builder;
  builder.arc({0.0, 0.0}, radius, radius, 0.0, 0.0, 2.0 * std::numbers::pi).close();
  const Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  return *path;
}

StrokeStyle wide_round_style() {
  StrokeStyle style;
  style.width = 11.0;
  style.join = LineJoin::kRound;
  return style;
}

std::size_t outline_elements(const Path& path, const StrokeStyle& style, double tolerance) {
  const Result<Path> outline = stroke_path(path, style, tolerance);
  REQUIRE(outline.is_ok());
  return outline->verbs().size();
}

TEST_CASE("a wide stroke on a circle grows like tolerance^(-1/2), down to the fuzz finding's tolerance",
          "[stroke][limits]") {
  const Path path = circle(5.0);
  const StrokeStyle style = wide_round_style();
  double tolerance = 2.5e-4;
  std::size_t previous = outline_elements(path, style, tolerance);
  for (int decade = 0; decade < 4; ++decade) {
    tolerance /= 10.0;
    const std::size_t elements = outline_elements(path, style, tolerance);
    INFO("tolerance " << tolerance << ": " << previous << " -> " << elements << " elements");
    // sqrt(10) per decade; the cuts halve pieces in parameter, so the piece count at one tolerance may
    // overshoot what Δ needs by up to 2x where the other does not: at most 2·sqrt(10) per decade.
    CHECK(static_cast<double>(elements) <= 2.0 * std::sqrt(10.0) * static_cast<double>(previous));
    CHECK(elements >= previous);  // a finer tolerance never needs fewer chords
    previous = elements;
  }
  // The finding's tolerance (2.5e-8) fits the default budget, one point per outline element or fewer.
  CHECK(previous <= static_cast<std::size_t>(kMaxStrokeOutlinePoints));
}

TEST_CASE("the outline budget refuses a stroke that needs more points, with kLimitExceeded", "[stroke][limits]") {
  const Path path = circle(5.0);
  const StrokeStyle style = wide_round_style();
  const double tolerance = 2.5e-5;
  const Result<Path> full = stroke_path(path, style, tolerance);
  REQUIRE(full.is_ok());
  const auto points = static_cast<std::int64_t>(full->points().size());
  // Twice the points it needs: the budget is not in the way.
  const Result<Path> roomy = stroke_path(path, style, tolerance, 2 * points);
  REQUIRE(roomy.is_ok());
  CHECK(roomy->verbs().size() == full->verbs().size());
  // Half: refused, before the outline is made.
  const Result<Path> refused = stroke_path(path, style, tolerance, points / 2);
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  CHECK(refused.error().message.find("budget") != std::string::npos);
  CHECK(stroke_path(path, style, tolerance, -1).error().kind == ErrorKind::kInvalidArgument);
}

TEST_CASE("the default budget refuses a tolerance far too fine for the stroke instead of exhausting memory",
          "[stroke][limits]") {
  // Δ = sqrt(2·2.5e-11/5.5) ≈ 3e-6 rad: ~2·10^6 cuts per turn, past kMaxStrokeOutlinePoints / 2 vertices.
  const Result<Path> outline = stroke_path(circle(5.0), wide_round_style(), 2.5e-11);
  REQUIRE_FALSE(outline.is_ok());
  CHECK(outline.error().kind == ErrorKind::kLimitExceeded);
}

}  // namespace
}  // namespace curvescan
