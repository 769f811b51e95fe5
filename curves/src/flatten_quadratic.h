// flatten_quadratic.h (private to the flattener): quadratic Béziers flattened in closed form, O(1) work
// per segment, no de Casteljau split and no chord frame per trial.
//
// Essay. Let B(t) = (1-t)^2 P0 + 2t(1-t) P1 + t^2 P2, E = P1 - P0, D = P0 - 2P1 + P2, so that
// V(t) = E + t·D = B'(t)/2 and B''(t) = 2D (Ince, *Curves*, "Bernstein Polynomials", Gallivan, *Parametric Curves*, "DeCasteljau's
// Algorithm": the derivative of a Bézier is the Bézier of the differences). Take the sub-arc [a, b],
// h = b - a, m = (a + b)/2, and reparametrize it as g(s) = B(a + s·h), s in [0, 1].
//
//  (i)  Chord. B' is linear in t, so B(b) - B(a) = integral of B' = h·B'(m) = 2h·V(m) exactly: the chord is
//       parallel to the tangent at the parameter midpoint; its length is L = 2h·|V(m)|.
//  (ii) Deviation from the linear interpolant. g'' = 2h^2·D is constant and g - lerp(g(0), g(1), s)
//       vanishes at s = 0 and s = 1, so g(s) = g(0) + s·(g(1) - g(0)) - h^2·D·s(1-s).
//  (iii) Chord frame: u = V(m)/|V(m)|. Across the chord d(s) = u x (g(s) - g(0)) = -h^2 (u x D) s(1-s)
//       (the s-term is along u), so max|d| = h^2 |u x D| / 4 = h^2·|E x D| / (4|V(m)|), because
//       V(m) x D = E x D + m·(D x D) = E x D: the cross product is the same for every sub-arc.
//       Along the chord, with c = h^2 (u·D): s(σ) = σ·L - c·σ(1-σ) = σ(L - c) + c·σ^2. It leaves [0, L]
//       only if |c| > L (the tangent at one end points backwards along the chord), by at most
//       over = (|c| - L)^2 / (4|c|) (the vertex of that parabola in σ; by the symmetry σ -> 1 - σ the same
//       at the far end when c < -L).
//  (iv) The bound of flatness_bound.h, Hausdorff(arc, chord) <= sqrt(max|d|^2 + max over^2) (curve ->
//       chord by the clamped projection, chord -> curve by the intermediate value theorem on s), holds
//       with the exact max|d| and max over of (iii): it is the same number chord_distance_bound computes
//       for the split control points, with no split. Independently, (ii) with lerp sweeping the whole
//       chord gives Hausdorff <= max |g - lerp| = h^2 |D| / 4 (Wang's bound, exact in parameter space):
//       the bound used is the smaller of the two, and Wang's alone where |V(m)| is too small for the
//       chord direction to be trusted (a chord that nearly closes on itself).
//
// Step. For a piece of error max|d| = tau (no overshoot, the usual case of a flat piece),
// |E x D|·h^2 = 4·tau·|V(a + h/2)|: solved for h by Newton's method from the small-step estimate
// h0 = sqrt(4·tau·|V(a)| / |E x D|) (a handful of flops and one square root per iteration, quadratic
// convergence). That h is only a guess: the piece is accepted by the exact bound (iv) plus rounding
// margins, evaluated in O(1), and the shared step search (flatten_step_search.h) shortens it when the
// guess fails (overshoot, or a guess Newton could not settle). Every vertex is B(t) by de Casteljau from
// the original control points (no accumulated rounding), so the walk's polyline has the same contract as
// the general one (flatten.h) and, aiming at 99.5 % of the tolerance instead of 90-96 %, slightly fewer
// segments.
//
// Rounding. E and D are differences of the coordinates; the cross product, |V(m)| and the products carry
// an absolute error below ~10·eps·(|E| + |D|)^2, hence an error in max|d| below 10·eps·(|E| + |D|)^2·h^2 /
// (4|V(m)|) <= 2.5e4·eps·(|E| + |D|)·h^2 once |V(m)| >= 1e-4·(|E| + |D|) (below that, Wang's bound only):
// < 1e-11·h·(|E| + |D|) (h <= 1). The margin added is 1e-9·2h(|E| + |D|) (>= 1e-9 of the sub-arc's control
// polygon radius, as the general bound's margin) plus 16·eps·max|coordinate| for the vertices, which are
// de Casteljau points with a few ulps of the coordinates of error each. The closed form is used only when
// that absolute margin is <= 1.6e-5 of the tolerance and the coordinates are within 1e±100 (no overflow or
// underflow in squares); otherwise the general walk, which scales its coefficients, takes the curve.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/curves/point.h"

namespace curvescan::detail {

/// The proven bound (iv) above, with its rounding margins, on the Hausdorff distance between the sub-arc
/// [a, b] (0 <= a < b <= 1) of the quadratic Bézier (p0, p1, p2) and its chord [B(a), B(b)]. NaN in, NaN
/// out. Meant for tests: the flattener evaluates the same formula with the constants hoisted.
[[nodiscard]] double quadratic_arc_chord_bound(Point p0, Point p1, Point p2, double a, double b) noexcept;

/// Flattens the quadratic Bézier ctrl (exactly 3 finite points whose differences are finite, tolerance
/// finite and > 0) with the contract of flatten_bezier. Returns nothing, and appends nothing, when the
/// closed form does not apply (see "Rounding" above): the caller then runs the general walk.
std::optional<FlattenOutcome> flatten_quadratic(std::span<const Point> ctrl, double tolerance,
                                                std::vector<Point>& out,
                                                std::size_t max_segments = kMaxFlattenSegments);

}  // namespace curvescan::detail
