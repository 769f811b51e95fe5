// flatten_cubic_uniform.h (private to the flattener): a cubic Bézier cut into n equal parameter steps, n
// from Wang's bound in closed form, where that n is close to the fewest segments — no step search at all
// (docs/flattening.md §1e). flatten_bezier calls it for every cubic before the adaptive walk.
//
// Bound. With D0 = P0 - 2P1 + P2, D1 = P1 - 2P2 + P3, B''(t) = 6·((1 - t)·D0 + t·D1) (the derivative of a
// Bézier is the Bézier of its differences: Dill, *Introduction to Parametric Curves*; Ince, *Curves*,
// "Bernstein Polynomials"), so |B''| <= 6·max(|D0|, |D1|) on [0, 1]. For a sub-interval [a, b], h = b - a,
// and the chord L(s) = lerp(B(a), B(b), s), the difference e(s) = B(a + sh) - L(s) vanishes at s = 0 and 1
// and e'' = h²·B''(a + sh); for every unit w, w·e is a scalar function with those end values, so
// |w·e(s)| <= s(1 - s)/2 · max|w·e''| <= h²·6·max(|D0|, |D1|)/8, hence
//     |B(a + sh) - L(s)| <= 3/4 · h² · max(|D0|, |D1|)   for every s
// (Wang's bound; Filip, Magedson and Markot, "Surface algorithms using bounds on derivatives", CAGD 1986).
// Pairing each curve point with the chord point of the same s, and each chord point with the curve point of
// the same s, bounds the Hausdorff distance of the sub-arc and its chord by that number. With h = 1/n:
//     n = ceil(sqrt(3/4 · max(|D0|, |D1|) / τ)).
//
// When. Wang's bound counts the whole second derivative, also its part along the tangent (the
// parametrisation speeding up), which does not move the curve off its chord: on random cubics it emits ~2×
// the fewest segments, on cusps 3.5× (docs/flattening.md §3). On arcs of near-constant speed (a circle's
// four cubics, the offset pieces of a stroke, font outlines) it is within a few % of the fewest. So the
// fewest are estimated first: a short piece at t needs h(t)² · 3/4·|V × K|/|V| <= τ (the across term of
// flatten_cubic.h (i), V = B'/3 in place of the chord direction, K = B''/6), hence about
// ∫ sqrt(3/4·|V × K|/(|V|·τ)) dt pieces, by Simpson's rule on t = 0, 1/2, 1 (two steps or fewer are
// left to the walk, which often needs one). Only when n is within
// kUniformAllowance of that estimate (plus one segment) are the uniform steps taken; otherwise the adaptive
// walk (flatten_cubic.h). The choice is only about cost: both are proven within τ.
//
// Rounding. Vertices are de Casteljau points at t_i = i·(1/n) rounded (three lerp levels: B(t_i) up to
// ~9 ulps of M = max|coordinate| per coordinate, within δ = 16·eps·M as a vector), the last exactly P3;
// moving a chord's two ends by <= δ moves every chord point by <= δ, and 2δ is added as in the cubic walk.
// |t_i - i/n| <= 2·eps, so a step is at most (1/n)(1 + 4n·eps): for n <= 2^22 its square exceeds 1/n² by
// less than 1e-8 relative. max(|D0|, |D1|) from rounded differences is off by <= 8·eps·M. So n is the fewest
// with (max(|D0|, |D1|) + 8·eps·M)·(1 + 1e-8)·3/4 / n² + 2δ <= τ, checked after the square root and ceiling.
// Used where δ <= 1.6e-5·τ and coordinates are within 1e100 (the cubic walk's range); elsewhere the walk
// takes the curve.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/curves/point.h"

namespace curvescan::detail {

/// Flattens the cubic Bézier ctrl (exactly 4 finite points whose differences are finite, tolerance finite
/// and > 0) in Wang's n uniform steps, with the contract of flatten_bezier, when that n is near the fewest
/// segments (above). Returns nothing, and appends nothing, when it is not, when the rounding analysis does
/// not hold, or when n exceeds max_segments: the caller then runs the adaptive walk.
std::optional<FlattenOutcome> flatten_cubic_uniform(std::span<const Point> ctrl, double tolerance,
                                                    std::vector<Point>& out,
                                                    std::size_t max_segments = kMaxFlattenSegments);

/// Wang's step count for the cubic at `tolerance` with the rounding margins above (0 where they do not
/// hold or n would pass kMaxFlattenSegments), and the estimate of the fewest segments that decides whether
/// flatten_cubic_uniform takes the curve. For tests and the benchmark.
struct CubicUniformPlan {
  std::size_t steps = 0;
  double fewest_estimate = 0.0;
  bool uniform = false;
};
[[nodiscard]] CubicUniformPlan plan_cubic_uniform(std::span<const Point> ctrl, double tolerance) noexcept;

/// The same two, given `largest`, the largest |coordinate| of ctrl (exact: a maximum of absolute values),
/// which flatten_bezier has already taken for its resolution floor: the same plan, bit for bit.
[[nodiscard]] CubicUniformPlan plan_cubic_uniform(std::span<const Point> ctrl, double tolerance,
                                                  double largest) noexcept;
std::optional<FlattenOutcome> flatten_cubic_uniform(std::span<const Point> ctrl, double tolerance,
                                                    double largest, std::vector<Point>& out,
                                                    std::size_t max_segments);

}  // namespace curvescan::detail
