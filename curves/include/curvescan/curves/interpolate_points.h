// Interpolating polynomial curves through given points, and the power form to Bézier conversion.
//
// Ince, *Curves*, "Representations of Curves: Parametric Representation": a quadratic p(t) = a t² + b t + c
// through p0 at t = 0, p1 at t = t1 and p2 at t = 1 has
//
//   c = p0,   a = (t1 (p2 - p0) + (p0 - p1)) / (t1 (1 - t1)),   b = p2 - p0 - a,
//
// the inverse of the interpolation matrix [[0 0 1], [t1² t1 1], [1 1 1]]. The notes ask "Can you get the
// interpolation matrix for cubic curves?": for four parameters t_k it is the inverse of the Vandermonde
// matrix with rows [t_k³ t_k² t_k 1], whose column j holds the power-form coefficients of the Lagrange
// polynomial L_j(t) = prod_{k != j} (t - t_k) / (t_j - t_k).
#pragma once

#include <array>
#include <optional>
#include <span>

#include "curvescan/curves/basis_matrix.h"
#include "curvescan/curves/bezier.h"
#include "curvescan/curves/point.h"

namespace curvescan {

/// p(t) = a t² + b t + c.
struct QuadraticPowerForm {
  Vec2 a;
  Vec2 b;
  Point c;

  [[nodiscard]] Point eval(double t) const noexcept { return c + (a * t + b) * t; }
  /// The same curve as a quadratic Bézier: P0 = c, P1 = c + b/2, P2 = c + b + a.
  [[nodiscard]] Bezier to_bezier() const;
};

/// p(t) = a t³ + b t² + c t + d.
struct CubicPowerForm {
  Vec2 a;
  Vec2 b;
  Vec2 c;
  Point d;

  [[nodiscard]] Point eval(double t) const noexcept { return d + ((a * t + b) * t + c) * t; }
  /// The same curve as a cubic Bézier: P0 = d, P1 = d + c/3, P2 = d + 2c/3 + b/3, P3 = d + c + b + a.
  [[nodiscard]] Bezier to_bezier() const;
};

/// The quadratic through p0 (t = 0), p1 (t = t1) and p2 (t = 1), by Ince's formula above.
/// nullopt when t1 is 0, 1 or not finite (the interpolation matrix is singular or undefined); NaN points
/// give NaN coefficients.
[[nodiscard]] std::optional<QuadraticPowerForm> interpolate_quadratic(Point p0, Point p1, Point p2,
                                                                      double t1) noexcept;

/// The cubic interpolation matrix: the inverse of the matrix with rows [t_k³ t_k² t_k 1], so that the
/// coefficients [a b c d] of the cubic through points P_k at t_k are M · [P_0 .. P_3]. nullopt when two
/// parameters coincide or one is not finite.
[[nodiscard]] std::optional<BasisMatrix> cubic_interpolation_matrix(
    const std::array<double, 4>& params) noexcept;

/// The cubic through points[k] at params[k], k = 0..3 (any distinct finite parameters).
[[nodiscard]] std::optional<CubicPowerForm> interpolate_cubic(const std::array<Point, 4>& points,
                                                              const std::array<double, 4>& params) noexcept;

/// The Bézier control points of the polynomial sum_j coefficients[j] t^j (ascending powers; coefficients[0]
/// is the position at t = 0 as a vector from the origin), of degree coefficients.size() - 1:
/// P_i = sum_{j <= i} C(i, j) / C(n, j) · coefficients[j] (the power basis in Bernstein terms,
/// t^j = sum_{i >= j} C(i, j) / C(n, j) B_{n,i}(t)). Empty input gives an empty curve.
[[nodiscard]] Bezier power_to_bezier(std::span<const Vec2> coefficients);

}  // namespace curvescan
