// Arc length by adaptive Gauss–Legendre quadrature: exactness, convergence, the requested accuracy
// (bezier.h, rational_bezier.h).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "curvescan/curves/arc.h"
#include "curvescan/curves/bezier.h"
#include "curvescan/curves/rational_bezier.h"
#include "random_curves.h"

using curvescan::Bezier;
using curvescan::Point;
using curvescan::RationalBezier;

namespace {

constexpr double kPi = std::numbers::pi;

double polyline_length(const Bezier& curve, int segments) {
  double length = 0.0;
  Point previous = curve.eval(0.0);
  for (int k = 1; k <= segments; ++k) {
    const Point p = curve.eval(k / double(segments));
    length += previous.distance(p);
    previous = p;
  }
  return length;
}

}  // namespace

TEST_CASE("arc length: exact for a monotone collinear curve whose speed is a degree-15 polynomial",
          "[bezier][arc_length]") {
  // Control x increasing on a line: B'(t) >= 0 along x, so |B'| = x'(t) is a polynomial of degree n - 1 and
  // the 8-point Gauss–Legendre rule integrates degree <= 15 exactly. Degree 16 is thus the hardest exact
  // case; any wrong node or weight digit shows at ~1e-10, far above the rounding (~1e-14) allowed here.
  std::vector<Point> ctrl;
  double x = 0.0;
  std::mt19937_64 rng(16);
  std::uniform_real_distribution<double> step(0.1, 3.0);
  for (int i = 0; i <= 16; ++i) {
    ctrl.push_back({x, 0.5 * x});
    x += step(rng);
  }
  const Bezier curve(ctrl);
  const double exact = ctrl.front().distance(ctrl.back());
  REQUIRE(curve.arc_length(1e-300) == Approx(exact).epsilon(1e-13));
}

TEST_CASE("arc length: circle arcs as conics have length r·|sweep|", "[rational][arc_length]") {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> angle(-2 * kPi, 2 * kPi);
  std::uniform_real_distribution<double> radius(0.1, 100.0);
  for (int trial = 0; trial < 50; ++trial) {
    const double r = radius(rng), sweep = angle(rng);
    double total = 0.0;
    for (const RationalBezier& conic :
         curvescan::elliptical_arc_conics({3, 4}, r, r, 0.4, angle(rng), sweep)) {
      total += conic.arc_length(1e-12 * r);
    }
    // Requested 1e-12·r per piece (<= 4 pieces); the conic's radius error is ~1e-15 relative.
    REQUIRE(std::abs(total - r * std::abs(sweep)) <= 1e-11 * r);
  }
}

TEST_CASE("arc length: polylines converge to it from below at second order", "[bezier][arc_length]") {
  std::mt19937_64 rng(55);
  for (int degree = 2; degree <= 7; ++degree) {
    const Bezier curve = curvescan::test::random_bezier(rng, degree);
    const double length = curve.arc_length(1e-10);
    double previous_gap = 0.0;
    for (int segments = 64; segments <= 4096; segments *= 4) {
      const double gap = length - polyline_length(curve, segments);
      // A chord is never longer than its arc (allow rounding of the sums, ~1e-12 of lengths ~1000).
      REQUIRE(gap >= -1e-9);
      // Chord error is O(h²): quadrupling the segments divides the gap by ~16; demand at least 8 (a wrong
      // length would stall the gap at the error instead).
      if (previous_gap > 1e-7) REQUIRE(gap < previous_gap / 8);
      previous_gap = gap;
    }
    REQUIRE(previous_gap <= 1e-3 * length);
  }
}

TEST_CASE("arc length: honours the requested accuracy, also across a cusp", "[bezier][arc_length]") {
  // (0,0),(1,1),(0,1),(1,0): x'(t) and y'(t) vanish together at t = 1/2, a cusp where |B'| has a kink that
  // Gauss–Legendre does not resolve without subdivision.
  const Bezier cusp({{0, 0}, {1, 1}, {0, 1}, {1, 0}});
  const double reference = cusp.arc_length(1e-13);
  for (double accuracy : {1e-2, 1e-4, 1e-6, 1e-9}) {
    REQUIRE(std::abs(cusp.arc_length(accuracy) - reference) <= accuracy);
  }
  // Independent check on the reference: a polyline of 2^16 chords undershoots by O(h²) ≈ 1e-9.
  REQUIRE(reference - polyline_length(cusp, 1 << 16) <= 1e-7);
  REQUIRE(reference - polyline_length(cusp, 1 << 16) >= 0.0);
}

TEST_CASE("arc length: degenerate input", "[bezier][arc_length]") {
  REQUIRE(std::isnan(Bezier().arc_length(1e-6)));
  REQUIRE(Bezier({{1, 2}}).arc_length(1e-6) == 0.0);
  REQUIRE(Bezier({{1, 2}, {1, 2}, {1, 2}}).arc_length(1e-6) == 0.0);
  REQUIRE(std::isnan(Bezier({{0, 0}, {std::nan(""), 0}}).arc_length(1e-6)));
  // NaN or non-positive accuracy: best effort within the work bound, still the right answer for a line.
  REQUIRE(Bezier({{0, 0}, {3, 4}}).arc_length(std::nan("")) == Approx(5.0).epsilon(1e-15));
  REQUIRE(Bezier({{0, 0}, {3, 4}}).arc_length(-1.0) == Approx(5.0).epsilon(1e-15));
}
