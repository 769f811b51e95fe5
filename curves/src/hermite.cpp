// Cubic Hermite segments and piecewise Hermite splines (U. of Toronto, *Parametric Curves*, "Hermite Curves", Dill, *Introduction to Parametric Curves*, "Parametric
// Cubic (Hermite) Curves").
#include "curvescan/curves/hermite.h"

#include <cmath>
#include <string>

namespace curvescan {

Point HermiteSegment::eval(double t) const noexcept {
  const double t2 = t * t, t3 = t2 * t;
  // f1 + f2 = 1, so f1 P1 + f2 P4 = P1 + f2 (P4 - P1): an affine combination written on a vector.
  const double f2 = -2.0 * t3 + 3.0 * t2;
  const double f3 = t3 - 2.0 * t2 + t;
  const double f4 = t3 - t2;
  return p0 + (p1 - p0) * f2 + r0 * f3 + r1 * f4;
}

Vec2 HermiteSegment::derivative(double t) const noexcept {
  const double t2 = t * t;
  return (p1 - p0) * (-6.0 * t2 + 6.0 * t) + r0 * (3.0 * t2 - 4.0 * t + 1.0) + r1 * (3.0 * t2 - 2.0 * t);
}

Bezier HermiteSegment::to_bezier() const noexcept {
  return Bezier({p0, p0 + r0 / 3.0, p1 - r1 / 3.0, p1});
}

Result<std::vector<Bezier>> hermite_spline(std::span<const Point> points, std::span<const Vec2> tangents,
                                           std::span<const double> parameters) {
  auto invalid = [](std::string message) { return Error{ErrorKind::kInvalidArgument, std::move(message)}; };
  if (points.size() < 2) {
    return invalid("a Hermite spline needs at least 2 points, got " + std::to_string(points.size()) + ".");
  }
  if (tangents.size() != points.size()) {
    return invalid("a Hermite spline through " + std::to_string(points.size()) +
                   " points needs as many tangents, got " + std::to_string(tangents.size()) + ".");
  }
  if (parameters.size() != points.size()) {
    return invalid("a Hermite spline through " + std::to_string(points.size()) +
                   " points needs as many parameters, got " + std::to_string(parameters.size()) + ".");
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].is_finite())
      return invalid("point " + std::to_string(i) + " has a NaN or infinite coordinate.");
    if (!tangents[i].is_finite())
      return invalid("tangent " + std::to_string(i) + " has a NaN or infinite coordinate.");
    if (!std::isfinite(parameters[i])) return invalid("parameter " + std::to_string(i) + " is not finite.");
    if (i > 0 && !(parameters[i] > parameters[i - 1])) {
      return invalid("parameters must increase strictly, but parameter " + std::to_string(i) + " does not.");
    }
  }
  std::vector<Bezier> segments;
  segments.reserve(points.size() - 1);
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double h = parameters[i + 1] - parameters[i];
    segments.push_back(
        HermiteSegment{points[i], points[i + 1], tangents[i] * h, tangents[i + 1] * h}.to_bezier());
  }
  return segments;
}

Result<std::vector<Bezier>> hermite_spline(std::span<const Point> points, std::span<const Vec2> tangents) {
  std::vector<double> parameters(points.size());
  for (std::size_t i = 0; i < parameters.size(); ++i) parameters[i] = static_cast<double>(i);
  return hermite_spline(points, tangents, parameters);
}

}  // namespace curvescan
