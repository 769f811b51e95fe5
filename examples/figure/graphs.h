// Graphs of the notes' basis and blending functions, drawn exactly as curves.
//
// Each function is a polynomial (or piecewise polynomial) of the parameter, so its graph (u, f(u)) IS a
// (piecewise) Bézier curve in the plane and needs no sampling:
//  - B-spline basis function N_{i,p} (Umetani eq. 6–7): the B-spline curve whose control points are
//    (Greville abscissa ξ_j, δ_ij). Its x coordinate is Σ_j ξ_j N_j(u) = u (linear precision of the
//    B-spline basis: the Greville abscissae ξ_j = (u_{j+1} + ... + u_{j+p}) / p reproduce the identity)
//    and its y coordinate Σ_j δ_ij N_j(u) = N_i(u). Converted to Bézier pieces by BSpline::to_beziers.
//  - Bernstein polynomial B_{n,i} (Dill "Bezier Curves", Gallivan): the degree-n Bézier with control
//    points (k/n, δ_ik), for the same reason (Σ_k (k/n) B_{n,k}(t) = t).
//  - Cubic blending functions T·M (basis_matrix.h): power-form coefficients converted by power_to_bezier.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "curvescan/curves/basis_matrix.h"
#include "curvescan/curves/bezier.h"

namespace curvescan::figure {

/// The graph of N_{i,p}(u) over its support [u_i, u_{i+p+1}] on `knots` as Bézier pieces of degree p in
/// the (u, N) plane (for p = 0, the horizontal segment at height 1). Empty when i + p + 1 is outside the
/// knot vector, the support is empty, or the degree is negative.
[[nodiscard]] std::vector<Bezier> basis_function_graph(std::span<const double> knots, int degree,
                                                       std::size_t i);

/// N_{i,p}(u) on `knots` over the whole real line: the Cox–de Boor value inside the support [u_i, u_{i+p+1})
/// (and at its right end when that is the last knot), 0 outside. Unlike curvescan::bspline_basis, which
/// follows the curve's conventions and extends the end spans' polynomials outside the domain [u_p, u_n]
/// (bspline.h), this is the textbook function the notes plot, also on the first and last p spans.
/// NaN for NaN u; 0 for an index or degree out of range.
[[nodiscard]] double basis_function(std::span<const double> knots, int degree, std::size_t i, double u);

/// The graph of the Bernstein polynomial B_{n,i}(t), t in [0, 1], as one Bézier of degree n.
[[nodiscard]] Bezier bernstein_graph(int n, int i);

/// The graph of blending function `column` of basis matrix `m` (entry `column` of T·M), t in [0, 1],
/// as one cubic Bézier.
[[nodiscard]] Bezier blending_graph(const BasisMatrix& m, int column);

/// The graph of the quadratic polynomial through (a, fa), ((a+b)/2, fm), (b, fb) over [a, b] as one
/// quadratic Bézier: exact when the function is a quadratic (the interpolant of three of its values).
[[nodiscard]] Bezier quadratic_graph(double a, double b, double fa, double fm, double fb);

}  // namespace curvescan::figure
