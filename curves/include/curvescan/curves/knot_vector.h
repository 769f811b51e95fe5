// Knot vectors for B-splines and NURBS: the standard generators and the one validator.
//
// A B-spline of degree p with n control points has m + 1 = n + p + 1 non-decreasing knots u_0 <= ... <= u_m
// (Umetani, *Parametric Curve*, §3, "m = n + p"; Gallivan, *Parametric Curves*, "B-spline Curves", m = n + d + 1 with n counted from 0). The curve is
// defined on the domain [u_p, u_{m-p}] = [u_p, u_n], where exactly p + 1 basis functions are non-zero on each
// non-empty knot span (Umetani, *Parametric Curve*, §3.2). The number of times a value repeats is its multiplicity (Umetani, *Parametric Curve*
// §3.1); a first and last knot of multiplicity p + 1 clamp the curve to its end points (Gallivan, *Parametric Curves*).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "curvescan/status.h"

namespace curvescan {

/// Checks that `knots` is a valid knot vector for `point_count` control points of degree `degree`:
/// degree >= 0, point_count >= degree + 1, knots.size() == point_count + degree + 1, every knot finite,
/// non-decreasing, no value repeated more than degree + 1 times, and a non-empty domain u_p < u_n.
/// The error message names the first violation found (index and values).
[[nodiscard]] Status validate_knots(std::span<const double> knots, std::size_t point_count, int degree);

/// The clamped (open uniform) knot vector on [0, 1]: degree + 1 zeros, the interior knots
/// i / (n - p) for i = 1 .. n - p - 1, degree + 1 ones. The curve starts at its first control point and ends
/// at its last (Gallivan, *Parametric Curves*, "first and last knot with multiplicity d+1 clamps curve").
/// Fails when degree < 0 or point_count < degree + 1.
[[nodiscard]] Result<std::vector<double>> clamped_knots(std::size_t point_count, int degree);

/// The uniform knot vector u_i = i, i = 0 .. n + p: every basis function is a translate of one
/// (Dill, *Introduction to Parametric Curves*, "Uniform BSpline", knots at equal intervals). Domain [p, n]; the curve does not, in general,
/// touch any control point. Fails when degree < 0 or point_count < degree + 1.
[[nodiscard]] Result<std::vector<double>> uniform_knots(std::size_t point_count, int degree);

/// The closed (periodic) knot vector for a closed curve through `point_count` distinct control points:
/// uniform knots u_i = i, i = 0 .. n + 2p, to be used with the n + p control points P_0 .. P_{n-1},
/// P_0 .. P_{p-1} (the first p wrapped to the end; Gallivan, *Parametric Curves*, "repeating knots and control points closes the
/// curve"). Domain [p, n + p]; the curve is closed and C^{p-1} at the seam.
/// Fails when degree < 1 or point_count < degree + 1.
[[nodiscard]] Result<std::vector<double>> periodic_knots(std::size_t point_count, int degree);

}  // namespace curvescan
