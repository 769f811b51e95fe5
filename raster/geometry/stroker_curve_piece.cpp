// curve_point_along (stroke_curve_piece.h): safeguarded Newton on a curve piece for the point whose
// projection on a chord's direction is given, and the exact tangent there.
#include <array>
#include <cmath>

#include "curvescan/raster/limits.h"
#include "stroke_curve_piece.h"
#include "vector_length.h"

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

  // d/dt of the projection on `axis` of the curve at the latest point_at(t): with h = a + t·(b − a) the
  // homogeneous point from the last two de Casteljau points a, b, the homogeneous derivative is n·(b − a)
  // (n the degree) and the quotient rule gives P' = n·((b − a)_xy·h_w − h_xy·(b_w − a_w)) / h_w².
  [[nodiscard]] double slope_along(double t, Vec2 axis) const noexcept {
    const HomogeneousPoint a = level_[0], b = level_[1];
    const double hx = a.x + t * (b.x - a.x), hy = a.y + t * (b.y - a.y), hw = a.w + t * (b.w - a.w);
    const double dw = b.w - a.w;
    const Vec2 derivative{((b.x - a.x) * hw - hx * dw) / (hw * hw), ((b.y - a.y) * hw - hy * dw) / (hw * hw)};
    return static_cast<double>(control_.size() - 1) * derivative.dot(axis);
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

// Casteljau for the common case, a polynomial cubic (every weight 1): the same de Casteljau steps on
// plain points, unrolled. The homogeneous steps keep w = 1 exactly and divide by it, so both give the same
// doubles; this one only skips the w arithmetic and the loops.
class CubicCasteljau {
 public:
  explicit CubicCasteljau(std::span<const HomogeneousPoint> control) noexcept
      : p0_{control[0].x, control[0].y},
        p1_{control[1].x, control[1].y},
        p2_{control[2].x, control[2].y},
        p3_{control[3].x, control[3].y} {}

  static bool fits(std::span<const HomogeneousPoint> control) noexcept {
    return control.size() == 4 && control[0].w == 1.0 && control[1].w == 1.0 && control[2].w == 1.0 &&
           control[3].w == 1.0;
  }

  Point point_at(double t) noexcept {
    const Point a = lerp(p0_, p1_, t), b = lerp(p1_, p2_, t), c = lerp(p2_, p3_, t);
    a_ = lerp(a, b, t);
    b_ = lerp(b, c, t);
    return lerp(a_, b_, t);
  }

  [[nodiscard]] double slope_along(double, Vec2 axis) const noexcept { return 3.0 * (b_ - a_).dot(axis); }
  [[nodiscard]] Vec2 direction() const noexcept { return b_ - a_; }

 private:
  // The same expression as Casteljau::reduce: a + t·(b − a).
  static Point lerp(Point a, Point b, double t) noexcept {
    return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  }

  Point p0_, p1_, p2_, p3_;
  Point a_, b_;  // the last two de Casteljau points of the latest point_at
};

// The search of curve_point_along on `curve` (Casteljau or CubicCasteljau of `control`).
template <class Curve>
std::optional<CurvePoint> solve_along(Curve& curve, std::span<const HomogeneousPoint> control, Point q,
                                      Vec2 axis) noexcept {
  double lo = 0.0, hi = 1.0;
  const auto end_point = [](HomogeneousPoint c) { return Point{c.x / c.w, c.y / c.w}; };
  const double f_lo = (end_point(control.front()) - q).dot(axis),
               f_hi = (end_point(control.back()) - q).dot(axis);
  if (!(f_lo < 0.0 && f_hi > 0.0)) return std::nullopt;
  const double goal = 1e-12 * axis.dot(axis);
  // f(t) = (P(t) − q)·axis increases on [0, 1] (the piece is monotone along the axis). Newton's steps from
  // the chord's guess converge quadratically; a step that leaves the bracket [lo, hi] (where f changes sign),
  // or that did not halve the step before it, is replaced by bisection (rtsafe, Press et al., *Numerical
  // Recipes* §9.4), so the bracket shrinks at least geometrically: 64 steps reach double resolution on
  // [0, 1]. On random pieces of narrow cone (cubics within 0.15 of their chord) it takes 3.7 evaluations
  // on average to reach |f| <= 1e-12·|axis|², where regula falsi with the Illinois rule took 5.9.
  double t = -f_lo / (f_hi - f_lo);
  double step_before = 1.0;
  Point p;
  for (int iteration = 0; iteration < 64; ++iteration) {
    p = curve.point_at(t);
    const double f = (p - q).dot(axis);
    if (std::abs(f) <= goal) break;
    (f < 0.0 ? lo : hi) = t;
    const double slope = curve.slope_along(t, axis);
    double next = t - f / slope;
    if (!(next > lo && next < hi) || !(std::abs(next - t) <= 0.5 * step_before)) next = 0.5 * (lo + hi);
    step_before = std::abs(next - t);
    if (!(step_before > 0.0)) break;  // the bracket is down to adjacent doubles
    t = next;
  }
  // The loop's last point_at gave p (the loop breaks or ends right after a step's evaluation).
  const Vec2 d = curve.direction();
  const double length = vector_length(d);
  if (!(length > 0.0)) return std::nullopt;
  return CurvePoint{p, d / length};
}

}  // namespace

std::optional<CurvePoint> curve_point_along(std::span<const HomogeneousPoint> control, Point q,
                                            Vec2 axis) noexcept {
  if (control.size() < 2 || control.size() > static_cast<std::size_t>(kMaxPathCurveDegree) + 1)
    return std::nullopt;
  if (CubicCasteljau::fits(control)) {
    CubicCasteljau curve(control);
    return solve_along(curve, control, q, axis);
  }
  Casteljau curve(control);
  return solve_along(curve, control, q, axis);
}

}  // namespace curvescan::detail
