// flatten_conic.h (private to the flattener): conics (rational quadratic Béziers: circular arcs, ellipses,
// NURBS circles) flattened with an O(1) exact bound per trial, no de Casteljau split of control arrays and
// no general chord frame.
//
// Essay. Let the conic have homogeneous control points H_i = (w_i·P_i, w_i), w_i > 0 (Umetani, *Parametric Curve*, §4.1), and
// H(u, v) = lerp(lerp(H0, H1, u), lerp(H1, H2, u), v) its blossom (symmetric, affine in each argument):
// the sub-arc [a, b] is the conic with homogeneous control points H(a, a), H(a, b), H(b, b) (Gallivan, *Parametric Curves*
// "DeCasteljau's Algorithm": the de Casteljau triangle at a, then at b, is the blossom). Project them:
// Q_i = (q_i, W_i). A Möbius reparametrization of [0, 1] puts any rational quadratic into standard form,
// end weights 1 and middle weight k = W1 / sqrt(W0·W2), without changing its image.
//
//  (i)  Across the chord. In the chord frame of [q0, q2], with d1 the signed distance of q1 from the
//       chord's line, the standard form gives d(t) = 2k·t(1-t)·d1 / (1 - 2t(1-t)(1-k)). With s = t(1-t)
//       in [0, 1/4], f(s) = 2k·s / (1 - 2s(1-k)) has f'(s) = 2k / (1 - 2s(1-k))^2 > 0, so the maximum is
//       at t = 1/2: max|d| = k/(1+k)·|d1| = k/(1+k)·|(q1 - q0) x (q2 - q0)| / |q2 - q0|, exactly.
//  (ii) Along the chord the coordinate is a convex combination (positive rational Bernstein weights) of
//       0, s1 = <q1 - q0, u>, and L = |q2 - q0|: it stays in [0, L] when 0 <= s1 <= L, so there is no
//       overshoot and (B) of flatness_bound.h, Hausdorff(arc, chord) <= sqrt(max|d|^2 + max over^2),
//       is max|d| itself. Otherwise (a sub-arc turning by more than 90° against its chord, rare at any
//       useful tolerance) the general exact bound chord_distance_bound takes the piece.
//  (iii) A chord short against R = max(|q1 - q0|, |q2 - q0|) (L < 1e-4·R: a nearly closed piece) has no
//       trustworthy direction: the frame-free bound R of flatness_bound.h is used.
//
// Walk: the shared step search (flatten_step_search.h) with this O(1) bound in place of split + general
// bound; vertices are the de Casteljau points of the original homogeneous control points, bit for bit the
// general walk's, so the polyline keeps flatten.h's contract.
//
// Rounding. The projected q_i carry an absolute error of a few ulps of M = max|coordinate| of the control
// points (a product and a division each); the cross product and the chord length inherit it, so max|d| is
// off by at most ~4·eps·M·R/L, and by a relative ~1e4·eps from the rest (L >= 1e-4·R). The margin added is
// 1e-9·R (as the general bound's) + 16·eps·M·(1 + R/L). The closed form is used when 16·eps·M is at most
// 1.6e-5 of the tolerance and the coordinates are within 1e±100; otherwise the general walk takes the curve.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/curves/point.h"

namespace curvescan::detail {

/// The proven bound above, margins included, on the Hausdorff distance between the sub-arc [a, b]
/// (0 <= a < b <= 1) of the conic (ctrl, weights) (3 points, weights > 0) and its chord. NaN in, NaN out.
/// Meant for tests: the flattener evaluates the same formula with the constants hoisted.
[[nodiscard]] double conic_arc_chord_bound(std::span<const Point> ctrl, std::span<const double> weights,
                                           double a, double b) noexcept;

/// Flattens the conic (ctrl, weights) (3 finite points with finite differences, 3 finite weights > 0,
/// finite tolerance > 0) with the contract of flatten_rational. Returns nothing, and appends nothing, when
/// the closed form does not apply (see "Rounding"): the caller then runs the general walk.
std::optional<FlattenOutcome> flatten_conic(std::span<const Point> ctrl, std::span<const double> weights,
                                            double tolerance, std::vector<Point>& out,
                                            std::size_t max_segments = kMaxFlattenSegments);

}  // namespace curvescan::detail
