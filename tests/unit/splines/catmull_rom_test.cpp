// Catmull–Rom splines (Ince, *Curves*, "Spline Parametrization"): interpolation, C1 joins in the knot parameter,
// the classic uniform tangents, the centripetal loop-free property on the textbook example, merging of
// coincident points, and errors.
#include "curvescan/curves/catmull_rom.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "random_spline.h"

namespace curvescan {
namespace {

Vec2 start_derivative(const Bezier& b) {
  return (b.points()[1] - b.points()[0]) * 3.0;
}
Vec2 end_derivative(const Bezier& b) {
  return (b.points()[3] - b.points()[2]) * 3.0;
}
Vec2 derivative(const Bezier& b, double t) {
  const auto p = b.points();
  const double s = 1.0 - t;
  return (p[1] - p[0]) * (3 * s * s) + (p[2] - p[1]) * (6 * s * t) + (p[3] - p[2]) * (3 * t * t);
}

// Whether the polyline of `samples` + 1 points on the Bézier crosses itself (proper crossings of
// non-adjacent edges). 400 edges resolve loops far smaller than the example's.
bool self_intersects(const Bezier& b, int samples = 400) {
  std::vector<Point> poly;
  for (int i = 0; i <= samples; ++i) poly.push_back(b.eval(static_cast<double>(i) / samples));
  auto side = [](Point o, Point a, Point c) { return (a - o).cross(c - o); };
  for (std::size_t i = 0; i + 1 < poly.size(); ++i) {
    for (std::size_t j = i + 2; j + 1 < poly.size(); ++j) {
      const double d1 = side(poly[j], poly[j + 1], poly[i]), d2 = side(poly[j], poly[j + 1], poly[i + 1]);
      const double d3 = side(poly[i], poly[i + 1], poly[j]), d4 = side(poly[i], poly[i + 1], poly[j + 1]);
      if (d1 * d2 < 0 && d3 * d4 < 0) return true;
    }
  }
  return false;
}

TEST_CASE("Catmull-Rom interpolates its points and is C1 in the knot parameter", "[catmull_rom]") {
  std::mt19937_64 rng(14001);
  for (const double alpha : {kCatmullRomUniform, kCatmullRomCentripetal, kCatmullRomChordal}) {
    for (const bool closed : {false, true}) {
      for (int trial = 0; trial < 50; ++trial) {
        const auto points = test::random_points(rng, 3 + static_cast<std::size_t>(trial % 8));
        auto segments = catmull_rom(points, alpha, closed);
        REQUIRE(segments.is_ok());
        const std::size_t n = points.size();
        REQUIRE(segments->size() == (closed ? n : n - 1));
        for (std::size_t i = 0; i < segments->size(); ++i) {
          INFO("alpha " << alpha << " closed " << closed << " trial " << trial << " segment " << i);
          const Bezier& here = (*segments)[i];
          REQUIRE(here.start() == points[i]);
          REQUIRE(here.end() == points[(i + 1) % n]);
          if (!closed && i + 1 == segments->size()) continue;
          const Bezier& next = (*segments)[(i + 1) % segments->size()];
          // dC/dt = (dB/ds) / h with h the segment's knot interval |P_{i+1} - P_i|^alpha.
          const double h_here = std::pow(points[i].distance(points[(i + 1) % n]), alpha);
          const double h_next = std::pow(points[(i + 1) % n].distance(points[(i + 2) % n]), alpha);
          const Vec2 left = end_derivative(here) / h_here, right = start_derivative(next) / h_next;
          // Both sides evaluate the same tangent formula and are scaled back by the interval they were
          // scaled with: a few roundings relative to the tangent's size.
          REQUIRE((left - right).length() <= 1e-12 * std::max(1.0, left.length()));
        }
      }
    }
  }
}

TEST_CASE("Uniform Catmull-Rom has the classic tangents (P_{i+1} - P_{i-1}) / 2", "[catmull_rom]") {
  std::mt19937_64 rng(14002);
  const auto p = test::random_points(rng, 6);
  auto segments = catmull_rom(p, kCatmullRomUniform);
  REQUIRE(segments.is_ok());
  for (std::size_t i = 1; i + 2 < p.size(); ++i) {
    const Bezier& b = (*segments)[i];
    REQUIRE(b.points()[1].distance(p[i] + (p[i + 1] - p[i - 1]) / 6.0) <= 1e-15);
    REQUIRE(b.points()[2].distance(p[i + 1] - (p[i + 2] - p[i]) / 6.0) <= 1e-15);
  }
  // Reflected phantom point at the open start: P_{-1} = 2 P_0 - P_1, tangent (P_1 - P_{-1}) / 2 = P_1 - P_0.
  REQUIRE((*segments)[0].points()[1].distance(p[0] + (p[1] - p[0]) / 3.0) <= 1e-15);
}

TEST_CASE("Centripetal Catmull-Rom has no loop or cusp where uniform forms a loop", "[catmull_rom]") {
  // A short middle segment between two long ones turning sharply (the configuration of Yuksel et al.
  // 2011, fig. 1; Ince, *Curves*, "Uniform parameterization ... generates cusps and intersections within short
  // curve segments").
  const std::vector<Point> points{{0, 0}, {1, 1}, {1.1, 1}, {2, 0}};
  auto uniform = catmull_rom(points, kCatmullRomUniform);
  auto centripetal = catmull_rom(points, kCatmullRomCentripetal);
  auto chordal = catmull_rom(points, kCatmullRomChordal);
  REQUIRE(uniform.is_ok());
  REQUIRE(centripetal.is_ok());
  REQUIRE(chordal.is_ok());
  REQUIRE(self_intersects((*uniform)[1]));  // the example does show the defect
  for (const Bezier& b : *centripetal) {
    REQUIRE_FALSE(self_intersects(b));
    // No cusp: the speed stays well away from zero. The segments' chords are >= 0.1 and the speed of a
    // cusp-free cubic on such a chord stays of that order; a cusp would bring it to 0.
    double slowest = std::numeric_limits<double>::infinity();
    for (int i = 0; i <= 1000; ++i) slowest = std::min(slowest, derivative(b, i / 1000.0).length());
    INFO("slowest speed " << slowest);
    REQUIRE(slowest > 0.01);
  }
  REQUIRE_FALSE(self_intersects((*chordal)[1]));
}

TEST_CASE("Catmull-Rom merges coincident consecutive points", "[catmull_rom]") {
  const std::vector<Point> clean{{0, 0}, {1, 2}, {3, 1}, {4, 4}};
  const std::vector<Point> repeated{{0, 0}, {0, 0}, {1, 2}, {3, 1}, {3, 1}, {3, 1}, {4, 4}};
  for (const double alpha : {kCatmullRomUniform, kCatmullRomCentripetal, kCatmullRomChordal}) {
    auto a = catmull_rom(clean, alpha);
    auto b = catmull_rom(repeated, alpha);
    REQUIRE(a.is_ok());
    REQUIRE(b.is_ok());
    REQUIRE(*a == *b);
    // Closed: a repeated first point at the end is the closing point, merged too.
    std::vector<Point> closed_repeat = clean;
    closed_repeat.push_back(clean.front());
    auto c = catmull_rom(clean, alpha, true);
    auto d = catmull_rom(closed_repeat, alpha, true);
    REQUIRE(c.is_ok());
    REQUIRE(d.is_ok());
    REQUIRE(*c == *d);
    for (const Bezier& segment : *d) {
      for (const Point& p : segment.points()) REQUIRE(p.is_finite());
    }
  }
}

TEST_CASE("catmull_rom rejects malformed input", "[catmull_rom][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto check = [](const Result<std::vector<Bezier>>& r, const std::string& fragment) {
    REQUIRE_FALSE(r.is_ok());
    INFO(r.error().message);
    REQUIRE(r.error().message.find(fragment) != std::string::npos);
  };
  const std::vector<Point> points{{0, 0}, {1, 0}, {2, 1}};
  check(catmull_rom(points, 1.5), "alpha must be in [0, 1]");
  check(catmull_rom(points, nan), "alpha must be in [0, 1]");
  check(catmull_rom(std::vector<Point>{{0, 0}, {nan, 1}}, 0.5), "point 1");
  check(catmull_rom(std::vector<Point>{{0, 0}}, 0.5), "at least 2 distinct points, got 1");
  check(catmull_rom(std::vector<Point>{{1, 1}, {1, 1}, {1, 1}}, 0.5, true), "got 1");
  check(catmull_rom(std::vector<Point>{{-1e308, 0}, {1e308, 0}}, 1.0), "too far apart");
}

}  // namespace
}  // namespace curvescan
