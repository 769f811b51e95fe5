// Catmull–Rom splines through points, in the non-uniform (Barry–Goldman) formulation.
//
// Consecutive points P_{k-1}, P_k are given the knot interval |P_k - P_{k-1}|^α (Ince, *Curves*, "Spline
// Parametrization"): α = 0 uniform, α = 0.5 centripetal, α = 1 chordal. Centripetal is the recommended
// choice: no cusp or self-intersection within a segment (Yuksel, Schaefer, Keyser, "Parameterization and
// applications of Catmull–Rom curves", CAD 2011). Barry and Goldman's pyramid of interpolations over
// P0..P3 with knots t0..t3 is, on [t1, t2], the Hermite cubic with tangents (derivatives in t)
//
//   m1 = (P1 - P0)/(t1 - t0) - (P2 - P0)/(t2 - t0) + (P2 - P1)/(t2 - t1)
//   m2 = (P2 - P1)/(t2 - t1) - (P3 - P1)/(t3 - t1) + (P3 - P2)/(t3 - t2)
//
// so each segment is exactly the cubic Bézier P1, P1 + (t2 - t1) m1 / 3, P2 - (t2 - t1) m2 / 3, P2 (U. of
// Toronto, *Parametric Curves*, "Hermite Curves" with tangents scaled by the interval, as in hermite.h).
// Adjacent segments share the tangent at their common point, so the spline is C1 in the knot parameter t.
#pragma once

#include <span>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan {

inline constexpr double kCatmullRomUniform = 0.0;
inline constexpr double kCatmullRomCentripetal = 0.5;
inline constexpr double kCatmullRomChordal = 1.0;

/// The Catmull–Rom spline through `points` with knot exponent `alpha` in [0, 1], as cubic Béziers, one per
/// pair of consecutive (distinct) points, in order; segment i starts exactly at its point and ends exactly
/// at the next.
///  - Coincident consecutive points (equal coordinates, or so close that |ΔP|^α underflows to 0) are merged
///    into one before anything else: a zero knot interval would divide by zero, and a zero-length segment
///    draws nothing. For a closed spline the last point is also merged with the first, so repeating the
///    first point at the end is harmless.
///  - Open ends use a reflected phantom point: P_{-1} = 2 P_0 - P_1 and P_n = 2 P_{n-1} - P_{n-2}. (A
///    duplicated end point would give a zero knot interval for α > 0.) With it the end tangent is
///    (P_1 - P_0) / |P_1 - P_0|^α.
///  - Closed: one more segment from the last point back to the first, neighbours taken cyclically; the
///    result is C1 all round.
/// Fails on a NaN or infinite coordinate, alpha outside [0, 1] or NaN, fewer than 2 distinct points, or
/// points so far apart that a knot interval overflows.
[[nodiscard]] Result<std::vector<Bezier>> catmull_rom(std::span<const Point> points, double alpha,
                                                      bool closed = false);

}  // namespace curvescan
