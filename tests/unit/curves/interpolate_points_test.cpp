// Interpolating quadratics and cubics, and power form to Bézier (interpolate_points.h; Ince, *Curves*
// "Representations of Curves: Parametric Representation").
#include "curvescan/curves/interpolate_points.h"

#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

using curvescan::Point;
using curvescan::Vec2;

TEST_CASE("interpolate: Ince, *Curves*, worked examples", "[interpolate]") {
  // Endpoints (0,0) and (3,3), (3,8) on the curve at t = 0.5: a = (-6,-26), b = (9,29), c = (0,0).
  const auto half = curvescan::interpolate_quadratic({0, 0}, {3, 8}, {3, 3}, 0.5);
  REQUIRE(half.has_value());
  // The arithmetic is on small binary fractions except the division by t(1-t): a few ulps of 26.
  REQUIRE(half->a.x == Approx(-6.0).epsilon(1e-14));
  REQUIRE(half->a.y == Approx(-26.0).epsilon(1e-14));
  REQUIRE(half->b.x == Approx(9.0).epsilon(1e-14));
  REQUIRE(half->b.y == Approx(29.0).epsilon(1e-14));
  REQUIRE(half->c == Point{0, 0});
  // The same points with t = 0.2: a = (-15,-46.25), b = (18,49.25).
  const auto fifth = curvescan::interpolate_quadratic({0, 0}, {3, 8}, {3, 3}, 0.2);
  REQUIRE(fifth.has_value());
  REQUIRE(fifth->a.x == Approx(-15.0).epsilon(1e-14));
  REQUIRE(fifth->a.y == Approx(-46.25).epsilon(1e-14));
  REQUIRE(fifth->b.x == Approx(18.0).epsilon(1e-14));
  REQUIRE(fifth->b.y == Approx(49.25).epsilon(1e-14));
}

TEST_CASE("interpolate: the quadratic passes through its points and converts to the same Bézier",
          "[interpolate]") {
  std::mt19937_64 rng(1001);
  std::uniform_real_distribution<double> coord(-50.0, 50.0);
  std::uniform_real_distribution<double> param(0.05, 0.95);
  for (int trial = 0; trial < 200; ++trial) {
    const Point p0{coord(rng), coord(rng)}, p1{coord(rng), coord(rng)}, p2{coord(rng), coord(rng)};
    const double t1 = param(rng);
    const auto q = curvescan::interpolate_quadratic(p0, p1, p2, t1);
    REQUIRE(q.has_value());
    // Dividing by t1(1 - t1) >= 0.0475 amplifies rounding of coordinates ~50 by ~20: 1e-11 is ~1000x that.
    REQUIRE(q->eval(0.0).distance(p0) <= 1e-11);
    REQUIRE(q->eval(t1).distance(p1) <= 1e-11);
    REQUIRE(q->eval(1.0).distance(p2) <= 1e-11);
    const curvescan::Bezier bezier = q->to_bezier();
    REQUIRE(bezier.degree() == 2);
    for (int k = 0; k <= 10; ++k) REQUIRE(bezier.eval(k / 10.0).distance(q->eval(k / 10.0)) <= 1e-10);
  }
  // Singular interpolation matrix: the middle parameter on an endpoint, or not a number.
  REQUIRE(!curvescan::interpolate_quadratic({0, 0}, {1, 1}, {2, 0}, 0.0).has_value());
  REQUIRE(!curvescan::interpolate_quadratic({0, 0}, {1, 1}, {2, 0}, 1.0).has_value());
  REQUIRE(!curvescan::interpolate_quadratic({0, 0}, {1, 1}, {2, 0}, std::nan("")).has_value());
}

TEST_CASE("interpolate: the cubic interpolation matrix inverts the Vandermonde matrix", "[interpolate]") {
  std::mt19937_64 rng(2002);
  std::uniform_real_distribution<double> param(-1.0, 2.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::array<double, 4> t{param(rng), param(rng), param(rng), param(rng)};
    const auto inverse = curvescan::cubic_interpolation_matrix(t);
    REQUIRE(inverse.has_value());
    double conditioning = 1.0;  // rounding grows like 1 / min |t_j - t_k|³ for the Lagrange denominators
    for (std::size_t j = 0; j < 4; ++j) {
      for (std::size_t k = 0; k < j; ++k) conditioning = std::max(conditioning, 1.0 / std::abs(t[j] - t[k]));
    }
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t j = 0; j < 4; ++j) {
        // V[i][k] = t_i^(3-k); (V · M)[i][j] = sum_k V[i][k] M[k][j] = L_j(t_i) = δ_ij.
        const double row[4] = {t[i] * t[i] * t[i], t[i] * t[i], t[i], 1.0};
        double sum = 0.0;
        for (std::size_t k = 0; k < 4; ++k) sum += row[k] * (*inverse)[k][j];
        REQUIRE(std::abs(sum - (i == j ? 1.0 : 0.0)) <= 1e-13 * std::pow(conditioning, 3));
      }
    }
  }
  REQUIRE(!curvescan::cubic_interpolation_matrix({0.0, 0.3, 0.3, 1.0}).has_value());
  REQUIRE(!curvescan::cubic_interpolation_matrix({0.0, 0.3, INFINITY, 1.0}).has_value());
}

TEST_CASE("interpolate: the cubic passes through four points — points of a quadratic give a = 0",
          "[interpolate]") {
  const std::array<double, 4> t{0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0};
  const std::array<Point, 4> points{Point{0, 0}, Point{1, 2}, Point{3, 3}, Point{4, 0}};
  const auto cubic = curvescan::interpolate_cubic(points, t);
  REQUIRE(cubic.has_value());
  // Uniform parameters in [0, 1]: the Lagrange denominators are >= 2/27, so rounding stays ~1e-14.
  for (std::size_t k = 0; k < 4; ++k) REQUIRE(cubic->eval(t[k]).distance(points[k]) <= 1e-13);
  const curvescan::Bezier bezier = cubic->to_bezier();
  for (int k = 0; k <= 10; ++k) REQUIRE(bezier.eval(k / 10.0).distance(cubic->eval(k / 10.0)) <= 1e-13);

  const auto q = curvescan::interpolate_quadratic({0, 0}, {3, 8}, {3, 3}, 0.5);
  const std::array<double, 4> s{0.0, 0.25, 0.6, 1.0};
  const auto through_quadratic =
      curvescan::interpolate_cubic({q->eval(s[0]), q->eval(s[1]), q->eval(s[2]), q->eval(s[3])}, s);
  REQUIRE(through_quadratic->a.length() <= 1e-12);
  REQUIRE((through_quadratic->b - q->a).length() <= 1e-12);
  REQUIRE((through_quadratic->c - q->b).length() <= 1e-12);
  REQUIRE(!curvescan::interpolate_cubic(points, {0.0, 0.5, 0.5, 1.0}).has_value());
}

TEST_CASE("interpolate: power form to Bézier for degrees 0..8", "[interpolate]") {
  std::mt19937_64 rng(3003);
  std::uniform_real_distribution<double> coord(-5.0, 5.0);
  for (std::size_t degree = 0; degree <= 8; ++degree) {
    std::vector<Vec2> coefficients(degree + 1);
    for (Vec2& c : coefficients) c = {coord(rng), coord(rng)};
    const curvescan::Bezier bezier = curvescan::power_to_bezier(coefficients);
    REQUIRE(bezier.degree() == static_cast<int>(degree));
    for (int k = 0; k <= 20; ++k) {
      const double t = k / 20.0;
      Vec2 horner{0, 0};
      for (std::size_t j = coefficients.size(); j-- > 0;) horner = horner * t + coefficients[j];
      // Coefficients <= 5, degree <= 8: sums of <= 45 terms of size <= 5·C(8,4) = 350, rounding ~1e-13.
      REQUIRE(bezier.eval(t).distance(Point::from_vec(horner)) <= 1e-11);
    }
  }
  REQUIRE(curvescan::power_to_bezier({}).points().empty());
}
