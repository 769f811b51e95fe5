// Dash ends inside a chord sit on the curve and are cut on its exact normal there (dasher.cpp,
// stroke_curve_piece.h). Regression: oracle scenes 115, 129 and 174 (wide dashed curves, a short dash across
// a bend tighter than the half-width) were 23-63/255 off the swept reference because a dash end inside a
// chord sat on the chord and took the tangent interpolated between the chord's end tangents: off by a
// fraction of the chord's turn where the curvature changes along it, times h = 50 (0.15 px).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/stroke.h"

namespace curvescan {
namespace {

// The parameter of the point of `curve` nearest to `m`: the best of a dense sampling, then Newton on
// (B(t) - m)·B'(t) = 0 (Umetani, *Parametric Curve*, eq. 8 for B, its hodograph for B').
double nearest_parameter(const Bezier& curve, const Bezier& velocity, const Bezier& acceleration, Point m) {
  double best_t = 0.0, best_distance = INFINITY;
  for (int i = 0; i <= 4000; ++i) {
    const double t = i / 4000.0;
    const double distance = curve.eval(t).distance(m);
    if (distance < best_distance) {
      best_distance = distance;
      best_t = t;
    }
  }
  double t = best_t;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const Vec2 offset = curve.eval(t) - m;
    const Vec2 d1 = velocity.eval(t) - Point{}, d2 = acceleration.eval(t) - Point{};
    const double slope = d1.dot(d1) + offset.dot(d2);
    if (!(slope > 0.0)) break;
    t = std::clamp(t - offset.dot(d1) / slope, 0.0, 1.0);
  }
  return t;
}

TEST_CASE("dash ends on a wide dashed cubic sit on the curve, cut on its exact normal", "[stroke][dash]") {
  // An S-shaped cubic whose curvature changes fast near its bends, stroked 100 wide with butt caps (each
  // dash end is one outline edge of length exactly 2h, centred on the dash end, along the normal there).
  const Point p0{10, 20}, p1{130, 10}, p2{-10, 100}, p3{110, 110};
  PathBuilder builder;
  builder.move_to(p0).cubic_to(p1, p2, p3);
  const Path path = *builder.build();
  const Bezier curve(std::vector<Point>{p0, p1, p2, p3});
  const Bezier velocity = curve.deriv(), acceleration = velocity.deriv();
  StrokeStyle style;
  style.width = 100.0;
  style.cap = LineCap::kButt;
  style.dash_array = {9, 4, 2};
  style.dash_offset = 3.0;
  const Result<Path> outline = stroke_path(path, style, 0.02);
  REQUIRE(outline.is_ok());

  int cap_edges = 0;
  for (const PathElement& e : *outline) {
    if (e.verb == PathVerb::kMove) continue;
    const Vec2 edge = e.end - e.start;
    // A butt cap edge is P ± h·n: length 2h up to rounding (coordinates ~1e2, so ~1e-13); no offset chord
    // of this stroke is within 1e-9 of it (checked: the count below is the dash ends').
    if (std::abs(edge.length() - style.width) > 1e-9) continue;
    ++cap_edges;
    const Point middle = lerp(e.start, e.end, 0.5);
    const double t = nearest_parameter(curve, velocity, acceleration, middle);
    const Vec2 tangent = (velocity.eval(t) - Point{}).normalized();
    INFO("cap edge " << cap_edges << " at t = " << t);
    // On the curve and perpendicular to it, up to rounding (the dash end is the curve point found by regula
    // falsi and its tangent is exact there; the old chord point was up to tolerance/2 = 0.01 off the curve
    // and its interpolated normal ~1e-4 rad off).
    CHECK(curve.eval(t).distance(middle) <= 1e-9);
    CHECK(std::abs(edge.normalized().dot(tangent)) <= 1e-9);
  }
  // The odd array is repeated ({9, 4, 2, 9, 4, 2}): three dashes per period of 30, i.e. one per 10 of arc
  // length (measured by sampling); every dash has two cap edges. Two dashes fewer leave room for the ones
  // cut short by the curve's ends.
  double length = 0.0;
  for (int i = 1; i <= 4000; ++i) length += curve.eval(i / 4000.0).distance(curve.eval((i - 1) / 4000.0));
  const int expected_dashes = static_cast<int>(std::floor(length / 10.0));
  CHECK(cap_edges >= 2 * (expected_dashes - 2));
}

}  // namespace
}  // namespace curvescan
