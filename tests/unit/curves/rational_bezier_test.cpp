// RationalBezier: homogeneous split/subsegment, quotient-rule derivative, reversal, conic helper
// (rational_bezier.h).
#include "curvescan/curves/rational_bezier.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "random_curves.h"

using curvescan::Point;
using curvescan::RationalBezier;
using curvescan::Vec2;

namespace {

// Coordinates <= 100, weights in [0.2, 5]: the projected points carry ~n lerps of rounding amplified by
// at most the weight ratio 25, ~1e-14 relative; 1e-11 relative to the coordinate scale keeps a margin of
// 1000 while any algebra slip is O(1).
constexpr double kRel = 1e-11;

}  // namespace

TEST_CASE("rational split: halves reproduce the curve, weights stay positive, shared point exact",
          "[rational][split]") {
  std::mt19937_64 rng(60606);
  std::uniform_real_distribution<double> param(0.0, 1.0);
  for (int degree = 1; degree <= 8; ++degree) {
    for (int trial = 0; trial < 20; ++trial) {
      const RationalBezier curve = curvescan::test::random_rational(rng, degree);
      const double scale = curvescan::test::coordinate_scale(curve.points());
      const double t = param(rng);
      const auto [left, right] = curve.split(t);
      REQUIRE(left.degree() == degree);
      REQUIRE(right.degree() == degree);
      REQUIRE(left.points().back() == curve.eval(t));
      REQUIRE(right.points().front() == curve.eval(t));
      for (double w : left.weights()) REQUIRE(w > 0.0);
      for (double w : right.weights()) REQUIRE(w > 0.0);
      for (int k = 0; k <= 16; ++k) {
        const double s = k / 16.0;
        REQUIRE(left.eval(s).distance(curve.eval(s * t)) <= kRel * scale);
        REQUIRE(right.eval(s).distance(curve.eval(t + s * (1 - t))) <= kRel * scale);
      }
    }
  }
}

TEST_CASE("rational subsegment and reversed reproduce the curve", "[rational][split]") {
  std::mt19937_64 rng(70707);
  std::uniform_real_distribution<double> param(0.0, 1.0);
  for (int degree = 1; degree <= 8; ++degree) {
    for (int trial = 0; trial < 20; ++trial) {
      const RationalBezier curve = curvescan::test::random_rational(rng, degree);
      const double scale = curvescan::test::coordinate_scale(curve.points());
      const double t0 = param(rng), t1 = param(rng);
      const RationalBezier piece = curve.subsegment(t0, t1);
      const RationalBezier back = curve.reversed();
      REQUIRE(piece.points().front() == curve.eval(t0));
      REQUIRE(piece.points().back() == curve.eval(t1));
      for (int k = 0; k <= 16; ++k) {
        const double s = k / 16.0;
        REQUIRE(piece.eval(s).distance(curve.eval(t0 + s * (t1 - t0))) <= kRel * scale);
        REQUIRE(back.eval(s).distance(curve.eval(1.0 - s)) <= kRel * scale);
      }
    }
  }
}

TEST_CASE("rational deriv_at matches central finite differences", "[rational][deriv]") {
  std::mt19937_64 rng(80808);
  std::uniform_real_distribution<double> param(0.05, 0.95);
  constexpr double kStep = 1e-6;
  for (int degree = 1; degree <= 6; ++degree) {
    for (int trial = 0; trial < 30; ++trial) {
      const RationalBezier curve = curvescan::test::random_rational(rng, degree, 1.0);
      for (int k = 0; k < 10; ++k) {
        const double t = param(rng);
        const Vec2 fd = (curve.eval(t + kStep) - curve.eval(t - kStep)) / (2 * kStep);
        const Vec2 exact = curve.deriv_at(t);
        // Error h²/6 |R'''| + ε|R|/h. A weight ratio of 25 lets |R'''| reach ~1e4–1e5 for these degrees,
        // so truncation <= 1e-12/6 · 1e5 ≈ 2e-8 and rounding ≈ 1e-16/1e-6 = 1e-10: 1e-5 relative to
        // max(1, |R'|) is generous, and a missing quotient-rule term is O(|R'|).
        REQUIRE((fd - exact).length() <= 1e-5 * std::max(1.0, exact.length()));
      }
    }
  }
}

TEST_CASE("rational conic helper: w = cos(φ/2) with equal legs is a circular arc", "[rational][conic]") {
  // Quarter circle of radius 2 about the origin: tangents at (2,0) and (0,2) meet at (2,2), w = cos 45°.
  const RationalBezier quarter =
      RationalBezier::conic({2, 0}, {2, 2}, {0, 2}, std::cos(std::numbers::pi / 4));
  REQUIRE(quarter.degree() == 2);
  for (int k = 0; k <= 100; ++k) {
    // Radius 2 rounded at ~1e-16 through ~10 operations: 1e-14 is ample.
    REQUIRE(quarter.eval(k / 100.0).distance({0, 0}) == Approx(2.0).epsilon(1e-14));
  }
  // End tangents of a rational quadratic point along the legs, with speed 2·w·|leg| (w_0 = w_2 = 1).
  const Vec2 start_tangent = quarter.deriv_at(0.0);
  REQUIRE(start_tangent.x == Approx(0.0).margin(1e-14));
  REQUIRE(start_tangent.y == Approx(2.0 * std::cos(std::numbers::pi / 4) * 2.0).epsilon(1e-14));
  // w = 1 is the polynomial parabola: its midpoint is (P0 + 2 P1 + P2) / 4.
  const RationalBezier parabola = RationalBezier::conic({0, 0}, {1, 2}, {2, 0}, 1.0);
  REQUIRE(parabola.eval(0.5) == Point{1.0, 1.0});
}

TEST_CASE("rational: invalid curves are total", "[rational]") {
  const RationalBezier mismatched({{0, 0}, {1, 1}}, {1.0});
  REQUIRE(std::isnan(mismatched.deriv_at(0.5).x));
  REQUIRE(mismatched.split(0.5).first.points().empty());
  REQUIRE(mismatched.subsegment(0.1, 0.2).points().empty());
  REQUIRE(std::isnan(mismatched.arc_length(1e-6)));
  REQUIRE(RationalBezier({{1, 1}}, {2.0}).deriv_at(0.3) == Vec2{0, 0});
}
