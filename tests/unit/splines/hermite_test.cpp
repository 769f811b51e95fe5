// Hermite cubics (U. of Toronto, *Parametric Curves*, "Hermite Curves"): blending-function evaluation equals the Bézier conversion,
// end conditions hold, and piecewise Hermite splines honour tangents scaled by the parameter intervals.
#include "curvescan/curves/hermite.h"

#include <catch2/catch.hpp>
#include <limits>
#include <random>
#include <string>

#include "random_spline.h"

namespace curvescan {
namespace {

Vec2 random_vector(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> coord(-5.0, 5.0);
  return {coord(rng), coord(rng)};
}

// d/dt of a cubic Bézier at its ends: 3 (b1 - b0) and 3 (b3 - b2).
Vec2 start_derivative(const Bezier& b) {
  return (b.points()[1] - b.points()[0]) * 3.0;
}
Vec2 end_derivative(const Bezier& b) {
  return (b.points()[3] - b.points()[2]) * 3.0;
}

TEST_CASE("A Hermite segment equals its Bezier form", "[hermite]") {
  std::mt19937_64 rng(13001);
  for (int trial = 0; trial < 500; ++trial) {
    const auto ends = test::random_points(rng, 2);
    const HermiteSegment segment{ends[0], ends[1], random_vector(rng), random_vector(rng)};
    const Bezier bezier = segment.to_bezier();
    REQUIRE(bezier.degree() == 3);
    for (int step = 0; step <= 32; ++step) {
      const double t = step / 32.0;
      // Points in [-1, 1], tangents in [-5, 5]: both forms sum a few terms of magnitude <= 5 with a few
      // roundings each, so they agree to ~1e-15; 1e-12 leaves room.
      REQUIRE(segment.eval(t).distance(bezier.eval(t)) <= 1e-12);
    }
  }
}

TEST_CASE("Hermite blending functions meet the end conditions", "[hermite]") {
  std::mt19937_64 rng(13002);
  const auto ends = test::random_points(rng, 2);
  const HermiteSegment segment{ends[0], ends[1], random_vector(rng), random_vector(rng)};
  // The blending functions are exactly 0 or 1 at t = 0 and t = 1 (integer arithmetic).
  REQUIRE(segment.eval(0.0) == segment.p0);
  REQUIRE(segment.eval(1.0).distance(segment.p1) <= 1e-15);
  REQUIRE(segment.derivative(0.0) == segment.r0);
  REQUIRE((segment.derivative(1.0) - segment.r1).length() <= 1e-14);
  // The derivative against central differences: h = 1e-6, |P'''| <= 12 |P4 - P1| + 6 (|R1| + |R4|) ~ 100,
  // truncation h^2/6 * 100 ~ 2e-11, rounding 1e-16 / 1e-6 ~ 1e-10. Tolerance 1e-8.
  for (int step = 1; step < 10; ++step) {
    const double t = step / 10.0, h = 1e-6;
    const Vec2 numeric = (segment.eval(t + h) - segment.eval(t - h)) / (2 * h);
    REQUIRE((segment.derivative(t) - numeric).length() <= 1e-8);
  }
}

TEST_CASE("Piecewise Hermite scales tangents by the parameter intervals", "[hermite]") {
  std::mt19937_64 rng(13003);
  const auto points = test::random_points(rng, 6);
  std::vector<Vec2> tangents;
  for (int i = 0; i < 6; ++i) tangents.push_back(random_vector(rng));
  const std::vector<double> parameters{0.0, 0.5, 2.0, 2.25, 4.0, 7.0};
  auto segments = hermite_spline(points, tangents, parameters);
  REQUIRE(segments.is_ok());
  REQUIRE(segments->size() == 5);
  for (std::size_t i = 0; i < 5; ++i) {
    const Bezier& b = (*segments)[i];
    const double h = parameters[i + 1] - parameters[i];
    REQUIRE(b.start() == points[i]);
    REQUIRE(b.end() == points[i + 1]);
    // dP/dt = (dP/ds) / h on [t_i, t_{i+1}]: the given tangents, to a few roundings of magnitude 5.
    REQUIRE((start_derivative(b) / h - tangents[i]).length() <= 1e-13);
    REQUIRE((end_derivative(b) / h - tangents[i + 1]).length() <= 1e-13);
  }
  // Without parameters the intervals are unit, so the segments are the plain Hermite segments.
  auto unit = hermite_spline(points, tangents);
  REQUIRE(unit.is_ok());
  REQUIRE((*unit)[2] == HermiteSegment{points[2], points[3], tangents[2], tangents[3]}.to_bezier());
}

TEST_CASE("hermite_spline rejects malformed input", "[hermite][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Point> points{{0, 0}, {1, 0}, {2, 1}};
  const std::vector<Vec2> tangents{{1, 0}, {1, 0}, {1, 0}};
  auto check = [](const Result<std::vector<Bezier>>& r, const std::string& fragment) {
    REQUIRE_FALSE(r.is_ok());
    INFO(r.error().message);
    REQUIRE(r.error().message.find(fragment) != std::string::npos);
  };
  check(hermite_spline(std::span(points).first(1), std::span(tangents).first(1)), "at least 2 points");
  check(hermite_spline(points, std::span(tangents).first(2)), "needs as many tangents, got 2");
  check(hermite_spline(points, tangents, std::vector<double>{0, 1}), "needs as many parameters");
  check(hermite_spline(std::vector<Point>{{0, 0}, {nan, 0}, {2, 1}}, tangents), "point 1");
  check(hermite_spline(points, std::vector<Vec2>{{1, 0}, {1, nan}, {1, 0}}), "tangent 1");
  check(hermite_spline(points, tangents, std::vector<double>{0, 1, 1}), "parameter 2 does not");
  check(hermite_spline(points, tangents, std::vector<double>{0, nan, 2}), "parameter 1 is not finite");
}

}  // namespace
}  // namespace curvescan
