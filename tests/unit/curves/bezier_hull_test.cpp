// The convex hull property: B(t), t in [0, 1], lies in the convex hull of the control points (U. of Toronto, *Parametric Curves*
// "Convex hull property", Dill, *Introduction to Parametric Curves*, "Bernstein functions sum to one and are everywhere positive").
#include <algorithm>
#include <catch2/catch.hpp>
#include <random>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "random_curves.h"

using curvescan::Bezier;
using curvescan::Point;

namespace {

// Andrew's monotone chain: the hull's vertices in counter-clockwise order (y up), collinear points dropped.
std::vector<Point> convex_hull(std::vector<Point> points) {
  std::sort(points.begin(), points.end(),
            [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<Point> hull(2 * points.size());
  std::size_t k = 0;
  auto turn = [](Point o, Point a, Point b) { return (a - o).cross(b - o); };
  for (const Point& p : points) {
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], p) <= 0) --k;
    hull[k++] = p;
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

// Signed distance of p inside the convex polygon: the smallest distance to an edge line, negative outside.
double inside_margin(const std::vector<Point>& hull, Point p) {
  double margin = 1e300;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point a = hull[i], b = hull[(i + 1) % hull.size()];
    margin = std::min(margin, (b - a).cross(p - a) / (b - a).length());
  }
  return margin;
}

}  // namespace

TEST_CASE("bezier hull: samples lie inside the convex hull of the control points", "[bezier][hull]") {
  std::mt19937_64 rng(8675309);
  for (int degree = 2; degree <= 10; ++degree) {
    for (int trial = 0; trial < 20; ++trial) {
      const Bezier curve = curvescan::test::random_bezier(rng, degree);
      const auto hull = convex_hull({curve.points().begin(), curve.points().end()});
      REQUIRE(hull.size() >= 3);
      for (int k = 0; k <= 256; ++k) {
        // Endpoints sit exactly on the hull; rounding can put them ~1e-14 outside (coordinates <= 100).
        REQUIRE(inside_margin(hull, curve.eval(k / 256.0)) >= -1e-11);
      }
    }
  }
  // The check can fail: outside [0, 1] the Bernstein weights go negative and the curve leaves the hull.
  const Bezier cubic({{0, 0}, {1, 2}, {3, 2}, {4, 0}});
  const auto hull = convex_hull({cubic.points().begin(), cubic.points().end()});
  REQUIRE(inside_margin(hull, cubic.eval(-0.5)) < -0.1);
  REQUIRE(inside_margin(hull, cubic.eval(1.5)) < -0.1);
}
