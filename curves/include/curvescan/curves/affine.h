// Affine: a 2D affine transform, the six numbers of SVG's matrix(a b c d e f) and Cairo's cairo_matrix_t.
//
//   x' = a·x + c·y + e
//   y' = b·x + d·y + f
//
// Bézier and B-spline curves are affine-invariant (Ince, *Curves*, "Affine invariance property"), so a curve
// is transformed by transforming its control points.
#pragma once

#include <cmath>
#include <optional>

#include "curvescan/curves/point.h"

namespace curvescan {

struct Affine {
  double a = 1.0, b = 0.0, c = 0.0, d = 1.0, e = 0.0, f = 0.0;

  [[nodiscard]] static constexpr Affine identity() noexcept { return {}; }
  [[nodiscard]] static constexpr Affine translate(double tx, double ty) noexcept { return {1, 0, 0, 1, tx, ty}; }
  [[nodiscard]] static constexpr Affine scale(double sx, double sy) noexcept { return {sx, 0, 0, sy, 0, 0}; }
  [[nodiscard]] static constexpr Affine scale(double s) noexcept { return scale(s, s); }
  /// Rotation by `radians`, positive from +x towards +y (clockwise on a y-down screen, as in SVG).
  [[nodiscard]] static Affine rotate(double radians) noexcept {
    const double cs = std::cos(radians), sn = std::sin(radians);
    return {cs, sn, -sn, cs, 0, 0};
  }
  /// SVG skewX(angle): x' = x + tan(angle)·y.
  [[nodiscard]] static Affine skew_x(double radians) noexcept { return {1, 0, std::tan(radians), 1, 0, 0}; }
  /// SVG skewY(angle): y' = y + tan(angle)·x.
  [[nodiscard]] static Affine skew_y(double radians) noexcept { return {1, std::tan(radians), 0, 1, 0, 0}; }

  [[nodiscard]] constexpr Point apply(Point p) const noexcept {
    return {a * p.x + c * p.y + e, b * p.x + d * p.y + f};
  }
  /// Transforms a displacement: the linear part only.
  [[nodiscard]] constexpr Vec2 apply(Vec2 v) const noexcept { return {a * v.x + c * v.y, b * v.x + d * v.y}; }
  constexpr Point operator*(Point p) const noexcept { return apply(p); }
  constexpr Vec2 operator*(Vec2 v) const noexcept { return apply(v); }

  /// Composition: (this * o) applies `o` first, then `this` (as SVG's transform lists nest).
  [[nodiscard]] constexpr Affine operator*(const Affine& o) const noexcept {
    return {a * o.a + c * o.b,     b * o.a + d * o.b,     a * o.c + c * o.d,
            b * o.c + d * o.d,     a * o.e + c * o.f + e, b * o.e + d * o.f + f};
  }
  constexpr bool operator==(const Affine&) const noexcept = default;

  [[nodiscard]] constexpr double determinant() const noexcept { return a * d - b * c; }
  /// The inverse, or nullopt when the transform is singular or not finite.
  [[nodiscard]] std::optional<Affine> inverse() const noexcept {
    const double det = determinant();
    if (det == 0.0 || !std::isfinite(det)) return std::nullopt;
    const double inv = 1.0 / det;
    Affine r{d * inv, -b * inv, -c * inv, a * inv, 0, 0};
    r.e = -(r.a * e + r.c * f);
    r.f = -(r.b * e + r.d * f);
    return r;
  }
  [[nodiscard]] bool is_finite() const noexcept {
    return std::isfinite(a) && std::isfinite(b) && std::isfinite(c) && std::isfinite(d) && std::isfinite(e) &&
           std::isfinite(f);
  }
};

}  // namespace curvescan
