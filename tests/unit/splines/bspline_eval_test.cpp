// de Boor evaluation against the plain sum of Cox–de Boor bases times control points (Umetani, *Parametric Curve*, eq. 5),
// end-point interpolation of clamped curves, and the classic uniform cubic B-spline matrix.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "curvescan/curves/bspline.h"
#include "random_spline.h"

namespace curvescan {
namespace {

// Control points lie in [-1, 1]^2 and both methods combine them with convex weights in at most ~p^2
// roundings each, so they agree to a few dozen ulps of 1; 1e-12 is the task's bar and leaves ample room.
constexpr double kTolerance = 1e-12;

TEST_CASE("de Boor equals the Cox–de Boor sum on random splines", "[bspline][eval]") {
  std::mt19937_64 rng(7001);
  for (int degree = 0; degree <= 5; ++degree) {
    for (int trial = 0; trial < 60; ++trial) {
      const BSpline spline = test::random_bspline(rng, degree, trial % 3 == 0);
      for (const double u : test::sample_parameters(rng, spline, 30)) {
        const Point fast = spline.eval(u);
        const Point reference = spline.eval_reference(u);
        INFO("degree " << degree << " trial " << trial << " u " << u);
        REQUIRE(fast.distance(reference) <= kTolerance);
      }
    }
  }
}

TEST_CASE("A clamped B-spline starts at its first and ends at its last control point", "[bspline][eval]") {
  std::mt19937_64 rng(7002);
  for (int degree = 1; degree <= 5; ++degree) {
    for (int trial = 0; trial < 30; ++trial) {
      const std::size_t count = static_cast<std::size_t>(degree) + 1 + static_cast<std::size_t>(trial % 7);
      const auto points = test::random_points(rng, count);
      auto spline = BSpline::clamped(points, degree);
      REQUIRE(spline.is_ok());
      REQUIRE(spline->domain_start() == 0.0);
      REQUIRE(spline->domain_end() == 1.0);
      // At u = 0 every de Boor alpha is exactly 0; at u = 1 exactly 1, and lerp(a, b, 1) = a + (b - a)
      // is within one rounding of b.
      REQUIRE(spline->eval(0.0) == points.front());
      REQUIRE(spline->eval(1.0).distance(points.back()) <= 1e-15);
    }
  }
}

TEST_CASE("Uniform cubic B-spline matches the 1/6 basis matrix", "[bspline][eval]") {
  // Dill, *Introduction to Parametric Curves*; U. of Toronto, *Parametric Curves*: on a uniform span the cubic B-spline is (1/6)[(1-t)^3, 3t^3-6t^2+4, -3t^3+3t^2+3t+1, t^3]
  // applied to four consecutive points.
  std::mt19937_64 rng(7003);
  const auto points = test::random_points(rng, 6, 10.0);
  auto spline = BSpline::uniform(points, 3);
  REQUIRE(spline.is_ok());
  for (std::size_t segment = 0; segment < 3; ++segment) {
    for (int step = 0; step <= 10; ++step) {
      const double t = step / 10.0;
      const double b0 = (1 - t) * (1 - t) * (1 - t) / 6.0;
      const double b1 = (3 * t * t * t - 6 * t * t + 4) / 6.0;
      const double b2 = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6.0;
      const double b3 = t * t * t / 6.0;
      const Vec2 sum = points[segment].to_vec() * b0 + points[segment + 1].to_vec() * b1 +
                       points[segment + 2].to_vec() * b2 + points[segment + 3].to_vec() * b3;
      // Points within [-10, 10]: a few roundings of magnitude 10 each.
      REQUIRE(spline->eval(3.0 + static_cast<double>(segment) + t).distance(Point::from_vec(sum)) <= 1e-13);
    }
  }
}

TEST_CASE("Outside the domain the end polynomial is extended, and NaN gives NaN", "[bspline][eval]") {
  std::mt19937_64 rng(7004);
  const BSpline spline = test::random_bspline(rng, 3, false);
  // Continuity across the domain ends: the extension is the same polynomial, so a 1e-9 step moves the
  // point by about |C'| * 1e-9 (|C'| is O(10) for these splines).
  const double a = spline.domain_start(), b = spline.domain_end();
  REQUIRE(spline.eval(a - 1e-9).distance(spline.eval(a)) <= 1e-7);
  REQUIRE(spline.eval(b + 1e-9).distance(spline.eval(b)) <= 1e-7);
  const Point nan_point = spline.eval(std::nan(""));
  REQUIRE(std::isnan(nan_point.x));
  REQUIRE(std::isnan(nan_point.y));
}

}  // namespace
}  // namespace curvescan
