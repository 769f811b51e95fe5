// implicit_curve: contours of f(x, y) = 0 against the function and against dense roots (implicit_curve.h).
#include "curvescan/curves/implicit_curve.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

using curvescan::ErrorKind;
using curvescan::Expression;
using curvescan::ExpressionVariable;
using curvescan::ImplicitCurve;
using curvescan::ImplicitCurveOptions;
using curvescan::Point;

namespace {

constexpr ExpressionVariable kXY[] = {ExpressionVariable::kX, ExpressionVariable::kY};

Expression parse(const char* text) {
  auto expression = Expression::parse(text, kXY);
  REQUIRE(expression.is_ok());
  return std::move(*expression);
}

ImplicitCurve contour(const char* text, Point min, Point max, double tolerance) {
  ImplicitCurveOptions options;
  options.tolerance = tolerance;
  auto curve = curvescan::contour_implicit_curve(parse(text), min, max, options);
  REQUIRE(curve.is_ok());
  return std::move(*curve);
}

double distance_to_segment(Point p, Point a, Point b) {
  const curvescan::Vec2 ab = b - a, ap = p - a;
  const double length2 = ab.x * ab.x + ab.y * ab.y;
  const double t = length2 == 0 ? 0.0 : std::clamp((ap.x * ab.x + ap.y * ab.y) / length2, 0.0, 1.0);
  const Point q = a + ab * t;
  return std::hypot(p.x - q.x, p.y - q.y);
}

double distance_to_polylines(Point p, const std::vector<std::vector<Point>>& polylines) {
  double best = INFINITY;
  for (const auto& line : polylines) {
    for (std::size_t i = 1; i < line.size(); ++i)
      best = std::min(best, distance_to_segment(p, line[i - 1], line[i]));
  }
  return best;
}

// Roots of f on `lines` horizontal and as many vertical lines across the box, each found by bisection of a
// sign change between samples 1/2000 of the box apart (to 1e-12): points of the curve, independent of the
// quadtree.
std::vector<Point> dense_roots(const Expression& f, Point min, Point max, int lines) {
  std::vector<Point> roots;
  constexpr int kSamples = 2000;
  for (int axis = 0; axis < 2; ++axis) {
    for (int k = 0; k <= lines; ++k) {
      auto at = [&](double s) {
        const double fixed =
            axis == 0 ? min.y + (max.y - min.y) * k / lines : min.x + (max.x - min.x) * k / lines;
        return axis == 0 ? Point{min.x + (max.x - min.x) * s, fixed}
                         : Point{fixed, min.y + (max.y - min.y) * s};
      };
      for (int i = 0; i < kSamples; ++i) {
        double a = static_cast<double>(i) / kSamples, b = static_cast<double>(i + 1) / kSamples;
        const Point pa = at(a), pb = at(b);
        double fa = f.evaluate(pa.x, pa.y);
        const double fb = f.evaluate(pb.x, pb.y);
        if (!(fa < 0) == !(fb < 0) || std::isnan(fa) || std::isnan(fb)) continue;
        for (int step = 0; step < 60; ++step) {
          const double m = 0.5 * (a + b);
          const Point pm = at(m);
          const double fm = f.evaluate(pm.x, pm.y);
          if (!(fm < 0) == !(fa < 0)) {
            a = m;
            fa = fm;
          } else {
            b = m;
          }
        }
        roots.push_back(at(0.5 * (a + b)));
      }
    }
  }
  return roots;
}

bool is_closed(const std::vector<Point>& line) {
  return line.size() > 2 && line.front() == line.back();
}

}  // namespace

TEST_CASE("implicit: a circle is one closed polyline within the tolerance", "[implicit]") {
  for (const double tolerance : {0.1, 0.01, 0.001}) {
    const Expression f = parse("x^2 + y^2 - 1");
    const ImplicitCurve curve = contour("x^2 + y^2 - 1", {-2, -1.5}, {2.5, 2}, tolerance);
    REQUIRE(curve.polylines.size() == 1);
    CHECK(is_closed(curve.polylines[0]));
    CHECK(curve.singular_points.empty());
    CHECK(curve.uncertified_cells == 0);
    // Vertices are crossings bracketed to 2^-12 of the deepest cell (below tolerance / 2^16) and placed
    // at the secant's zero there, whose error is the curvature term, (tolerance / 2^16)² / 2 < 1e-12.
    for (const Point p : curve.polylines[0]) CHECK(std::abs(std::hypot(p.x, p.y) - 1.0) < 1e-12);
    // Every point of the curve is within the tolerance of the polyline (both ways for a circle: every
    // segment joins two points of the circle within one cell).
    for (const Point p : dense_roots(f, {-2, -1.5}, {2.5, 2}, 50)) {
      CHECK(distance_to_polylines(p, curve.polylines) <= tolerance);
    }
    for (int k = 0; k < 3600; ++k) {
      const double angle = 2 * std::numbers::pi * k / 3600;
      CHECK(distance_to_polylines({std::cos(angle), std::sin(angle)}, curve.polylines) <= tolerance);
    }
  }
}

TEST_CASE("implicit: two disjoint circles are two polylines", "[implicit]") {
  const char* text = "((x-1)^2 + y^2 - 0.5) * ((x+1.2)^2 + (y-0.3)^2 - 0.3)";
  const ImplicitCurve curve = contour(text, {-3, -2}, {3, 2}, 0.01);
  REQUIRE(curve.polylines.size() == 2);
  CHECK(is_closed(curve.polylines[0]));
  CHECK(is_closed(curve.polylines[1]));
  const Expression f = parse(text);
  for (const auto& line : curve.polylines) {
    for (const Point p : line) CHECK(std::abs(f.evaluate(p.x, p.y)) < 1e-10);
  }
  for (const Point p : dense_roots(f, {-3, -2}, {3, 2}, 40))
    CHECK(distance_to_polylines(p, curve.polylines) <= 0.01);
}

TEST_CASE("implicit: a curve cut by the box is an open polyline ending on the box", "[implicit]") {
  const ImplicitCurve curve = contour("y - sin(3*x)", {-2, -2}, {2, 2}, 0.01);
  REQUIRE(curve.polylines.size() == 1);
  const auto& line = curve.polylines[0];
  CHECK_FALSE(is_closed(line));
  const double left = std::min(line.front().x, line.back().x),
               right = std::max(line.front().x, line.back().x);
  CHECK(left == -2.0);  // crossings on the box's own edges
  CHECK(right == 2.0);
  for (const Point p : dense_roots(parse("y - sin(3*x)"), {-2, -2}, {2, 2}, 40)) {
    CHECK(distance_to_polylines(p, curve.polylines) <= 0.01);
  }
}

TEST_CASE("implicit: the lemniscate's node is found and reported, the curve stays one component",
          "[implicit]") {
  const char* text = "(x^2 + y^2)^2 - 2*(x^2 - y^2)";
  const ImplicitCurve curve = contour(text, {-2, -1.3}, {2.1, 1.2}, 0.01);
  REQUIRE(curve.singular_points.size() == 1);
  CHECK(std::hypot(curve.singular_points[0].x, curve.singular_points[0].y) < 0.01);
  // Away from the node every cell is certified, the four horizontal tangents at (±0.87, ±0.5) included
  // (they need the mean value form: the natural enclosure cannot decide the cell holding the tangent).
  CHECK(curve.uncertified_cells == 0);
  // One connected figure-eight: every vertex has even degree, so one closed trail passes the node twice.
  REQUIRE(curve.polylines.size() == 1);
  CHECK(is_closed(curve.polylines[0]));
  for (const Point p : dense_roots(parse(text), {-2, -1.3}, {2.1, 1.2}, 50)) {
    CHECK(distance_to_polylines(p, curve.polylines) <= 0.01);
  }
}

TEST_CASE("implicit: limits and bad boxes are clear errors", "[implicit]") {
  ImplicitCurveOptions options;
  options.tolerance = 1e-14;
  const auto fine = curvescan::contour_implicit_curve(parse("x^2 + y^2 - 1"), {-2, -2}, {2, 2}, options);
  REQUIRE_FALSE(fine.is_ok());
  CHECK(fine.error().kind == ErrorKind::kLimitExceeded);
  options.tolerance = 1e-5;
  options.max_cells = 1000;
  const auto many =
      curvescan::contour_implicit_curve(parse("sin(40*x)*sin(40*y) - 0.1"), {-2, -2}, {2, 2}, options);
  REQUIRE_FALSE(many.is_ok());
  CHECK(many.error().kind == ErrorKind::kLimitExceeded);
  CHECK_FALSE(curvescan::contour_implicit_curve(parse("x"), {0, 0}, {0, 1}).is_ok());
  CHECK_FALSE(curvescan::contour_implicit_curve(parse("x"), {-1e308, 0}, {1e308, 1}).is_ok());
  // A function undefined in part of the box: contoured where defined, without a crash.
  const ImplicitCurve partial = contour("sqrt(x) - y", {-1, -1}, {1, 1}, 0.01);
  CHECK_FALSE(partial.polylines.empty());
}
