// explicit_curve: the polylines of y = f(x) against dense sampling of f (explicit_curve.h).
#include "curvescan/curves/explicit_curve.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

using curvescan::ErrorKind;
using curvescan::ExplicitCurve;
using curvescan::ExplicitCurveOptions;
using curvescan::Expression;
using curvescan::ExpressionVariable;
using curvescan::Point;

namespace {

constexpr ExpressionVariable kX[] = {ExpressionVariable::kX};
constexpr double kPi = std::numbers::pi;

Expression parse(const char* text) {
  auto expression = Expression::parse(text, kX);
  REQUIRE(expression.is_ok());
  return std::move(*expression);
}

ExplicitCurve graph(const char* text, double x0, double x1, double tolerance) {
  ExplicitCurveOptions options;
  options.tolerance = tolerance;
  auto curve = curvescan::flatten_explicit_curve(parse(text), x0, x1, options);
  REQUIRE(curve.is_ok());
  return std::move(*curve);
}

// The largest vertical distance between f and the polyline (x-increasing) at `samples` points of its x
// range. The polyline is a graph over x, so this bounds the Hausdorff distance between the two.
double max_vertical_error(const Expression& f, const std::vector<Point>& polyline, int samples) {
  double worst = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const double x = polyline.front().x + (polyline.back().x - polyline.front().x) * i / samples;
    const auto after = std::upper_bound(polyline.begin(), polyline.end(), x,
                                        [](double value, const Point& p) { return value < p.x; });
    const std::size_t k =
        std::clamp<std::size_t>(static_cast<std::size_t>(after - polyline.begin()), 1, polyline.size() - 1);
    const Point p = polyline[k - 1], q = polyline[k];
    const double y = q.x == p.x ? p.y : p.y + (q.y - p.y) * (x - p.x) / (q.x - p.x);
    worst = std::max(worst, std::abs(f.evaluate(x) - y));
  }
  return worst;
}

}  // namespace

TEST_CASE("explicit: sin(x) stays within the tolerance of dense samples", "[explicit]") {
  for (const double tolerance : {0.1, 0.01, 1e-4}) {
    const ExplicitCurve curve = graph("sin(x)", 0.0, 10.0, tolerance);
    REQUIRE(curve.polylines.size() == 1);
    CHECK(curve.splits.empty());
    const std::vector<Point>& line = curve.polylines[0];
    CHECK(line.front() == Point{0.0, 0.0});
    CHECK(line.back().x == 10.0);
    // 2·10^5 samples, far more than vertices; the proof bounds the error by the tolerance, the samples
    // must agree (nothing to allow for but the rounding of the interpolation, 1e-15 here).
    CHECK(max_vertical_error(parse("sin(x)"), line, 200'000) <= tolerance);
    // Not absurdly fine either: the chord error of sin is h²/8, so about 10 / sqrt(8 · tolerance) pieces
    // would do; the certified ones may be a few times more.
    CHECK(static_cast<double>(line.size()) < 12 * 10.0 / std::sqrt(8 * tolerance) + 10);
  }
}

TEST_CASE("explicit: a kink (abs) and a steep polynomial stay within the tolerance", "[explicit]") {
  for (const char* text : {"abs(x) - 0.3", "x^5 - 3*x^3 + x", "exp(x) * cos(3*x)", "max(sin(x), cos(2*x))"}) {
    INFO(text);
    const ExplicitCurve curve = graph(text, -2.1, 2.3, 0.01);
    REQUIRE(curve.polylines.size() == 1);
    CHECK(max_vertical_error(parse(text), curve.polylines[0], 100'000) <= 0.01);
  }
}

TEST_CASE("explicit: tan splits at its poles", "[explicit]") {
  const ExplicitCurve curve = graph("tan(x)", -3.0, 3.0, 0.01);
  REQUIRE(curve.polylines.size() == 3);
  REQUIRE(curve.splits.size() == 2);
  CHECK(curve.splits[0].first <= -kPi / 2);
  CHECK(curve.splits[0].second >= -kPi / 2);
  CHECK(curve.splits[1].first <= kPi / 2);
  CHECK(curve.splits[1].second >= kPi / 2);
  CHECK(curve.clipped);  // near the poles tan leaves the band |y| <= 1e6
  for (const auto& line : curve.polylines) CHECK(max_vertical_error(parse("tan(x)"), line, 50'000) <= 0.01);
  // No vertical line across a pole: consecutive vertices never jump from one branch to the other.
  for (const auto& line : curve.polylines) {
    for (std::size_t i = 1; i < line.size(); ++i) CHECK(std::abs(line[i].y - line[i - 1].y) < 2e6);
  }
}

TEST_CASE("explicit: jumps and undefined stretches split the graph", "[explicit]") {
  const ExplicitCurve jump = graph("atan(1/x)", -1.0, 1.0, 0.01);
  REQUIRE(jump.polylines.size() == 2);
  CHECK(jump.polylines[0].back().x < 0.0);
  CHECK(jump.polylines[1].front().x > 0.0);
  CHECK(jump.polylines[0].back().y == Approx(-kPi / 2).margin(0.01));  // the graph's limit from the left
  CHECK(jump.polylines[1].front().y == Approx(kPi / 2).margin(0.01));
  const ExplicitCurve root = graph("sqrt(x)", -1.0, 1.0, 0.01);
  REQUIRE(root.polylines.size() == 1);
  CHECK(root.polylines[0].front().x >= 0.0);
  CHECK(root.polylines[0].front().x < 1e-4);  // the polyline reaches x = 0 within the tolerance
  CHECK(max_vertical_error(parse("sqrt(x)"), root.polylines[0], 100'000) <= 0.01);
  const ExplicitCurve nowhere = graph("log(-1 - x*x)", -1.0, 1.0, 0.01);
  CHECK(nowhere.polylines.empty());
}

TEST_CASE("explicit: limits give clear errors", "[explicit]") {
  ExplicitCurveOptions options;
  options.max_pieces = 100'000;
  const auto wild = curvescan::flatten_explicit_curve(parse("sin(1/x)"), -1.0, 1.0, options);
  REQUIRE_FALSE(wild.is_ok());
  CHECK(wild.error().kind == ErrorKind::kLimitExceeded);
  CHECK(wild.error().message.find("more than 100000 pieces") != std::string::npos);
  CHECK_FALSE(curvescan::flatten_explicit_curve(parse("x"), 1.0, 0.0).is_ok());
  CHECK_FALSE(curvescan::flatten_explicit_curve(parse("x"), 0.0, INFINITY).is_ok());
  CHECK_FALSE(curvescan::flatten_explicit_curve(parse("x"), -1e308, 1e308).is_ok());
}

TEST_CASE("explicit: pieces beside a pole of tan are clipped, not split without end (margin regression)",
          "[explicit]") {
  // A pole test with a margin of 1e-9 periods took every piece within 3e-9 of π/2 for one holding the
  // pole: millions of pieces down to the depth limit. The graph needs a few hundred.
  ExplicitCurveOptions options;
  options.y_min = -20;
  options.y_max = 20;
  options.max_pieces = 3000;
  const auto curve = curvescan::flatten_explicit_curve(parse("tan(x)"), -3.0, 3.0, options);
  REQUIRE(curve.is_ok());
  CHECK(curve->polylines.size() == 3);
}
