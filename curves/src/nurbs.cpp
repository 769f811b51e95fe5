// NURBS in homogeneous coordinates (Umetani, *Parametric Curve*, §4, eq. 10 and §4.1; Ince, *Curves*, "NURBS Curves").
#include "curvescan/curves/nurbs.h"

#include <cmath>
#include <string>

namespace curvescan {

Result<Nurbs> Nurbs::create(std::vector<Point> points, std::vector<double> weights, std::vector<double> knots,
                            int degree) {
  if (weights.size() != points.size()) {
    return Error{ErrorKind::kInvalidArgument, "NURBS has " + std::to_string(points.size()) +
                                                  " control points but " + std::to_string(weights.size()) +
                                                  " weights."};
  }
  std::vector<Point> weighted(points.size());
  std::vector<Point> weight_points(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!std::isfinite(weights[i]) || !(weights[i] > 0.0)) {
      return Error{ErrorKind::kInvalidArgument, "NURBS weight " + std::to_string(i) +
                                                    " must be finite and > 0, got " +
                                                    std::to_string(weights[i]) + "."};
    }
    if (!points[i].is_finite()) {
      return Error{ErrorKind::kInvalidArgument,
                   "control point " + std::to_string(i) + " has a NaN or infinite coordinate."};
    }
    weighted[i] = Point::from_vec(points[i].to_vec() * weights[i]);
    if (!weighted[i].is_finite()) {
      return Error{ErrorKind::kInvalidArgument,
                   "control point " + std::to_string(i) + " times its weight overflows a double."};
    }
    weight_points[i] = {weights[i], 0.0};
  }
  auto weighted_spline = BSpline::create(std::move(weighted), knots, degree);
  if (!weighted_spline) return weighted_spline.error();
  auto weight_spline = BSpline::create(std::move(weight_points), std::move(knots), degree);
  if (!weight_spline) return weight_spline.error();
  return Nurbs(std::move(weighted_spline).value(), std::move(weight_spline).value());
}

Result<Nurbs> Nurbs::circle(Point center, double radius) {
  if (!center.is_finite()) {
    return Error{ErrorKind::kInvalidArgument, "circle center has a NaN or infinite coordinate."};
  }
  if (!std::isfinite(radius) || radius < 0.0) {
    return Error{ErrorKind::kInvalidArgument,
                 "circle radius must be finite and >= 0, got " + std::to_string(radius) + "."};
  }
  // The square's corners carry weight cos(45°) = √2/2: each quarter is then the rational quadratic
  // (1, √2/2, 1) of a 90° arc, whose weight is cos(half the sweep).
  const double corner = std::sqrt(0.5);
  const double unit[9][2] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  std::vector<Point> points;
  std::vector<double> weights;
  for (int i = 0; i < 9; ++i) {
    points.push_back(center + Vec2{unit[i][0], unit[i][1]} * radius);
    weights.push_back(i % 2 == 0 ? 1.0 : corner);
  }
  std::vector<double> knots{0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
  return create(std::move(points), std::move(weights), std::move(knots), 2);
}

std::vector<Point> Nurbs::points() const noexcept {
  const auto weighted = weighted_.points();
  const auto weight = weight_.points();
  std::vector<Point> points(weighted.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    points[i] = Point::from_vec(weighted[i].to_vec() / weight[i].x);
  return points;
}

std::vector<double> Nurbs::weights() const noexcept {
  std::vector<double> weights;
  for (const Point& w : weight_.points()) weights.push_back(w.x);
  return weights;
}

Point Nurbs::eval(double u) const noexcept {
  const Point h = weighted_.eval(u);
  const double w = weight_.eval(u).x;
  return {h.x / w, h.y / w};
}

Nurbs Nurbs::insert_knot(double u) const noexcept {
  return Nurbs(weighted_.insert_knot(u), weight_.insert_knot(u));
}

std::vector<RationalBezier> Nurbs::to_rational_beziers() const noexcept {
  // Both splines have the same knots, so their refinements and segments correspond one to one.
  const std::vector<Bezier> weighted = weighted_.to_beziers();
  const std::vector<Bezier> weight = weight_.to_beziers();
  std::vector<RationalBezier> segments;
  segments.reserve(weighted.size());
  for (std::size_t j = 0; j < weighted.size(); ++j) {
    const auto h = weighted[j].points();
    const auto w = weight[j].points();
    std::vector<Point> points(h.size());
    std::vector<double> weights(h.size());
    for (std::size_t i = 0; i < h.size(); ++i) {
      weights[i] = w[i].x;
      points[i] = Point::from_vec(h[i].to_vec() / w[i].x);
    }
    segments.emplace_back(std::move(points), std::move(weights));
  }
  return segments;
}

}  // namespace curvescan
