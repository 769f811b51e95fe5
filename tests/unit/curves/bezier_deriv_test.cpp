// Bezier::deriv (the hodograph) against central finite differences (bezier.h).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "curvescan/curves/bezier.h"
#include "random_curves.h"

using curvescan::Bezier;
using curvescan::Point;
using curvescan::Vec2;

TEST_CASE("bezier deriv: hodograph matches central finite differences", "[bezier][deriv]") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> param(0.05, 0.95);
  constexpr double kStep = 1e-5;
  for (int degree = 1; degree <= 7; ++degree) {
    for (int trial = 0; trial < 30; ++trial) {
      const Bezier curve = curvescan::test::random_bezier(rng, degree, 1.0);
      const Bezier hodograph = curve.deriv();
      REQUIRE(hodograph.degree() == degree - 1);
      for (int k = 0; k < 10; ++k) {
        const double t = param(rng);
        const Vec2 fd = (curve.eval(t + kStep) - curve.eval(t - kStep)) / (2 * kStep);
        const Vec2 exact = hodograph.eval(t).to_vec();
        // Central differences err by h²/6 |B'''| + ε|B|/h. With |P| <= 1, |B'''| <= n(n-1)(n-2)·8 <= 1680
        // for n <= 7, so truncation <= 1e-10/6 · 1680 ≈ 3e-8 and rounding ≈ 1e-16/1e-5 = 1e-11: 1e-6
        // bounds both with a wide margin, yet a wrong factor n would miss by O(1).
        REQUIRE((fd - exact).length() <= 1e-6);
      }
    }
  }
}

TEST_CASE("bezier deriv: end derivatives are n times the end legs (Dill, *Introduction to Parametric Curves*, 'Joining Bezier Curves')",
          "[bezier][deriv]") {
  const Bezier cubic({{0, 0}, {1, 2}, {4, 2}, {5, 0}});
  const Bezier d = cubic.deriv();
  REQUIRE(d.eval(0.0) == Point{3, 6});   // 3 (P1 - P0)
  REQUIRE(d.eval(1.0) == Point{3, -6});  // 3 (P3 - P2)
  const Bezier second = d.deriv();
  REQUIRE(second.degree() == 1);
  REQUIRE(second.eval(0.0) == Point{6 * (0 - 2 + 4), 6 * (0 - 4 + 2)});  // 6 (P0 - 2P1 + P2)
}

TEST_CASE("bezier deriv: degenerate curves", "[bezier][deriv]") {
  REQUIRE(Bezier({{3, 4}}).deriv() == Bezier({{0, 0}}));
  REQUIRE(Bezier().deriv().points().empty());
  const Bezier line({{1, 1}, {4, 5}});
  REQUIRE(line.deriv() == Bezier({{3, 4}}));
}
