// Point and Vec2: positions and displacements in the plane.
//
// After kurbo (src/point.rs): they are different types, so that the algebra says what a value is.
// Point - Point -> Vec2, Point + Vec2 -> Point; there is no Point + Point. An affine combination of points
// (de Casteljau, B-spline blending) is written with lerp() or as origin + weighted vectors.
// Units are whatever the caller's space is: user units before a transform, device pixels after.
#pragma once

#include <cmath>

namespace curvescan {

/// A displacement (dx, dy).
struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  constexpr Vec2 operator+(Vec2 o) const noexcept { return {x + o.x, y + o.y}; }
  constexpr Vec2 operator-(Vec2 o) const noexcept { return {x - o.x, y - o.y}; }
  constexpr Vec2 operator-() const noexcept { return {-x, -y}; }
  constexpr Vec2 operator*(double s) const noexcept { return {x * s, y * s}; }
  constexpr Vec2 operator/(double s) const noexcept { return {x / s, y / s}; }
  constexpr Vec2& operator+=(Vec2 o) noexcept { x += o.x; y += o.y; return *this; }
  constexpr Vec2& operator-=(Vec2 o) noexcept { x -= o.x; y -= o.y; return *this; }
  constexpr Vec2& operator*=(double s) noexcept { x *= s; y *= s; return *this; }
  constexpr bool operator==(const Vec2&) const noexcept = default;

  /// Dot product.
  [[nodiscard]] constexpr double dot(Vec2 o) const noexcept { return x * o.x + y * o.y; }
  /// z-component of the 3D cross product: positive when `o` turns counter-clockwise from *this
  /// in a y-up frame (clockwise on screen, where y points down).
  [[nodiscard]] constexpr double cross(Vec2 o) const noexcept { return x * o.y - y * o.x; }
  [[nodiscard]] double length() const noexcept { return std::hypot(x, y); }
  [[nodiscard]] constexpr double length_squared() const noexcept { return x * x + y * y; }
  /// Unit vector in the same direction; NaN components for the zero vector.
  [[nodiscard]] Vec2 normalized() const noexcept { return *this / length(); }
  /// Rotated by +90 degrees: (-y, x).
  [[nodiscard]] constexpr Vec2 perp() const noexcept { return {-y, x}; }
  [[nodiscard]] bool is_finite() const noexcept { return std::isfinite(x) && std::isfinite(y); }
};

constexpr Vec2 operator*(double s, Vec2 v) noexcept { return v * s; }

/// A position (x, y).
struct Point {
  double x = 0.0;
  double y = 0.0;

  constexpr Point operator+(Vec2 v) const noexcept { return {x + v.x, y + v.y}; }
  constexpr Point operator-(Vec2 v) const noexcept { return {x - v.x, y - v.y}; }
  constexpr Vec2 operator-(Point o) const noexcept { return {x - o.x, y - o.y}; }
  constexpr Point& operator+=(Vec2 v) noexcept { x += v.x; y += v.y; return *this; }
  constexpr bool operator==(const Point&) const noexcept = default;

  /// The vector from the origin to this point (for weighted sums whose weights add to one).
  [[nodiscard]] constexpr Vec2 to_vec() const noexcept { return {x, y}; }
  [[nodiscard]] static constexpr Point from_vec(Vec2 v) noexcept { return {v.x, v.y}; }
  [[nodiscard]] double distance(Point o) const noexcept { return (*this - o).length(); }
  [[nodiscard]] bool is_finite() const noexcept { return std::isfinite(x) && std::isfinite(y); }
};

/// The point (1-t)·a + t·b, exact at t = 0 and t = 1.
[[nodiscard]] constexpr Point lerp(Point a, Point b, double t) noexcept {
  return {a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t};
}

/// Midpoint of a and b.
[[nodiscard]] constexpr Point midpoint(Point a, Point b) noexcept { return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y)}; }

}  // namespace curvescan
