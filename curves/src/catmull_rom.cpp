// Non-uniform Catmull–Rom splines (Ince, *Curves*, "Spline Parametrization"; Barry & Goldman 1988; Yuksel et al.
// 2011) converted to cubic Béziers through their Hermite form (U. of Toronto, *Parametric Curves*, "Hermite Curves").
#include "curvescan/curves/catmull_rom.h"

#include <cmath>
#include <string>

namespace curvescan {
namespace {

Error invalid(std::string message) {
  return Error{ErrorKind::kInvalidArgument, std::move(message)};
}

// The knot interval between two points: |b - a|^alpha, 0 for coincident points (also when alpha = 0).
double knot_interval(Point a, Point b, double alpha) noexcept {
  const double distance = a.distance(b);
  return distance == 0.0 ? 0.0 : std::pow(distance, alpha);
}

// The cubic Bézier of the segment p1 -> p2 with neighbours p0, p3 and knot intervals d0, d1, d2 > 0.
Bezier segment(Point p0, Point p1, Point p2, Point p3, double d0, double d1, double d2) {
  const Vec2 m1 = (p1 - p0) / d0 - (p2 - p0) / (d0 + d1) + (p2 - p1) / d1;
  const Vec2 m2 = (p2 - p1) / d1 - (p3 - p1) / (d1 + d2) + (p3 - p2) / d2;
  return Bezier({p1, p1 + m1 * (d1 / 3.0), p2 - m2 * (d1 / 3.0), p2});
}

}  // namespace

Result<std::vector<Bezier>> catmull_rom(std::span<const Point> points, double alpha, bool closed) {
  if (!(alpha >= 0.0 && alpha <= 1.0)) {
    return invalid("Catmull-Rom alpha must be in [0, 1] (0 uniform, 0.5 centripetal, 1 chordal), got " +
                   std::to_string(alpha) + ".");
  }
  std::vector<Point> distinct;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].is_finite())
      return invalid("point " + std::to_string(i) + " has a NaN or infinite coordinate.");
    if (distinct.empty() || knot_interval(distinct.back(), points[i], alpha) > 0.0)
      distinct.push_back(points[i]);
  }
  if (closed) {
    while (distinct.size() > 1 && !(knot_interval(distinct.back(), distinct.front(), alpha) > 0.0)) {
      distinct.pop_back();
    }
  }
  const std::size_t n = distinct.size();
  if (n < 2) {
    return invalid("a Catmull-Rom spline needs at least 2 distinct points, got " + std::to_string(n) + ".");
  }
  // The extended sequence Q_0 .. Q_{segments + 2}: the segment i runs Q_{i+1} -> Q_{i+2}.
  std::vector<Point> extended;
  if (closed) {
    extended.push_back(distinct[n - 1]);
    extended.insert(extended.end(), distinct.begin(), distinct.end());
    extended.push_back(distinct[0]);
    extended.push_back(distinct[1 % n]);
  } else {
    extended.push_back(distinct[0] + (distinct[0] - distinct[1]));
    extended.insert(extended.end(), distinct.begin(), distinct.end());
    extended.push_back(distinct[n - 1] + (distinct[n - 1] - distinct[n - 2]));
  }
  std::vector<double> intervals(extended.size() - 1);
  for (std::size_t i = 0; i + 1 < extended.size(); ++i) {
    intervals[i] = knot_interval(extended[i], extended[i + 1], alpha);
    // Distinct neighbours give intervals > 0; a phantom point can overflow, or an interval underflow.
    if (!std::isfinite(intervals[i]) || !(intervals[i] > 0.0)) {
      return invalid(
          "Catmull-Rom points are too far apart or too close for a finite, non-zero knot interval.");
    }
  }
  const std::size_t segment_count = closed ? n : n - 1;
  std::vector<Bezier> segments;
  segments.reserve(segment_count);
  for (std::size_t i = 0; i < segment_count; ++i) {
    segments.push_back(segment(extended[i], extended[i + 1], extended[i + 2], extended[i + 3], intervals[i],
                               intervals[i + 1], intervals[i + 2]));
  }
  return segments;
}

}  // namespace curvescan
