// Bezier::split, subsegment, reversed and elevate all leave the curve as a point set unchanged (bezier.h).
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "curvescan/curves/bezier.h"
#include "random_curves.h"

using curvescan::Bezier;
using curvescan::Point;

namespace {

// Curves have coordinates up to 100 and degree <= 10; every compared value is a convex combination formed
// by <= ~2n lerps, each adding ~1.1e-16 relative error: 1e-12 relative to the coordinate scale is ~1000x
// that and still ~1e9 below any real discrepancy.
constexpr double kRel = 1e-12;

bool close(Point a, Point b, double scale) {
  return a.distance(b) <= kRel * scale;
}

}  // namespace

TEST_CASE("bezier split: both halves reproduce the curve and meet exactly at eval(t)", "[bezier][split]") {
  std::mt19937_64 rng(31337);
  std::uniform_real_distribution<double> param(0.0, 1.0);
  for (int degree = 1; degree <= 10; ++degree) {
    for (int trial = 0; trial < 20; ++trial) {
      const Bezier curve = curvescan::test::random_bezier(rng, degree);
      const double scale = curvescan::test::coordinate_scale(curve.points());
      const double t = param(rng);
      const auto [left, right] = curve.split(t);
      REQUIRE(left.degree() == degree);
      REQUIRE(right.degree() == degree);
      REQUIRE(left.start() == curve.start());
      REQUIRE(right.end() == curve.end());
      REQUIRE(left.end() == curve.eval(t));
      REQUIRE(right.start() == curve.eval(t));
      for (int k = 0; k <= 16; ++k) {
        const double s = k / 16.0;
        REQUIRE(close(left.eval(s), curve.eval(s * t), scale));
        REQUIRE(close(right.eval(s), curve.eval(t + s * (1 - t)), scale));
      }
    }
  }
}

TEST_CASE("bezier subsegment: reproduces the curve on [t0, t1], endpoints exact, reversed when t0 > t1",
          "[bezier][split]") {
  std::mt19937_64 rng(2718);
  std::uniform_real_distribution<double> param(0.0, 1.0);
  for (int degree = 1; degree <= 10; ++degree) {
    for (int trial = 0; trial < 20; ++trial) {
      const Bezier curve = curvescan::test::random_bezier(rng, degree);
      const double scale = curvescan::test::coordinate_scale(curve.points());
      const double t0 = param(rng), t1 = param(rng);
      const Bezier piece = curve.subsegment(t0, t1);
      REQUIRE(piece.start() == curve.eval(t0));
      REQUIRE(piece.end() == curve.eval(t1));
      for (int k = 0; k <= 16; ++k) {
        const double s = k / 16.0;
        REQUIRE(close(piece.eval(s), curve.eval(t0 + s * (t1 - t0)), scale));
      }
    }
  }
  // The whole range gives the control points back (blossom of all 0s and 1s), up to lerp rounding.
  const Bezier cubic({{0, 0}, {1, 3}, {5, 3}, {6, 0}});
  REQUIRE(cubic.subsegment(0.0, 1.0) == cubic);
  REQUIRE(cubic.subsegment(1.0, 0.0) == cubic.reversed());
}

TEST_CASE("bezier reversed: eval(t) == reversed().eval(1 - t)", "[bezier][reversed]") {
  std::mt19937_64 rng(161803);
  for (int degree = 1; degree <= 10; ++degree) {
    const Bezier curve = curvescan::test::random_bezier(rng, degree);
    const double scale = curvescan::test::coordinate_scale(curve.points());
    const Bezier back = curve.reversed();
    REQUIRE(back.reversed() == curve);
    for (int k = 0; k <= 32; ++k) {
      const double t = k / 32.0;
      REQUIRE(close(curve.eval(t), back.eval(1.0 - t), scale));
    }
  }
}

TEST_CASE("bezier elevate: degree n+1 with the same curve (Dill, *Introduction to Parametric Curves*, 'Degree Raising')", "[bezier][elevate]") {
  std::mt19937_64 rng(4);
  for (int degree = 1; degree <= 10; ++degree) {
    for (int trial = 0; trial < 10; ++trial) {
      const Bezier curve = curvescan::test::random_bezier(rng, degree);
      const double scale = curvescan::test::coordinate_scale(curve.points());
      const Bezier raised = curve.elevate();
      const Bezier raised_twice = raised.elevate();
      REQUIRE(raised.degree() == degree + 1);
      REQUIRE(raised.start() == curve.start());
      REQUIRE(raised.end() == curve.end());
      for (int k = 0; k <= 32; ++k) {
        const double t = k / 32.0;
        REQUIRE(close(raised.eval(t), curve.eval(t), scale));
        REQUIRE(close(raised_twice.eval(t), curve.eval(t), scale));
      }
    }
  }
  // The seed's formula on a line: raising (0,0)-(3,0) gives (0,0), (1.5,0), (3,0) (Q1 = (P0 + P1)/2).
  REQUIRE(Bezier({{0, 0}, {3, 0}}).elevate() == Bezier({{0, 0}, {1.5, 0}, {3, 0}}));
}

TEST_CASE("bezier split/subsegment: degenerate inputs stay total", "[bezier][split]") {
  const auto [l, r] = Bezier().split(0.5);
  REQUIRE(l.points().empty());
  REQUIRE(r.points().empty());
  REQUIRE(Bezier().subsegment(0.2, 0.4).points().empty());
  REQUIRE(Bezier().elevate().points().empty());
  const Bezier point({{2, 3}});
  REQUIRE(point.split(0.3).first == point);
  const Point nan_eval = Bezier({{0, 0}, {1, 1}}).split(std::nan("")).first.end();
  REQUIRE(std::isnan(nan_eval.x));
}
