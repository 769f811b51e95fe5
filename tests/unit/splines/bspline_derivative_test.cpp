// BSpline::derivative (degree p-1, coefficients p (P_{i+1} - P_i)/(u_{i+p+1} - u_{i+1})) against central
// finite differences of the curve itself.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "curvescan/curves/bspline.h"
#include "random_spline.h"

namespace curvescan {
namespace {

// Central difference with step h: truncation error h^2/6 |C'''| plus rounding about eps |C| / h.
// Points in [-1, 1], spans >= 0.5 and p <= 5 bound |C'''| by about p^3 * 2 / 0.5^3 = 2000 for the
// derivative of C and |C''''| similarly for the second derivative test. With h = 1e-5: truncation
// <= 4e-8, rounding <= 1e-16 / 1e-5 * 10 = 1e-10. Tolerance 1e-6 is 25x above the bound.
constexpr double kStep = 1e-5;
constexpr double kTolerance = 1e-6;

// A parameter at least 2h away from every knot, so the stencil stays on one polynomial piece.
bool away_from_knots(const BSpline& spline, double u) {
  for (const double knot : spline.knots()) {
    if (std::abs(u - knot) < 2 * kStep) return false;
  }
  return true;
}

Vec2 central_difference(const BSpline& spline, double u) {
  return (spline.eval(u + kStep) - spline.eval(u - kStep)) / (2 * kStep);
}

TEST_CASE("B-spline derivative matches central differences", "[bspline][derivative]") {
  std::mt19937_64 rng(8001);
  for (int degree = 1; degree <= 5; ++degree) {
    for (int trial = 0; trial < 40; ++trial) {
      const BSpline spline = test::random_bspline(rng, degree, trial % 2 == 0);
      const BSpline first = spline.derivative();
      REQUIRE(first.degree() == degree - 1);
      REQUIRE(first.domain_start() == spline.domain_start());
      REQUIRE(first.domain_end() == spline.domain_end());
      const BSpline second = first.derivative();
      for (const double u : test::sample_parameters(rng, spline, 30)) {
        if (!away_from_knots(spline, u)) continue;
        INFO("degree " << degree << " trial " << trial << " u " << u);
        const Vec2 analytic = first.eval(u).to_vec();
        REQUIRE((analytic - central_difference(spline, u)).length() <= kTolerance);
        if (degree >= 2) {
          const Vec2 analytic2 = second.eval(u).to_vec();
          REQUIRE((analytic2 - central_difference(first, u)).length() <= kTolerance);
        }
      }
    }
  }
}

TEST_CASE("Clamped end tangents are p (P1 - P0) / (u_{p+1} - u_1)", "[bspline][derivative]") {
  std::mt19937_64 rng(8002);
  const auto points = test::random_points(rng, 7);
  auto spline = BSpline::clamped(points, 3);
  REQUIRE(spline.is_ok());
  const auto knots = spline->knots();
  const Vec2 expected = (points[1] - points[0]) * (3.0 / (knots[4] - knots[1]));
  // Exact formula on both sides, one extra rounding in the de Boor of the derivative.
  REQUIRE((spline->derivative().eval(0.0).to_vec() - expected).length() <= 1e-13);
}

TEST_CASE("The derivative of a degree-0 spline is zero", "[bspline][derivative]") {
  auto spline = BSpline::create({{1, 2}, {3, 4}}, {0, 1, 2}, 0);
  REQUIRE(spline.is_ok());
  const BSpline derivative = spline->derivative();
  REQUIRE(derivative.degree() == 0);
  REQUIRE(derivative.eval(0.5) == Point{0, 0});
  REQUIRE(derivative.eval(1.5) == Point{0, 0});
}

}  // namespace
}  // namespace curvescan
