// flatten_cubic.h (private to the flattener): cubic Béziers flattened with a closed-form proven bound on
// each sub-arc of the ORIGINAL control points: O(1) work per trial, no de Casteljau split of the piece, no
// chord frame of split control points, no root solving (docs/flattening.md §1c).
//
// Essay. Let B(t) be the cubic with control points P0..P3 (Ince, *Curves*, "Bernstein Polynomials"), D0 = P0 - 2P1
// + P2 and D1 = P1 - 2P2 + P3 its second differences, J = D1 - D0 its third difference and
// K(t) = D0 + t·J, so that B''(t) = 6·K(t): the second derivative of a cubic is LINEAR in t (the derivative
// of a Bézier is the Bézier of the differences, Dill, *Introduction to Parametric Curves*, "tangent vector"). Take the sub-arc [a, b],
// h = b - a, m = (a + b)/2, g(s) = B(a + s·h) for s in [0, 1], and e(s) = g(s) - lerp(g(0), g(1), s), the
// deviation from the linear interpolant: e(0) = e(1) = 0 and e'' = g'' = 6h^2·K(a + s·h), linear in s.
//
//  (i)   Shape of e. A function f with f(0) = f(1) = 0 and f'' linear, f''(0) = A, f''(1) = Z, is
//        f(s) = -(A + Z)/4 · p(s) - (Z - A)/6 · q(s), p = s(1-s), q = s(1-s)(s - 1/2)
//        (p'' = -2, q'' = 3(1 - 2s): the sum has f'' = A + s(Z - A), and both vanish at 0 and 1).
//        max p = 1/4 and max|q| = 1/(12·sqrt 3) (at s = 1/2 ± 1/(2 sqrt 3)). For e, A + Z = 12h^2·K(m) and
//        Z - A = 6h^3·J, so, for any unit vector w, with the triangle inequality:
//          |w x e(s)| <= 3/4·h^2·|w x K(m)| + h^3·|w x J| / (12 sqrt 3)                     (across)
//          |w · e(s)| <= p(s)·(3h^2·|w · K(m)| + h^3·|w · J| / 2)   (|s - 1/2| <= 1/2)      (along)
//          |e(s)|     <= 3/4·h^2·|K(m)| + h^3·|J| / (12 sqrt 3)                             (Wang-like)
//        The first is exact when K is constant over the piece (a parabola; it is then §1b's h^2|u x D|/4
//        for the quadratic degree-elevated) and when the two ends of w x K are opposite, and within ~10 %
//        in between; it needs no root.
//  (ii)  Chord frame: w = u, the unit chord direction of [B(a), B(b)], L = |B(b) - B(a)|. Across the chord
//        d(s) = u x (g(s) - g(0)) = u x e(s) (the lerp term is along u), so max|d| <= (across). Along it,
//        σ(s) = <g(s) - g(0), u> = s·L + u·e(s) with |u·e(s)| <= c·s(1-s), c the bracket of (along): σ
//        leaves [0, L] only if c > L, by at most max_s s·(c(1-s) - L) = (c - L)^2 / (4c) (and the same at
//        the far end by s -> 1 - s).
//  (iii) The bound (B) of flatness_bound.h (curve -> chord by the clamped projection, chord -> curve by the
//        intermediate value theorem on σ) with these maxima: Hausdorff(arc, chord) <= sqrt(across^2 +
//        over^2). Independently, e with lerp sweeping the whole chord gives Hausdorff <= (Wang-like), which
//        needs no chord direction: it takes a chord shorter than 1e-4 of the piece's hodograph scale
//        (a loop closing on itself, a cusp inside the piece), and caps (iii) when it overshoots.
//
// Step. The shared step search (flatten_step_search.h) from the previous piece's length, rescaled by the
// u^2 model, as the general walk does; each trial is one de Casteljau point (the candidate vertex) and a
// few dozen flops.
//
// Rounding. Vertices are de Casteljau points of the original control points at exact doubles a, b
// (three lerp levels: <= ~9 ulps of M = max|coordinate| per coordinate, below δ = 16·eps·M as a vector),
// the first and last exactly P0 and P3. The bound is about the EXACT arc and the COMPUTED chord:
// moving the chord's ends by <= δ moves the chord by <= δ; the chord direction computed from displaced
// ends is off by |Δu| <= 4δ/L, which changes (across) by <= |Δu|·W, W the (Wang-like) bracket with |K(m)|
// replaced by the bound (1-m)|D0| + m|D1|, and c by <= |Δu|·(3h^2|K| + h^3|J|/2) <= 10.4|Δu|·W (the
// h^3 factors: 1/2 against 1/(12 sqrt 3)); (c - L)^2/(4c) has derivatives <= 1/4 in c and 1/2 in L in
// size (|ΔL| <= 2δ), so it moves by <= 2.6|Δu|·W + δ. In all <= 3.6·4δ·W/L + δ, times 8/7 for L against
// the computed chord (>= 16δ where the frame is used): the margin 20δ·W/L + 2δ for the frame bound, and 2δ
// for (Wang-like), plus 1e-9·h·S for the arithmetic (S = 3 Σ|P_{i+1} - P_i|
// >= max|B'| >= L/h: every product and sum carries a few ulps of h^2·S or h·S, far below 1e-9·h·S), as
// §1b's margins. Used only when δ <= 1.6e-5 of the tolerance and coordinates and S are within 1e±100
// (no overflow or underflow in squares); otherwise the general walk takes the curve, as for quadratics.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/curves/point.h"

namespace curvescan::detail {

/// The proven bound (iii) above, with its rounding margins, on the Hausdorff distance between the sub-arc
/// [a, b] (0 <= a < b <= 1) of the cubic Bézier (p0, p1, p2, p3) and its chord between the walk's computed
/// vertices (exactly p0 at a = 0 and p3 at b = 1, de Casteljau points otherwise). NaN in, NaN out. Meant
/// for tests: the walk evaluates the same function with the constants hoisted.
[[nodiscard]] double cubic_arc_chord_bound(Point p0, Point p1, Point p2, Point p3, double a, double b) noexcept;

/// Flattens the cubic Bézier ctrl (exactly 4 finite points whose differences are finite, tolerance finite
/// and > 0) with the contract of flatten_bezier. Returns nothing, and appends nothing, when the closed form
/// does not apply (see "Rounding" above): the caller then runs the general walk.
std::optional<FlattenOutcome> flatten_cubic(std::span<const Point> ctrl, double tolerance, std::vector<Point>& out,
                                            std::size_t max_segments = kMaxFlattenSegments);

}  // namespace curvescan::detail
