// Bicubic Bézier surface patches and their isoparametric curves (Ince after Elias, *Lecture 11: Curves*,
// "Bézier surfaces": a surface computed this way is a bicubic Bézier patch, and 32 of them make the Utah
// teapot), projected to the plane by a view (view_transform.h).
//
// S(u, v) = Σ_i Σ_j B_i(u) B_j(v) P_ij with the cubic Bernstein polynomials B. Fixing u gives a cubic in v
// whose control points are the de Casteljau points at u of the four columns, and likewise for v: the
// isoparametric curves are exact cubics. A projective view maps a cubic with control points Q_j to the
// rational cubic with control points (X_j / W_j, Y_j / W_j) and weights W_j, (X_j, Y_j, W_j) the
// homogeneous images of Q_j: the projection of the curve, exactly (Farin, *Curves and Surfaces for CAGD*,
// ch. 12, "rational Bézier curves" as projections).
#pragma once

#include <array>

#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan {

/// A point of 3D space.
struct Point3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  constexpr bool operator==(const Point3&) const noexcept = default;
};

/// A bicubic Bézier patch: control points P_ij at points[4 * i + j], i along u, j along v.
struct BezierPatch {
  std::array<Point3, 16> points;

  /// S(u, v) by de Casteljau in 3D (u, v in [0, 1]; other values extrapolate).
  [[nodiscard]] Point3 eval(double u, double v) const noexcept;
  /// The control points of the cubic v -> S(u, v).
  [[nodiscard]] std::array<Point3, 4> curve_at_u(double u) const noexcept;
  /// The control points of the cubic u -> S(u, v).
  [[nodiscard]] std::array<Point3, 4> curve_at_v(double v) const noexcept;
};

/// The control points of the cubic Bézier with control points `ctrl` at t, by de Casteljau.
Point3 de_casteljau_3d(const std::array<Point3, 4>& ctrl, double t) noexcept;

}  // namespace curvescan
