// Closed (periodic) B-splines: the curve closes and is C^{p-1} at the seam (Gallivan, *Parametric Curves*, "repeating knots and
// control points closes the curve").
#include <catch2/catch.hpp>
#include <random>

#include "curvescan/curves/bspline.h"
#include "random_spline.h"

namespace curvescan {
namespace {

TEST_CASE("A closed B-spline is closed and C^{p-1} at the seam", "[bspline][closed]") {
  std::mt19937_64 rng(11001);
  for (int degree = 1; degree <= 5; ++degree) {
    for (int trial = 0; trial < 20; ++trial) {
      const std::size_t count = static_cast<std::size_t>(degree) + 1 + static_cast<std::size_t>(trial % 6);
      auto spline = BSpline::closed(test::random_points(rng, count), degree);
      REQUIRE(spline.is_ok());
      REQUIRE(spline->points().size() == count + static_cast<std::size_t>(degree));
      BSpline derivative = *spline;
      // Derivative j has magnitude up to about (2p)^j on unit spans with points in [-1, 1]; the seam
      // values are computed from the same p control points with the same knot gaps, so they differ only by
      // rounding: 1e-12 * (2p)^j covers it.
      double tolerance = 1e-12;
      for (int order = 0; order < degree; ++order) {
        INFO("degree " << degree << " trial " << trial << " derivative order " << order);
        const Point start = derivative.eval(derivative.domain_start());
        const Point end = derivative.eval(derivative.domain_end());
        REQUIRE(start.distance(end) <= tolerance);
        derivative = derivative.derivative();
        tolerance *= 2.0 * degree;
      }
    }
  }
}

TEST_CASE("A closed linear B-spline is the closed control polygon", "[bspline][closed]") {
  const std::vector<Point> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  auto spline = BSpline::closed(square, 1);
  REQUIRE(spline.is_ok());
  const auto segments = spline->to_beziers();
  REQUIRE(segments.size() == 4);
  for (std::size_t i = 0; i < 4; ++i) {
    REQUIRE(segments[i].start() == square[i]);
    REQUIRE(segments[i].end() == square[(i + 1) % 4]);
  }
}

}  // namespace
}  // namespace curvescan
