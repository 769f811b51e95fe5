// Interpolating cubic splines (Gallivan, *Parametric Curves*, "Parameterization", Dill, *Introduction to Parametric Curves*, Ince, *Curves*, "Spline Interpolation"):
// interpolation, C1 and C2 joins in the spline parameter, the end conditions, cubic reproduction, a closed
// spline approximating a circle, and errors.
#include "curvescan/curves/cubic_spline.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>

#include "random_spline.h"

namespace curvescan {
namespace {

// End derivatives of a cubic Bézier in its own parameter s in [0, 1].
Vec2 start_first(const Bezier& b) {
  return (b.points()[1] - b.points()[0]) * 3.0;
}
Vec2 end_first(const Bezier& b) {
  return (b.points()[3] - b.points()[2]) * 3.0;
}
Vec2 start_second(const Bezier& b) {
  const auto p = b.points();
  return ((p[0] - p[1]) + (p[2] - p[1])) * 6.0;
}
Vec2 end_second(const Bezier& b) {
  const auto p = b.points();
  return ((p[1] - p[2]) + (p[3] - p[2])) * 6.0;
}

// The Bézier points are built from the moments by a few operations each, and the second derivative
// re-derives them as a second difference of points of size ~1 divided by h^2: rounding (~1e-16) is
// amplified by about 1/h^2 (first derivative: 1/h). The bound 1e-12 / h_min^2, relative to the size of
// the derivative, leaves a factor ~1e4 over that.
double g_relative = 1e-9;

void require_close(Vec2 a, Vec2 b) {
  REQUIRE((a - b).length() <= g_relative * std::max({1.0, a.length(), b.length()}));
}

void set_tolerance(const std::vector<double>& t) {
  double shortest = 1.0;
  for (std::size_t i = 0; i + 1 < t.size(); ++i) shortest = std::min(shortest, t[i + 1] - t[i]);
  g_relative = 1e-12 / (shortest * shortest);
}

void check_c2(std::span<const Point> points, const std::vector<Bezier>& segments,
              const std::vector<double>& t, bool closed) {
  const std::size_t n = segments.size();
  for (std::size_t i = 0; i < n; ++i) {
    INFO("segment " << i);
    REQUIRE(segments[i].start() == points[i]);
    REQUIRE(segments[i].end() == points[(i + 1) % points.size()]);
    if (!closed && i + 1 == n) continue;
    const std::size_t j = (i + 1) % n;
    const double hi = t[i + 1] - t[i], hj = t[j + 1] - t[j];
    require_close(end_first(segments[i]) / hi, start_first(segments[j]) / hj);
    require_close(end_second(segments[i]) / (hi * hi), start_second(segments[j]) / (hj * hj));
  }
}

TEST_CASE("Cubic splines interpolate and are C2 at the joins", "[cubic_spline]") {
  std::mt19937_64 rng(15001);
  for (const auto parameterization :
       {SplineParameterization::kUniform, SplineParameterization::kChordLength}) {
    for (const auto ends : {SplineEnds::kNatural, SplineEnds::kClamped, SplineEnds::kClosed}) {
      for (int trial = 0; trial < 40; ++trial) {
        const auto points = test::random_points(rng, 3 + static_cast<std::size_t>(trial % 10));
        CubicSplineOptions options{parameterization, ends, {0.5, -1.0}, {2.0, 0.25}};
        auto segments = cubic_spline(points, options);
        auto t = spline_parameters(points, parameterization, ends == SplineEnds::kClosed);
        REQUIRE(segments.is_ok());
        REQUIRE(t.is_ok());
        REQUIRE(segments->size() + 1 == t->size());
        INFO("parameterization " << static_cast<int>(parameterization) << " ends " << static_cast<int>(ends)
                                 << " trial " << trial);
        set_tolerance(*t);
        check_c2(points, *segments, *t, ends == SplineEnds::kClosed);
        const double h0 = (*t)[1] - (*t)[0], hn = t->back() - (*t)[t->size() - 2];
        if (ends == SplineEnds::kNatural) {
          REQUIRE(start_second(segments->front()).length() / (h0 * h0) <= g_relative);
          REQUIRE(end_second(segments->back()).length() / (hn * hn) <= g_relative);
        } else if (ends == SplineEnds::kClamped) {
          require_close(start_first(segments->front()) / h0, options.start_tangent);
          require_close(end_first(segments->back()) / hn, options.end_tangent);
        }
      }
    }
  }
}

TEST_CASE("A clamped spline reproduces a cubic polynomial exactly", "[cubic_spline]") {
  // The clamped ("complete") cubic spline interpolant of a cubic is the cubic itself (de Boor, ch. IV),
  // an independent check of the whole solve. x(t) = 2t^3 - t + 1, y(t) = -t^3 + 3t^2 on uniform t_i = i/n.
  auto curve = [](double t) { return Point{2 * t * t * t - t + 1, -t * t * t + 3 * t * t}; };
  auto slope = [](double t) { return Vec2{6 * t * t - 1, -3 * t * t + 6 * t}; };
  constexpr int kPieces = 7;
  std::vector<Point> points;
  for (int i = 0; i <= kPieces; ++i) points.push_back(curve(static_cast<double>(i) / kPieces));
  CubicSplineOptions options{SplineParameterization::kUniform, SplineEnds::kClamped, slope(0.0), slope(1.0)};
  auto segments = cubic_spline(points, options);
  REQUIRE(segments.is_ok());
  for (int i = 0; i < kPieces; ++i) {
    for (int step = 0; step <= 8; ++step) {
      const double s = step / 8.0;
      const double t = (i + s) / kPieces;
      // Exact in exact arithmetic; values of size ~3, a tridiagonal solve with condition number <= 3.
      REQUIRE((*segments)[static_cast<std::size_t>(i)].eval(s).distance(curve(t)) <= 1e-13);
    }
  }
}

TEST_CASE("A closed chord-length spline through points on a circle stays near the circle", "[cubic_spline]") {
  // 16 points on the unit circle: the periodic cubic spline error is O(h^4), about h^4/384 |P''''| with
  // h = 2 pi / 16 ~ 0.39, i.e. ~1e-4. Bound 1e-3.
  std::vector<Point> points;
  for (int i = 0; i < 16; ++i) {
    const double angle = 2 * std::numbers::pi * i / 16;
    points.push_back({std::cos(angle), std::sin(angle)});
  }
  auto segments = cubic_spline(points, {SplineParameterization::kChordLength, SplineEnds::kClosed, {}, {}});
  REQUIRE(segments.is_ok());
  REQUIRE(segments->size() == 16);
  double worst = 0.0;
  for (const Bezier& b : *segments) {
    for (int step = 0; step <= 32; ++step)
      worst = std::max(worst, std::abs(b.eval(step / 32.0).distance({0, 0}) - 1));
  }
  INFO("worst radial error " << worst);
  REQUIRE(worst < 1e-3);
  // Repeating the first point at the end changes nothing.
  points.push_back(points.front());
  auto repeated = cubic_spline(points, {SplineParameterization::kChordLength, SplineEnds::kClosed, {}, {}});
  REQUIRE(repeated.is_ok());
  REQUIRE(*repeated == *segments);
}

TEST_CASE("Two-point splines are a line (natural) and a Hermite cubic (clamped)", "[cubic_spline]") {
  const std::vector<Point> points{{0, 0}, {3, 4}};
  auto line = cubic_spline(points, {SplineParameterization::kChordLength, SplineEnds::kNatural, {}, {}});
  REQUIRE(line.is_ok());
  REQUIRE(line->size() == 1);
  REQUIRE((*line)[0].points()[1].distance({1, 4.0 / 3.0}) <= 1e-15);
  REQUIRE((*line)[0].points()[2].distance({2, 8.0 / 3.0}) <= 1e-15);
}

TEST_CASE("cubic_spline rejects malformed input", "[cubic_spline][errors]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto check = [](const Result<std::vector<Bezier>>& r, const std::string& fragment) {
    REQUIRE_FALSE(r.is_ok());
    INFO(r.error().message);
    REQUIRE(r.error().message.find(fragment) != std::string::npos);
  };
  check(cubic_spline(std::vector<Point>{{0, 0}}), "at least 2 points, got 1");
  check(cubic_spline(std::vector<Point>{{0, 0}, {1, 1}, {0, 0}},
                     {SplineParameterization::kUniform, SplineEnds::kClosed, {}, {}}),
        "closed cubic spline needs at least 3 points, got 2");
  check(cubic_spline(std::vector<Point>{{0, 0}, {nan, 1}}), "point 1");
  check(cubic_spline(std::vector<Point>{{0, 0}, {1, 1}, {1, 1}, {2, 0}}), "points 1 and 2 coincide");
  check(cubic_spline(std::vector<Point>{{0, 0}, {1, 1}},
                     {SplineParameterization::kUniform, SplineEnds::kClamped, {nan, 0}, {1, 0}}),
        "tangents must be finite");
  // Uniform parameters do not need distinct points.
  REQUIRE(cubic_spline(std::vector<Point>{{0, 0}, {1, 1}, {1, 1}, {2, 0}},
                       {SplineParameterization::kUniform, SplineEnds::kNatural, {}, {}})
              .is_ok());
}

}  // namespace
}  // namespace curvescan
