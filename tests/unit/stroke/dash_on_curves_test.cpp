// Dashes on curves: positions by the curve's arc length, and dash ends cut on the curve's true normal
// (docs/stroking.md). Circle arcs make both exact in closed form: arc length r·angle, normal radial.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "curvescan/raster/stroke.h"
#include "curvescan/raster/path_builder.h"

namespace curvescan {
namespace {

constexpr double kRadius = 40.0;

Path circle_arc(double sweep) {
  PathBuilder builder;
  builder.arc({0.0, 0.0}, kRadius, kRadius, 0.0, 0.0, sweep);
  return *builder.build();
}

double polar_angle(Point p) {
  const double angle = std::atan2(p.y, p.x);
  return angle < -0.5 ? angle + 2.0 * std::numbers::pi : angle;
}

TEST_CASE("dashes on a circle start at their arc length", "[stroke][dash]") {
  // Tolerance 0.1: chords turn by ~sqrt(8·0.1/40) = 0.14 rad, so a bare polyline is short by δ²/24 = 8e-4
  // of the length: 0.2 px by the last dash. The dasher counts each chord as the arc its end tangents
  // define (exact on a circle); what remains is the chord-fraction to arc-fraction mapping, below
  // δ³/12 rad (~0.01 px at r = 40): the bound is 0.02 px along the circle.
  const std::vector<double> pattern{10.0, 5.0};
  const Result<Path> dashes = dash_path(circle_arc(2.0 * std::numbers::pi), pattern, 0.0, 0.1);
  REQUIRE(dashes.is_ok());
  int index = 0;
  for (const PathElement& e : *dashes) {
    if (e.verb != PathVerb::kMove) continue;
    const double expected = 15.0 * index / kRadius;
    INFO("dash " << index);
    CHECK(std::abs(std::remainder(polar_angle(e.start) - expected, 2.0 * std::numbers::pi)) * kRadius <= 0.02);
    ++index;
  }
  CHECK(index == 17);  // 2π·40 = 251.3 = 16 periods of 15 and a dash
}

TEST_CASE("a butt dash end on a wide arc is cut on the radial normal", "[stroke][dash]") {
  // One dash of length 20 (angle 0.5 rad) on a 30 px wide stroke: its outline lies between the radial
  // lines at 0 and 0.5 rad, within the stroke tolerance (0.1 px). A cut across the chord instead of the
  // normal would put the outer corner h·(chord turn)/2 ≈ 15·0.07 ≈ 1 px past the radial line.
  constexpr double kTol = 0.1;
  StrokeStyle style;
  style.width = 30.0;
  style.cap = LineCap::kButt;
  style.dash_array = {20.0, 1000.0};
  const Result<Path> outline = stroke_path(circle_arc(std::numbers::pi / 2), style, kTol);
  REQUIRE(outline.is_ok());
  const double end_angle = 20.0 / kRadius;
  int vertices = 0;
  for (const PathElement& e : *outline) {
    if (e.verb == PathVerb::kClose) continue;
    const Point p = e.end;
    const double r = std::hypot(p.x, p.y);
    INFO("vertex (" << p.x << ", " << p.y << ")");
    CHECK(polar_angle(p) >= -kTol / r);
    CHECK(polar_angle(p) <= end_angle + kTol / r);
    ++vertices;
  }
  CHECK(vertices > 4);
}

}  // namespace
}  // namespace curvescan
