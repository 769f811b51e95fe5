// curve_point_along (stroke_curve_piece.h): regula falsi on a curve piece for the point whose projection on a
// chord's direction is given, and the exact tangent there.
#include <array>
#include <cmath>

#include "curvescan/raster/limits.h"
#include "stroke_curve_piece.h"

namespace curvescan::detail {
namespace {

// de Casteljau on homogeneous control points (Umetani, *Parametric Curve*, eq. 8), down to the last two points, whose
// difference is the curve's derivative direction at t and whose interpolation at t is the point.
class Casteljau {
 public:
  explicit Casteljau(std::span<const HomogeneousPoint> control) noexcept : control_(control) {}

  // The last two de Casteljau points at t (level_[0], level_[1]).
  void reduce(double t) noexcept {
    const std::size_t n = control_.size();
    for (std::size_t i = 0; i < n; ++i) level_[i] = control_[i];
    for (std::size_t size = n; size > 2; --size) {
      for (std::size_t i = 0; i + 1 < size; ++i) {
        level_[i] = {level_[i].x + t * (level_[i + 1].x - level_[i].x),
                     level_[i].y + t * (level_[i + 1].y - level_[i].y),
                     level_[i].w + t * (level_[i + 1].w - level_[i].w)};
      }
    }
  }

  Point point_at(double t) noexcept {
    reduce(t);
    const HomogeneousPoint a = level_[0], b = level_[1];
    const double w = a.w + t * (b.w - a.w);
    return {(a.x + t * (b.x - a.x)) / w, (a.y + t * (b.y - a.y)) / w};
  }

  // The direction from the first to the second of the last two points of the latest point_at(t).
  [[nodiscard]] Vec2 direction() const noexcept {
    return {level_[1].x / level_[1].w - level_[0].x / level_[0].w,
            level_[1].y / level_[1].w - level_[0].y / level_[0].w};
  }

 private:
  std::span<const HomogeneousPoint> control_;
  std::array<HomogeneousPoint, kMaxPathCurveDegree + 1> level_;  // written before read (reduce)
};

}  // namespace

std::optional<CurvePoint> curve_point_along(std::span<const HomogeneousPoint> control, Point q,
                                            Vec2 axis) noexcept {
  if (control.size() < 2 || control.size() > static_cast<std::size_t>(kMaxPathCurveDegree) + 1)
    return std::nullopt;
  Casteljau curve(control);
  double lo = 0.0, hi = 1.0;
  const auto end_point = [](HomogeneousPoint c) { return Point{c.x / c.w, c.y / c.w}; };
  double f_lo = (end_point(control.front()) - q).dot(axis), f_hi = (end_point(control.back()) - q).dot(axis);
  if (!(f_lo < 0.0 && f_hi > 0.0)) return std::nullopt;
  double t = 0.0;
  Point p;
  int side = 0;
  // Regula falsi converges superlinearly with the Illinois halving; 24 steps reach the projection to
  // ~1e-12 of the axis' squared length on any monotone piece (the bracket shrinks at least geometrically).
  for (int iteration = 0; iteration < 24; ++iteration) {
    t = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
    p = curve.point_at(t);
    const double f = (p - q).dot(axis);
    if (std::abs(f) <= 1e-12 * axis.dot(axis)) break;
    if (f < 0.0) {
      lo = t;
      f_lo = f;
      if (side == -1) f_hi *= 0.5;
      side = -1;
    } else {
      hi = t;
      f_hi = f;
      if (side == 1) f_lo *= 0.5;
      side = 1;
    }
  }
  // The loop's last point_at was at t (it breaks right after evaluating there, or ends there).
  const Vec2 d = curve.direction();
  const double length = d.length();
  if (!(length > 0.0)) return std::nullopt;
  return CurvePoint{p, d / length};
}

}  // namespace curvescan::detail
