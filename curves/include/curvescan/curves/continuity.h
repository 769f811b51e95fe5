// Continuity of the join between two Bézier curves: the end of `a` meeting the start of `b`.
//
// U. of Toronto, *Parametric Curves*, "Geometric and Parametric Continuity"; Dill, *Introduction to
// Parametric Curves*, "Continuity Definition":
//   C0 / G0: the curves meet;  C1: equal first derivatives;  C2: equal first and second derivatives;
//   G1: tangents with the same direction (magnitudes may differ);  G2: G1 and the same curvature.
// The end derivatives of a Bézier are finite differences of its end control points (Dill, "Joining
// Bezier Curves": P'(1) = 3(P3 - P2), Q'(0) = 3(Q1 - Q0)): A'(1) = n (P_n - P_{n-1}),
// A''(1) = n (n-1) (P_n - 2 P_{n-1} + P_{n-2}), and the same at the start of B.
//
// G2 is tested as equal signed curvature κ = (A' × A'') / |A'|³, the reparametrization-invariant meaning of
// the Toronto notes' "first and second derivatives proportional": under a reparametrization s(t) with s' = k,
// B'' = k² A'' + s'' A', so requiring B'' ∝ A'' alone would reject joins that are geometrically G2.
//
// A zero end tangent leaves the tangent direction undefined: such a join is reported G0 even when it is
// C1 (the classic case where C^k does not imply G^k).
#pragma once

#include "curvescan/curves/bezier.h"

namespace curvescan {

/// The relative tolerance classify_join uses by default: far above the rounding of control points built by
/// arithmetic (~1e-15) and far below any visible difference.
inline constexpr double kDefaultJoinTolerance = 1e-9;

/// The highest orders of continuity, each at most 2, or -1 when the curves do not meet at all.
struct JoinContinuity {
  int parametric = -1;  ///< k of the highest C^k
  int geometric = -1;   ///< k of the highest G^k
  constexpr bool operator==(const JoinContinuity&) const noexcept = default;
};

/// Classifies the join of a's end with b's start. Comparisons are relative: two vectors u, v (positions,
/// first or second derivatives) are equal when |u - v| <= tolerance · max(|u|, |v|, L), L the size of the
/// box of all control points of both curves (so near-zero derivatives are compared against the scale of
/// the drawing, not against each other); directions are equal when their unit vectors differ by at most
/// `tolerance`; curvatures when |κa - κb| <= tolerance · max(|κa|, |κb|, 1/L).
/// Curves with no points, or NaN anywhere (including the tolerance), give {-1, -1}.
[[nodiscard]] JoinContinuity classify_join(const Bezier& a, const Bezier& b,
                                           double relative_tolerance = kDefaultJoinTolerance) noexcept;

}  // namespace curvescan
