// A quadratic Bézier flattened in uniform parameter steps whose number comes from Wang's bound in closed
// form: one square root per curve and one de Casteljau point per vertex, no per-segment search.
//
// Proof of the tolerance (docs/flattening.md §1d). B(t) = (1-t)²P0 + 2t(1-t)P1 + t²P2, D = P0 - 2P1 + P2.
// For any sub-interval [a, b], h = b - a, and the chord L(s) = lerp(B(a), B(b), s):
//   B(a + sh) - L(s) = -h²D·s(1 - s)
// (the difference is a quadratic in s, zero at both ends, with second derivative B'' h² = 2h²D), so
// |B(a + sh) - L(s)| <= h²|D|/4 for every s in [0, 1]. Pairing each curve point with the chord point of
// the same s (and each chord point with the curve point of the same s) bounds the Hausdorff distance
// between the sub-arc and its chord by h²|D|/4 (Wang's bound, exact for a quadratic). With n equal steps
// h = 1/n, so n = ceil(sqrt(|D| / 4τ)) makes every chord, hence the polyline, within τ of the curve.
//
// Rounding. The computed vertices are de Casteljau points at t_i = i·(1/n) rounded: each is B(t_i) for
// that rounded t_i up to a few ulps of the largest coordinate M (two lerp levels), and moving a chord's
// ends by δ moves every chord point by at most δ, so δ = 16εM (kVertexUlps, as the adaptive quadratic
// walk, flatten_quadratic.cpp) is added to the bound. The rounded t_i are still increasing, and each step
// is at most 1/n + 2ε ≤ (1/n)(1 + 2nε); for n ≤ 2^22 segments the square exceeds 1/n² by less than 10⁻⁸
// relative. |D| is computed from rounded differences: off by at most 8εM. So n is chosen for
//   (|D| + 8εM)(1 + 10⁻⁸) / (4n²) + 16εM <= τ,
// and checked again after the square root and ceiling (which round too); the comparison's own roundings
// (budget = τ - 16εM and the product budget·n², a few ε relative) are far inside the 10⁻⁸. Where 16εM
// exceeds 1.6·10⁻⁵ τ (tolerances near the coordinates' resolution), the coordinates exceed 10^100, a point is
// not finite, or n would pass max_segments, the adaptive flatten_quadratic_bezier takes the curve instead: it
// reports what it cannot certify.
//
// Cost against the adaptive walk: 9 to 13 % more segments on the quadratics of DejaVu Sans at 12 to
// 100 px (docs/flattening.md §1d) — Wang's bound ignores that the curve bends less where it moves fast — for
// a fraction of the work per vertex.
#include "curvescan/curves/flatten_quadratic_uniform.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace curvescan {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr double kVertexUlps = 16.0;                 // de Casteljau vertex rounding (see the proof above)
constexpr double kSecondDifferenceUlps = 8.0;        // rounding of |D| from the rounded differences
constexpr double kStepRelativeMargin = 1e-8;         // rounded t_i: h² over 1/n², for n <= 2^22
constexpr double kMaxVertexMarginFraction = 1.6e-5;  // as the adaptive walk (flatten_quadratic.cpp)
constexpr double kLargestCoordinate = 1e100;
constexpr std::size_t kSmallSteps = 8;  // step counts found by trial rather than by the closed form

}  // namespace

FlattenOutcome flatten_quadratic_bezier_uniform(Point p0, Point p1, Point p2, double tolerance,
                                                std::vector<Point>& out, std::size_t max_segments) {
  const Vec2 second = (p0 - p1) + (p2 - p1);
  return flatten_quadratic_bezier_uniform_with_length(p0, p1, p2, std::sqrt(second.length_squared()),
                                                      tolerance, out, max_segments);
}

FlattenOutcome flatten_quadratic_bezier_uniform_with_length(Point p0, Point p1, Point p2,
                                                            double second_length, double tolerance,
                                                            std::vector<Point>& out,
                                                            std::size_t max_segments) {
  const double largest =
      std::max(std::max(std::max(std::abs(p0.x), std::abs(p0.y)), std::max(std::abs(p1.x), std::abs(p1.y))),
               std::max(std::abs(p2.x), std::abs(p2.y)));
  const double vertex_margin = kVertexUlps * kEpsilon * largest;
  // NaN fails every comparison here, so a NaN tolerance takes the adaptive flattener (a NaN point: below).
  const bool applicable = largest <= kLargestCoordinate && std::isfinite(tolerance) && tolerance > 0.0 &&
                          vertex_margin <= kMaxVertexMarginFraction * tolerance;
  if (!applicable) return flatten_quadratic_bezier(p0, p1, p2, tolerance, out, max_segments);
  const double bulge = (second_length + kSecondDifferenceUlps * kEpsilon * largest) *
                       (1.0 + kStepRelativeMargin) * 0.25;  // the bound of one step is bulge / n²
  // A NaN coordinate can hide from the maxima above (std::max drops it), never from this sum.
  if (!std::isfinite(bulge)) return flatten_quadratic_bezier(p0, p1, p2, tolerance, out, max_segments);
  const double budget = tolerance - vertex_margin;
  // The fewest n with bulge <= budget·n². Most curves that reach here need 2 to 8 steps: those are found
  // by trial, without the square root and the division of the closed form.
  std::size_t n = 1;
  if (bulge > budget) {
    n = 2;
    while (n <= kSmallSteps && bulge > budget * static_cast<double>(n) * static_cast<double>(n)) ++n;
    if (n > kSmallSteps) {
      const double steps = std::ceil(std::sqrt(bulge / budget));
      if (!(steps <= static_cast<double>(std::min(max_segments, kMaxFlattenSegments)))) {
        return flatten_quadratic_bezier(p0, p1, p2, tolerance, out, max_segments);
      }
      n = static_cast<std::size_t>(steps);
      // The square root and the ceiling round: one more step if the bound does not hold for this n.
      if (bulge > budget * static_cast<double>(n) * static_cast<double>(n)) ++n;
    }
  }
  if (n > max_segments || n > kMaxFlattenSegments) {
    return flatten_quadratic_bezier(p0, p1, p2, tolerance, out, max_segments);
  }
  const double step = 1.0 / static_cast<double>(n);
  for (std::size_t i = 1; i < n; ++i) {
    const double t = static_cast<double>(i) * step;
    out.push_back(lerp(lerp(p0, p1, t), lerp(p1, p2, t), t));
  }
  out.push_back(p2);  // exactly the end point
  return FlattenOutcome::kOk;
}

}  // namespace curvescan
