// Exact decomposition of a B-spline into Bézier segments (every domain knot raised to multiplicity p).
#include <catch2/catch.hpp>
#include <random>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/bspline.h"
#include "random_spline.h"

namespace curvescan {
namespace {

// Points in [-1, 1]^2; up to p insertions per knot, each a convex combination, then de Casteljau on the
// segment and de Boor on the spline: errors of a few dozen ulps of 1. The parameter map u = a + t (b - a)
// adds eps * |C'| * |u| ~ 1e-14. 1e-12 is the task's bar.
constexpr double kTolerance = 1e-12;

TEST_CASE("Bezier segments reproduce the B-spline on every span", "[bspline][bezier]") {
  std::mt19937_64 rng(10001);
  for (int degree = 1; degree <= 5; ++degree) {
    for (int trial = 0; trial < 40; ++trial) {
      const BSpline spline = test::random_bspline(rng, degree, trial % 2 == 0);
      const std::vector<Bezier> segments = spline.to_beziers();
      const std::vector<double> breaks = spline.bezier_breakpoints();
      REQUIRE(segments.size() + 1 == breaks.size());
      for (std::size_t j = 0; j < segments.size(); ++j) {
        REQUIRE(segments[j].degree() == degree);
        for (int step = 0; step <= 16; ++step) {
          const double t = step / 16.0;
          const double u = breaks[j] + t * (breaks[j + 1] - breaks[j]);
          INFO("degree " << degree << " trial " << trial << " segment " << j << " t " << t);
          // At t = 1 the spline's span convention picks the next span; the curve is continuous there
          // unless the knot has multiplicity p + 1, where the segment's end is the left limit.
          const Point expected = step == 16 ? spline.eval(std::nextafter(u, breaks[j])) : spline.eval(u);
          REQUIRE(segments[j].eval(t).distance(expected) <= (step == 16 ? 1e-9 : kTolerance));
        }
      }
    }
  }
}

// to_beziers works on a sliding window of the refined curve; to_beziers_reference copies the whole curve per
// inserted knot. They make the same insertions in the same order with the same expressions, so the segments
// must be equal bit for bit (no tolerance): any difference is a different algorithm, not rounding.
TEST_CASE("Windowed Bezier decomposition equals the whole-curve reference exactly", "[bspline][bezier]") {
  std::mt19937_64 rng(10004);
  for (int degree = 0; degree <= 7; ++degree) {
    for (int trial = 0; trial < 60; ++trial) {
      const BSpline spline = test::random_bspline(rng, degree, trial % 3 == 0);
      INFO("degree " << degree << " trial " << trial);
      REQUIRE(spline.to_beziers() == spline.to_beziers_reference());
    }
  }
}

// The random splines above have at most eight spans; this curve has about 2000,
// with repeated interior knots, and is checked against de Boor's algorithm (BSpline::eval) directly. Points
// in [-1, 1]^2 and spans of length ~1 on a domain of length ~2000: the parameter map u = a + t (b - a) loses
// eps * |u| ~ 5e-13 in u, times |C'| of a few units, plus the dozen-ulp rounding of the insertions and of
// de Casteljau: 1e-11 is well above that and far below any visible error.
TEST_CASE("Windowed Bezier decomposition of a long spline matches de Boor", "[bspline][bezier]") {
  std::mt19937_64 rng(10005);
  for (const int degree : {1, 2, 3, 5}) {
    const std::size_t count = 2000;
    auto spline = BSpline::create(test::random_points(rng, count),
                                  test::random_knots(rng, count, degree, false), degree);
    REQUIRE(spline.is_ok());
    const std::vector<Bezier> segments = spline->to_beziers();
    const std::vector<double> breaks = spline->bezier_breakpoints();
    REQUIRE(segments.size() + 1 == breaks.size());
    for (std::size_t j = 0; j < segments.size(); ++j) {
      for (int step = 0; step < 8; ++step) {
        const double t = step / 8.0;
        INFO("degree " << degree << " segment " << j << " t " << t);
        REQUIRE(segments[j].eval(t).distance(spline->eval(breaks[j] + t * (breaks[j + 1] - breaks[j]))) <=
                1e-11);
      }
    }
  }
}

TEST_CASE("Uniform cubic B-spline converts to the textbook Bezier points", "[bspline][bezier]") {
  // For a uniform span with points P0..P3 the Bézier points are (P0 + 4P1 + P2)/6, (2P1 + P2)/3,
  // (P1 + 2P2)/3, (P1 + 4P2 + P3)/6 (the 1/6 B-spline matrix of Dill, *Introduction to Parametric Curves*, times the inverse Bézier matrix).
  std::mt19937_64 rng(10002);
  const auto p = test::random_points(rng, 5, 10.0);
  auto spline = BSpline::uniform(p, 3);
  REQUIRE(spline.is_ok());
  const auto segments = spline->to_beziers();
  REQUIRE(segments.size() == 2);
  for (std::size_t s = 0; s < 2; ++s) {
    auto combine = [&](double a, double b, double c, double d) {
      return Point::from_vec(p[s].to_vec() * a + p[s + 1].to_vec() * b + p[s + 2].to_vec() * c +
                             p[s + 3].to_vec() * d);
    };
    const Point expected[4] = {combine(1 / 6.0, 4 / 6.0, 1 / 6.0, 0), combine(0, 2 / 3.0, 1 / 3.0, 0),
                               combine(0, 1 / 3.0, 2 / 3.0, 0), combine(0, 1 / 6.0, 4 / 6.0, 1 / 6.0)};
    for (std::size_t i = 0; i < 4; ++i) {
      // Magnitude-10 coordinates, a few roundings on each side.
      REQUIRE(segments[s].points()[i].distance(expected[i]) <= 1e-13);
    }
  }
}

TEST_CASE("A clamped B-spline without interior knots is its own Bezier", "[bspline][bezier]") {
  std::mt19937_64 rng(10003);
  const auto points = test::random_points(rng, 4);
  auto spline = BSpline::clamped(points, 3);
  REQUIRE(spline.is_ok());
  const auto segments = spline->to_beziers();
  REQUIRE(segments.size() == 1);
  REQUIRE(segments[0] == Bezier(points));
}

}  // namespace
}  // namespace curvescan
