// C2 interpolating cubic splines through points.
//
// The points P_0 .. P_n get parameters t_i (Gallivan, *Parametric Curves*, "Parameterization"): uniform
// t_i = i / n on [0, 1], or cumulative chord length t_i = sum_{k<=i} |P_k - P_{k-1}|. x(t) and y(t) are
// then fitted separately (Gallivan) by the cubic spline of Dill, *Introduction to Parametric Curves* ("A
// Physical Basis for Cubic Splines": a piecewise cubic with C2 joints) and Ince, *Curves* ("Spline
// Interpolation", the piece between two points from positions and derivatives). With M_i the second
// derivative at t_i and h_i = t_{i+1} - t_i, C2 continuity gives the tridiagonal system (the standard
// moment equations, e.g. de Boor, "A Practical Guide to Splines", ch. IV)
//
//   h_{i-1} M_{i-1} + 2 (h_{i-1} + h_i) M_i + h_i M_{i+1} = 6 (s_i - s_{i-1}),   s_i = (P_{i+1} - P_i) / h_i
//
// closed by the end conditions: natural (M_0 = M_n = 0), clamped (given P'(t_0), P'(t_n)), or closed
// (periodic: indices wrap, a cyclic tridiagonal system solved with the Sherman–Morrison correction).
// Each piece is returned as the cubic Bézier with the same end points and end derivatives
// (Dill, *Introduction to Parametric Curves*, "Bezier Curves": R1 = 3 (P2 - P1)), i.e. exact.
#pragma once

#include <span>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan {

enum class SplineParameterization {
  /// t_i = i / n on [0, 1] (Gallivan, *Parametric Curves*, "Simple uniform scale")
  kUniform,
  /// t_i = cumulative distance along the points (Gallivan, *Parametric Curves*, "Cumulative length scale")
  kChordLength,
};

enum class SplineEnds {
  kNatural,  ///< zero second derivative at both ends
  kClamped,  ///< given first derivatives at both ends (start_tangent, end_tangent)
  kClosed,   ///< periodic: one more piece from the last point back to the first, C2 all round
};

struct CubicSplineOptions {
  SplineParameterization parameterization = SplineParameterization::kChordLength;
  SplineEnds ends = SplineEnds::kNatural;
  /// For kClamped: dP/dt at the first and last point, t being the chosen parameter (so with kUniform on
  /// [0, 1] a tangent is n times the displacement per point).
  Vec2 start_tangent{};
  Vec2 end_tangent{};
};

/// The parameters t_i for `points` (n + 1 values for n + 1 open points; for a closed spline one more, the
/// parameter at which the curve returns to points[0]). For a closed spline a last point equal to the first
/// is dropped first (the closing piece is implied). Fails on a non-finite coordinate, too few points
/// (2 open, 3 closed after dropping) or, for chord length, two consecutive points that coincide.
[[nodiscard]] Result<std::vector<double>> spline_parameters(std::span<const Point> points,
                                                            SplineParameterization parameterization,
                                                            bool closed);

/// The interpolating C2 cubic spline through `points` as cubic Béziers, piece i from points[i] to
/// points[i+1] (and, when closed, a last piece back to points[0]). Fails as spline_parameters does, or
/// on a non-finite clamped tangent.
[[nodiscard]] Result<std::vector<Bezier>> cubic_spline(std::span<const Point> points,
                                                       const CubicSplineOptions& options = {});

}  // namespace curvescan
