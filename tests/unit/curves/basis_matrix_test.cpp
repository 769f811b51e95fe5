// The cubic basis matrices reproduce their curves: T·M·G against de Casteljau, the Hermite definition,
// the uniform B-spline blending functions and the constraints of U. of Toronto, *Parametric Curves*'s first example (basis_matrix.h).
#include "curvescan/curves/basis_matrix.h"

#include <array>
#include <catch2/catch.hpp>
#include <random>

#include "curvescan/curves/bezier.h"

using curvescan::BasisMatrix;
using curvescan::Bezier;
using curvescan::Point;
using curvescan::Vec2;

namespace {

// Products of small integers (or sixths) with t³ in [0, 1] and coordinates <= 10: a few ulps of 10.
constexpr double kTol = 1e-13;

// The constraint matrix rows times M must be the identity: M is the inverse of the constraints.
void require_inverse(const BasisMatrix& constraints, const BasisMatrix& m) {
  for (std::size_t i = 0; i < 4; ++i) {
    for (std::size_t j = 0; j < 4; ++j) {
      double sum = 0.0;
      for (std::size_t k = 0; k < 4; ++k) sum += constraints[i][k] * m[k][j];
      REQUIRE(sum == Approx(i == j ? 1.0 : 0.0).margin(1e-15));
    }
  }
}

std::array<Vec2, 4> random_geometry(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> coord(-10.0, 10.0);
  std::array<Vec2, 4> g{};
  for (Vec2& v : g) v = {coord(rng), coord(rng)};
  return g;
}

}  // namespace

TEST_CASE("basis: Bézier T·M_b·G equals de Casteljau", "[basis]") {
  std::mt19937_64 rng(404);
  for (int trial = 0; trial < 100; ++trial) {
    const auto g = random_geometry(rng);
    const Bezier curve(
        {Point::from_vec(g[0]), Point::from_vec(g[1]), Point::from_vec(g[2]), Point::from_vec(g[3])});
    for (int k = 0; k <= 20; ++k) {
      const double t = k / 20.0;
      REQUIRE(curvescan::eval_basis(curvescan::kBezierBasis, t, g).distance(curve.eval(t)) <= kTol);
    }
  }
  // And its blending functions are the cubic Bernstein polynomials (U. of Toronto, *Parametric Curves*, "f1(t) = (1-t)^3 ...").
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    const auto f = curvescan::blending_functions(curvescan::kBezierBasis, t);
    for (int i = 0; i < 4; ++i)
      REQUIRE(f[static_cast<std::size_t>(i)] == Approx(curvescan::bernstein(3, i, t)).margin(1e-15));
  }
}

TEST_CASE("basis: Hermite T·M_h·G interpolates end points and end tangents", "[basis]") {
  // U. of Toronto, *Parametric Curves*, "Hermite Curves": constraints x(0), x(1), x'(0), x'(1) as rows on [a b c d].
  const BasisMatrix constraints{{{0, 0, 0, 1}, {1, 1, 1, 1}, {0, 0, 1, 0}, {3, 2, 1, 0}}};
  require_inverse(constraints, curvescan::kHermiteBasis);
  std::mt19937_64 rng(505);
  for (int trial = 0; trial < 50; ++trial) {
    const auto g = random_geometry(rng);  // [P0 P1 R0 R1]
    const auto at = [&](double t) { return curvescan::eval_basis(curvescan::kHermiteBasis, t, g); };
    REQUIRE(at(0.0).distance(Point::from_vec(g[0])) <= kTol);
    REQUIRE(at(1.0).distance(Point::from_vec(g[1])) <= kTol);
    // One-sided differences of a cubic: error h/2·|x''| <= 1e-6/2 · ~200; the step is small enough that
    // 1e-3 separates a right tangent from a wrong one (|R| ~ 10).
    constexpr double h = 1e-6;
    REQUIRE(((at(h) - at(0.0)) / h - g[2]).length() <= 1e-3);
    REQUIRE(((at(1.0) - at(1.0 - h)) / h - g[3]).length() <= 1e-3);
  }
  // The blending functions of U. of Toronto, *Parametric Curves*: f1 = 2t³-3t²+1, f2 = -2t³+3t², f3 = t³-2t²+t, f4 = t³-t².
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0;
    const auto f = curvescan::blending_functions(curvescan::kHermiteBasis, t);
    REQUIRE(f[0] == Approx(2 * t * t * t - 3 * t * t + 1).margin(1e-15));
    REQUIRE(f[1] == Approx(-2 * t * t * t + 3 * t * t).margin(1e-15));
    REQUIRE(f[2] == Approx(t * t * t - 2 * t * t + t).margin(1e-15));
    REQUIRE(f[3] == Approx(t * t * t - t * t).margin(1e-15));
  }
}

TEST_CASE("basis: uniform B-spline blending functions, partition of unity and C2 joins", "[basis]") {
  for (int k = 0; k <= 20; ++k) {
    const double t = k / 20.0, u = 1.0 - t;
    const auto f = curvescan::blending_functions(curvescan::kUniformBSplineBasis, t);
    // The uniform cubic B-spline blending functions (Dill, *Introduction to Parametric Curves*, "B-Spline Curves" plots them; the closed
    // forms are the uniform basis N_{i,4} restricted to one knot span).
    REQUIRE(f[0] == Approx(u * u * u / 6).margin(1e-15));
    REQUIRE(f[1] == Approx((3 * t * t * t - 6 * t * t + 4) / 6).margin(1e-15));
    REQUIRE(f[2] == Approx((-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6).margin(1e-15));
    REQUIRE(f[3] == Approx(t * t * t / 6).margin(1e-15));
    REQUIRE(f[0] + f[1] + f[2] + f[3] == Approx(1.0).margin(1e-15));  // Dill, *Introduction to Parametric Curves*: "sum = 1"
    for (double b : f) REQUIRE(b >= 0.0);                             // and non-negative
  }
  // Two consecutive segments of a 5-point control polygon meet with equal position, velocity and
  // acceleration (Dill, *Introduction to Parametric Curves*: "can show C0, C1 and C2 continuous"); compared with second differences.
  std::mt19937_64 rng(606);
  std::uniform_real_distribution<double> coord(-10.0, 10.0);
  std::array<Vec2, 5> p{};
  for (Vec2& v : p) v = {coord(rng), coord(rng)};
  const std::array<Vec2, 4> first{p[0], p[1], p[2], p[3]}, second{p[1], p[2], p[3], p[4]};
  const auto a = [&](double t) { return curvescan::eval_basis(curvescan::kUniformBSplineBasis, t, first); };
  const auto b = [&](double t) { return curvescan::eval_basis(curvescan::kUniformBSplineBasis, t, second); };
  REQUIRE(a(1.0).distance(b(0.0)) <= kTol);
  // Each segment is a cubic polynomial, defined beyond its span too, so central differences at the join
  // are exact up to rounding: the first has error h²/6·|x'''| (|x'''| <= 80 for coordinates <= 10, so
  // <= 1.4e-7) plus ε·10/h ≈ 1e-11; the second difference of a cubic is exact, leaving rounding
  // 4ε·10/h² ≈ 1e-6. A C1- or C2-breaking basis would differ by O(1).
  constexpr double h = 1e-4;
  const Vec2 velocity_a = (a(1.0 + h) - a(1.0 - h)) / (2 * h);
  const Vec2 velocity_b = (b(h) - b(-h)) / (2 * h);
  REQUIRE((velocity_a - velocity_b).length() <= 1e-6);
  const Vec2 accel_a = ((a(1.0 + h) - a(1.0)) - (a(1.0) - a(1.0 - h))) / (h * h);
  const Vec2 accel_b = ((b(h) - b(0.0)) - (b(0.0) - b(-h))) / (h * h);
  REQUIRE((accel_a - accel_b).length() <= 1e-5);
}

TEST_CASE("basis: U. of Toronto, *Parametric Curves*, first example meets its constraints", "[basis]") {
  // x(0) = P0, x(0.5) = P0.5, x'(0.5) = T0.5, x(1) = P1 as rows on [a b c d].
  const BasisMatrix constraints{{{0, 0, 0, 1}, {0.125, 0.25, 0.5, 1}, {0.75, 1, 1, 0}, {1, 1, 1, 1}}};
  require_inverse(constraints, curvescan::kMidpointTangentBasis);
  std::mt19937_64 rng(707);
  const auto g = random_geometry(rng);  // [P0 P0.5 T0.5 P1]
  const auto at = [&](double t) { return curvescan::eval_basis(curvescan::kMidpointTangentBasis, t, g); };
  REQUIRE(at(0.0).distance(Point::from_vec(g[0])) <= kTol);
  REQUIRE(at(0.5).distance(Point::from_vec(g[1])) <= kTol);
  REQUIRE(at(1.0).distance(Point::from_vec(g[3])) <= kTol);
  // Central difference of a cubic: error h²/6·|x'''| = 1e-8/6 · ~500, rounding 1e-16·10/1e-4: 1e-6 covers it.
  constexpr double h = 1e-4;
  REQUIRE(((at(0.5 + h) - at(0.5 - h)) / (2 * h) - g[2]).length() <= 1e-6);
  // The last blending function vanishes at t = 0 (f4 = 4t³ - 4t² + t; the seed's "+ 1" is a typo).
  REQUIRE(curvescan::blending_functions(curvescan::kMidpointTangentBasis, 0.0)[3] == 0.0);
  REQUIRE(curvescan::blending_functions(curvescan::kMidpointTangentBasis, 0.3)[3] ==
          Approx(4 * 0.027 - 4 * 0.09 + 0.3).margin(1e-15));
}
