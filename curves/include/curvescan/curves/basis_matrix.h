// The 4×4 basis matrices of cubic curves, as data: P(t) = T · M · G with T = [t³ t² t 1] and G the
// geometry vector (U. of Toronto, *Parametric Curves*, "Parametric Cubic Curves"; Dill, *Introduction to
// Parametric Curves*, "Parametric Cubic (Hermite) Curves").
//
// Each matrix is the inverse of the constraint matrix that maps power-form coefficients to the geometry
// vector (Toronto notes: "The matrix B_inv is often called the basis matrix"), and the entries of T·M are
// the blending functions. Rows of M multiply t³, t², t, 1; columns belong to the rows of G.
#pragma once

#include <array>

#include "curvescan/curves/point.h"

namespace curvescan {

/// A 4×4 matrix stored row by row: m[row][column].
using BasisMatrix = std::array<std::array<double, 4>, 4>;

/// Bézier: G = [P0 P1 P2 P3] (U. of Toronto, *Parametric Curves*, "Bezier Curves", M_b = M_h M_bh; Dill,
/// *Introduction to Parametric Curves*, "Bezier Curves").
inline constexpr BasisMatrix kBezierBasis{{{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}}};

/// Hermite: G = [P0 P1 R0 R1], end points and end tangents (U. of Toronto, *Parametric Curves*, "Hermite
/// Curves", M_h; Dill, *Introduction to Parametric Curves*).
inline constexpr BasisMatrix kHermiteBasis{{{2, -2, 1, 1}, {-3, 3, -2, -1}, {0, 0, 1, 0}, {1, 0, 0, 0}}};

/// Uniform cubic B-spline segment: G = four consecutive control points [P_{i-1} P_i P_{i+1} P_{i+2}] (Dill,
/// *Introduction to Parametric Curves*, "B-Spline Curves", M_s = 1/6 [...]; U. of Toronto, *Parametric
/// Curves*, "Splines", M_bspline).
inline constexpr BasisMatrix kUniformBSplineBasis{{{-1.0 / 6, 3.0 / 6, -3.0 / 6, 1.0 / 6},
                                                   {3.0 / 6, -6.0 / 6, 3.0 / 6, 0.0},
                                                   {-3.0 / 6, 0.0, 3.0 / 6, 0.0},
                                                   {1.0 / 6, 4.0 / 6, 1.0 / 6, 0.0}}};

/// U. of Toronto, *Parametric Curves*, "A First Example": the cubic through P(0), P(0.5) and P(1) with
/// tangent T(0.5) at the midpoint, G = [P0 P0.5 T0.5 P1]. (The notes list its last blending function as
/// 4t³ - 4t² + 1; the matrix gives 4t³ - 4t² + t, which is the one that vanishes at t = 0 as it must.)
inline constexpr BasisMatrix kMidpointTangentBasis{
    {{-4, 0, -4, 4}, {8, -4, 6, -4}, {-5, 4, -2, 1}, {1, 0, 0, 0}}};

/// The blending functions T·M at t: entry j weights row j of the geometry vector.
/// NaN t gives NaN; t outside [0, 1] extrapolates.
[[nodiscard]] std::array<double, 4> blending_functions(const BasisMatrix& m, double t) noexcept;

/// The curve point T·M·G at t. Rows of `geometry` are coordinates: positions as their vector from the
/// origin (Point::to_vec), tangents as themselves; the result is read back as a position.
[[nodiscard]] Point eval_basis(const BasisMatrix& m, double t, const std::array<Vec2, 4>& geometry) noexcept;

}  // namespace curvescan
