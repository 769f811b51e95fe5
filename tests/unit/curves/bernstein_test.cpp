// The Bernstein basis and the Bernstein-sum evaluation, the reference de Casteljau is held to (bezier.h).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "curvescan/curves/bezier.h"

using curvescan::bernstein;
using curvescan::Bezier;
using curvescan::Point;

TEST_CASE("bernstein: partition of unity and non-negativity on [0, 1]", "[bernstein]") {
  for (int n = 0; n <= 20; ++n) {
    for (int k = 0; k <= 200; ++k) {
      const double t = k / 200.0;
      double sum = 0.0;
      for (int i = 0; i <= n; ++i) {
        const double b = bernstein(n, i, t);
        REQUIRE(b >= 0.0);
        REQUIRE(b <= 1.0);
        sum += b;
      }
      // n + 1 terms each rounded at ~2 ulp (the binomial is exact for n <= 20, the powers are not):
      // 1e-14 bounds (n + 1) · 4 · 1.1e-16 with room to spare.
      REQUIRE(sum == Approx(1.0).margin(1e-14));
    }
  }
}

TEST_CASE("bernstein: out-of-range indices are zero, NaN parameter is NaN, end values are Kronecker",
          "[bernstein]") {
  REQUIRE(bernstein(3, -1, 0.5) == 0.0);
  REQUIRE(bernstein(3, 4, 0.5) == 0.0);
  REQUIRE(bernstein(-1, 0, 0.5) == 0.0);
  REQUIRE(std::isnan(bernstein(3, 0, std::nan(""))));
  REQUIRE(std::isnan(bernstein(0, 0, std::nan(""))));
  for (int n = 1; n <= 8; ++n) {
    for (int i = 0; i <= n; ++i) {
      REQUIRE(bernstein(n, i, 0.0) == (i == 0 ? 1.0 : 0.0));
      REQUIRE(bernstein(n, i, 1.0) == (i == n ? 1.0 : 0.0));
    }
  }
  // The cubic blending functions of U. of Toronto, *Parametric Curves*, "Bezier Curves": f2(t) = 3t(1-t)², at t = 1/3 exactly 4/9.
  REQUIRE(bernstein(3, 1, 1.0 / 3.0) == Approx(4.0 / 9.0).epsilon(1e-15));
}

TEST_CASE("bernstein: de Casteljau equals the Bernstein sum for random curves of degree 1..10",
          "[bernstein]") {
  std::mt19937_64 rng(1234567);
  std::uniform_real_distribution<double> coord(-100.0, 100.0);
  std::uniform_real_distribution<double> param(0.0, 1.0);
  for (int degree = 1; degree <= 10; ++degree) {
    for (int trial = 0; trial < 50; ++trial) {
      std::vector<Point> ctrl(static_cast<std::size_t>(degree) + 1);
      double scale = 0.0;
      for (Point& p : ctrl) {
        p = {coord(rng), coord(rng)};
        scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
      }
      const Bezier curve(ctrl);
      for (int k = 0; k < 20; ++k) {
        const double t = param(rng);
        const Point a = curve.eval(t);
        const Point b = curvescan::eval_bernstein(ctrl, t);
        // Both are convex combinations of the control points; each accumulates O(n) roundings of size
        // ~1.1e-16 · scale, so 1e-12 relative to the largest coordinate leaves a margin of ~1000.
        REQUIRE(std::abs(a.x - b.x) <= 1e-12 * scale);
        REQUIRE(std::abs(a.y - b.y) <= 1e-12 * scale);
      }
    }
  }
}

TEST_CASE("bernstein: empty control polygon evaluates to NaN", "[bernstein]") {
  const Point p = curvescan::eval_bernstein({}, 0.5);
  REQUIRE(std::isnan(p.x));
  REQUIRE(std::isnan(p.y));
}
