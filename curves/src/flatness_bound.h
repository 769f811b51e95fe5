// flatness_bound.h (private to the flattener): a proven upper bound on the Hausdorff distance between a
// Bézier piece and its chord.
//
// Essay (the full derivation with figures is in docs/flattening.md).
//
// Let Q_0..Q_n be the control points of a polynomial Bézier piece C(t), or of a rational one with positive
// weights w_i, and S = [Q_0, Q_n] its chord, L = |Q_n - Q_0|, u = (Q_n - Q_0)/L. Write every point of the
// curve in the chord frame: s(t) = <C(t) - Q_0, u> along the chord (s(0) = 0, s(1) = L) and
// d(t) = <u x (C(t) - Q_0)> across it.
//
//  (1) curve -> chord: the distance from C(t) to S is sqrt(d(t)^2 + over(t)^2) with
//      over(t) = max(0, -s(t), s(t) - L), the overshoot past an end of the chord. So
//      sup_t dist(C(t), S) <= sqrt(max|d|^2 + max over^2).
//  (2) chord -> curve: s is continuous with s(0) = 0 and s(1) = L, so by the intermediate value theorem
//      every chord point X = Q_0 + s·u, 0 <= s <= L, equals Q_0 + s(t*)·u for some t*; then
//      |X - C(t*)| = |d(t*)| <= max|d|.
//  Hence   Hausdorff(C, S) <= sqrt(max|d|^2 + max over^2).                                             (B)
//
// d and s are affine images of C, so they are Bernstein polynomials (Ince, *Curves*, "Bernstein Polynomials") with
// coefficients d_i, s_i (the frame coordinates of Q_i), or, for a rational piece, ratios
// sum w_i d_i B_i / sum w_i B_i. Their ranges on [0, 1]:
//  - polynomial, degree <= 3, and rational quadratic (conics): EXACT. The extrema are at t = 0, t = 1 or
//    where the derivative vanishes; the derivative of a cubic is a quadratic, and for a ratio N/D of
//    quadratics N'D - ND' is a quadratic too (its cubic terms cancel). Both are solved in closed form.
//  - higher degrees: the convex hull property (Ince, *Curves*, "Convex hull property", U. of Toronto, *Parametric Curves*, "Convex hull
//    property"): positive weights summing to one make the value a convex combination of the d_i, so it
//    lies in [min d_i, max d_i]. We take that hull after two levels of exact halving (4 pieces), which is
//    still a proven enclosure (each piece is a Bézier with its own hull) and about 4x tighter.
// A second, frame-free bound always holds: the curve lies in the hull of the Q_i, hence within
// R = max|Q_i - Q_0| of Q_0, and every chord point is within L <= R of Q_0, which is on the curve; so
// Hausdorff <= R. It is used when the chord is degenerate (L tiny against R: coincident end points,
// a closed loop) and as a cap on (B) otherwise.
//
// Floating point: coefficients are scaled by 1/R before any arithmetic (no overflow or underflow at any
// scale). The frame coordinates carry a relative error of a few ulps of R, and an extremum evaluated at a
// root that is off by delta is low by O(delta^2) (the derivative vanishes there); both are far below the
// margin of 1e-9·R added to the result, see kRoundingMargin in flatness_bound.cpp.
#pragma once

#include <span>

#include "curvescan/curves/point.h"

namespace curvescan::detail {

/// An upper bound on the Hausdorff distance between the Bézier piece with control points `ctrl` and the
/// segment [ctrl.front(), ctrl.back()], in the units of the points. `weights` empty: a polynomial piece;
/// otherwise one positive weight per point (a rational piece). Returns 0 for coincident points, +inf when
/// the coordinate differences overflow; NaN in (points or weights), NaN or inf out. Needs >= 1 point.
[[nodiscard]] double chord_distance_bound(std::span<const Point> ctrl,
                                          std::span<const double> weights) noexcept;

/// The plain hull bound sqrt(max|d_i|^2 + max over_i^2) with no exact extrema: the obviously-correct
/// reference that chord_distance_bound() must never exceed (tests hold them to that).
[[nodiscard]] double chord_distance_hull_bound(std::span<const Point> ctrl) noexcept;

}  // namespace curvescan::detail
