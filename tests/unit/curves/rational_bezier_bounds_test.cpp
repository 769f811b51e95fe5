// RationalBezier::bounding_box: contains the curve and is touched by it on all four sides; an arc's box is
// its circle's extent over the arc, not its control point's (rational_bezier.h).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "curvescan/curves/rational_bezier.h"
#include "random_curves.h"

using curvescan::Point;
using curvescan::RationalBezier;
using curvescan::Rect;
using curvescan::test::random_rational;
using curvescan::test::sampled_box;

namespace {

constexpr int kSamples = 20000;
// The box comes from eval() at computed roots: rounding ~1e-14 relative at coordinates ~100, amplified by
// the weight ratio (at most 25 here, random_rational) to ~1e-12.
constexpr double kContainSlack = 1e-10;

// How far the samples' box may stay inside the true one: near an extremum t*, a coordinate falls short of
// its extreme by at most max|x''| / 2 · Δt² with Δt <= 1 / (2 kSamples). max|x''| is measured on the
// samples by second differences (which underestimate it between samples, hence the factor 4).
double sampling_gap(const RationalBezier& curve) {
  const double h = 1.0 / kSamples;
  double second = 0.0;
  Point a = curve.eval(0.0), b = curve.eval(h);
  for (int k = 2; k <= kSamples; ++k) {
    const Point c = curve.eval(k * h);
    second =
        std::max({second, std::abs(a.x - 2 * b.x + c.x) / (h * h), std::abs(a.y - 2 * b.y + c.y) / (h * h)});
    a = b;
    b = c;
  }
  return 4.0 * second / 2.0 * (0.5 * h) * (0.5 * h) + kContainSlack;
}

void require_tight(const RationalBezier& curve) {
  curvescan::test::require_tight_box(curve.bounding_box(), sampled_box(curve, kSamples), kContainSlack,
                                     sampling_gap(curve));
}

}  // namespace

TEST_CASE("rational bounding box: a circular arc's box is the circle's extent over the arc",
          "[rational][bounds]") {
  // The unit circle's arc from -30 to 60 degrees as one conic: control point where the end tangents meet
  // (at distance 1 / cos 45 from the centre, x = 1.37), weight cos 45. The arc passes angle 0, where it
  // reaches x = 1: its box is [cos 60, 1] x [sin -30, sin 60], the control-point box 0.37 wider.
  const double a0 = -30.0 * std::numbers::pi / 180.0, a1 = 60.0 * std::numbers::pi / 180.0;
  const double half = 0.5 * (a1 - a0);
  const double mid = 0.5 * (a0 + a1);
  const Point p0{std::cos(a0), std::sin(a0)}, p2{std::cos(a1), std::sin(a1)};
  const Point p1{std::cos(mid) / std::cos(half), std::sin(mid) / std::cos(half)};
  const RationalBezier arc = RationalBezier::conic(p0, p1, p2, std::cos(half));
  const Rect box = arc.bounding_box();
  // Exact up to rounding of a few operations on numbers near 1.
  CHECK(box.x0 == Approx(std::cos(a1)).margin(1e-14));
  CHECK(box.x1 == Approx(1.0).margin(1e-14));
  CHECK(box.y0 == Approx(std::sin(a0)).margin(1e-14));
  CHECK(box.y1 == Approx(std::sin(a1)).margin(1e-14));

  // From -60 to 60 degrees: the rightmost point (1, 0) lies mid-arc, short of the control point at x = 2.
  const double h = 60.0 * std::numbers::pi / 180.0;
  const RationalBezier wide = RationalBezier::conic({std::cos(h), -std::sin(h)}, {1.0 / std::cos(h), 0.0},
                                                    {std::cos(h), std::sin(h)}, std::cos(h));
  const Rect wide_box = wide.bounding_box();
  CHECK(wide_box.x1 == Approx(1.0).margin(1e-14));
  CHECK(wide_box.x0 == Approx(0.5).margin(1e-14));
  CHECK(wide_box.y0 == Approx(-std::sin(h)).margin(1e-14));
  CHECK(wide_box.y1 == Approx(std::sin(h)).margin(1e-14));
}

TEST_CASE("rational bounding box: contains random rational curves and is touched on every side",
          "[rational][bounds]") {
  std::mt19937_64 rng(424242);
  for (int degree = 1; degree <= 7; ++degree) {
    for (int trial = 0; trial < 12; ++trial) {
      INFO("degree " << degree << " trial " << trial);
      require_tight(random_rational(rng, degree));
    }
  }
}

TEST_CASE("rational bounding box: invalid or non-finite curves give NaN, overflowing ones a valid bound",
          "[rational][bounds]") {
  CHECK(std::isnan(RationalBezier().bounding_box().x0));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK(std::isnan(RationalBezier({{0, 0}, {1, nan}, {2, 0}}, {1, 1, 1}).bounding_box().y1));
  // Coordinates whose differences overflow (1.6e308, times the binomials 2): the control points' extent on
  // that axis still bounds the curve, and the other axis stays tight.
  const RationalBezier huge({{-8e307, 0}, {8e307, 10}, {-8e307, 0}}, {1, 1, 1});
  const Rect box = huge.bounding_box();
  const Rect dense = sampled_box(huge, kSamples);
  REQUIRE(dense.is_finite());
  CHECK(box.x0 == -8e307);
  CHECK(box.x1 == 8e307);
  CHECK(box.y0 == 0.0);
  CHECK(box.y1 == Approx(5.0).margin(1e-12));  // the parabola's apex at t = 1/2: (0 + 2·10 + 0) / 4
  CHECK(dense.y1 <= box.y1 + kContainSlack);
}
