// Cubic Béziers in Wang's uniform steps where they are near the fewest: the plan and the walk-free loop.
// Proof, choice and rounding in flatten_cubic_uniform.h (docs/flattening.md §1e).
#include "flatten_cubic_uniform.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace curvescan::detail {
namespace {

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();
constexpr double kVertexUlps = 16.0;                 // δ: de Casteljau vertex rounding, as the cubic walk
constexpr double kSecondDifferenceUlps = 8.0;        // rounding of |D0|, |D1| from the rounded differences
constexpr double kStepRelativeMargin = 1e-8;         // rounded t_i: h² over 1/n², for n <= 2^22
constexpr double kMaxVertexMarginFraction = 1.6e-5;  // as the cubic walk (flatten_cubic.cpp)
constexpr double kLargestCoordinate = 1e100;
// Uniform steps are taken when n <= kUniformAllowance · (estimated fewest) + kUniformSlack: the walk itself
// emits 3-5 % above the fewest (docs/flattening.md §3), so this keeps the uniform polyline within about
// 10 % of the walk's where it is taken (measured in §1e), and the slack lets the small counts, where one
// segment more or less is rounding of the estimate, skip the walk.
constexpr double kUniformAllowance = 1.12;
constexpr double kUniformSlack = 1.0;

double length(Vec2 v) noexcept {
  return std::sqrt(v.length_squared());
}
Vec2 lerp_vec(Vec2 a, Vec2 b, double t) noexcept {
  return a + (b - a) * t;
}

/// sqrt(|V × K| / |V|) at t, V = B'/3 (the quadratic Bézier of the first differences), K = B''/6: the
/// square root of the across rate of a short piece (flatten_cubic_uniform.h "When"). 0 where V vanishes
/// (a cusp: the rate is bounded by |K| there, and 0 only makes the walk likelier, never wrong).
inline double root_across_rate(Vec2 e0, Vec2 e1, Vec2 e2, Vec2 d0, Vec2 j, double t) noexcept {
  const Vec2 v = lerp_vec(lerp_vec(e0, e1, t), lerp_vec(e1, e2, t), t);
  const double speed = length(v);
  if (!(speed > 0.0)) return 0.0;
  return std::sqrt(std::abs(v.cross(d0 + j * t)) / speed);
}

/// root_across_rate at an end, from V and K given: the same value, bit for bit, without the lerps (the
/// plan is asked for every cubic, and three in four of the curves that reach the estimate are declined).
/// At t = 0 the lerps return their first operand exactly (a + (b - a)·0 = a for finite a, b, up to the
/// sign of a zero, which neither the length nor |V × K| sees): V = E0, K = D0. At t = 1 they are
/// a + (b - a) (·1 is exact), which is not always b: the caller spells those sums out.
inline double root_across_rate_at(Vec2 v, Vec2 k) noexcept {
  const double speed = length(v);
  if (!(speed > 0.0)) return 0.0;
  return std::sqrt(std::abs(v.cross(k)) / speed);
}

}  // namespace

CubicUniformPlan plan_cubic_uniform(std::span<const Point> ctrl, double tolerance) noexcept {
  if (ctrl.size() != 4) return CubicUniformPlan{};
  const Point p0 = ctrl[0], p1 = ctrl[1], p2 = ctrl[2], p3 = ctrl[3];
  const double largest =
      std::max(std::max(std::max(std::abs(p0.x), std::abs(p0.y)), std::max(std::abs(p1.x), std::abs(p1.y))),
               std::max(std::max(std::abs(p2.x), std::abs(p2.y)), std::max(std::abs(p3.x), std::abs(p3.y))));
  return plan_cubic_uniform(ctrl, tolerance, largest);
}

CubicUniformPlan plan_cubic_uniform(std::span<const Point> ctrl, double tolerance, double largest) noexcept {
  CubicUniformPlan plan;
  if (ctrl.size() != 4) return plan;
  const Point p0 = ctrl[0], p1 = ctrl[1], p2 = ctrl[2], p3 = ctrl[3];
  const double vertex_margin = kVertexUlps * kEpsilon * largest;
  // NaN fails every comparison: a NaN tolerance or coordinate leaves the plan empty.
  if (!(largest <= kLargestCoordinate && tolerance > 0.0 &&
        vertex_margin <= kMaxVertexMarginFraction * tolerance))
    return plan;
  const Vec2 e0 = p1 - p0, e1 = p2 - p1, e2 = p3 - p2;
  const Vec2 d0 = e1 - e0, d1 = e2 - e1;
  const double second = std::max(length(d0), length(d1)) + kSecondDifferenceUlps * kEpsilon * largest;
  const double bulge = 0.75 * second * (1.0 + kStepRelativeMargin);  // one step's bound is bulge / n²
  const double budget = tolerance - 2.0 * vertex_margin;
  if (!std::isfinite(bulge) || !(budget > 0.0)) return plan;
  const double steps = std::max(1.0, std::ceil(std::sqrt(bulge / budget)));
  if (!(steps <= static_cast<double>(kMaxFlattenSegments))) return plan;
  auto n = static_cast<std::size_t>(steps);
  // The square root and the ceiling round: one more step if the bound does not hold for this n.
  if (bulge > budget * static_cast<double>(n) * static_cast<double>(n)) ++n;
  plan.steps = n;
  // Two steps: the walk, whose first trial is the whole curve with the across-chord bound, often needs
  // one. Two uniform steps there doubled the edges of a stroke's narrow pieces (the 20 px cubic stroke's
  // fill +3 %, docs/benchmarks.md), so the walk takes these; no estimate needed.
  if (n <= 2) return plan;
  // The fewest segments, estimated: ∫ sqrt(3/4·|V × K| / (|V|·τ)) dt by Simpson's rule on t = 0, 1/2, 1.
  const Vec2 j = d1 - d0;
  const Vec2 q0 = e0 + (e1 - e0), q1 = e1 + (e2 - e1);
  const Vec2 end_tangent = q0 + (q1 - q0);  // V(1) as root_across_rate's lerps round it
  const double integral = (root_across_rate_at(e0, d0) + 4.0 * root_across_rate(e0, e1, e2, d0, j, 0.5) +
                           root_across_rate_at(end_tangent, d0 + j)) /
                          6.0;
  plan.fewest_estimate = integral * std::sqrt(0.75 / tolerance);
  plan.uniform = static_cast<double>(n) <= kUniformAllowance * plan.fewest_estimate + kUniformSlack;
  return plan;
}

std::optional<FlattenOutcome> flatten_cubic_uniform(std::span<const Point> ctrl, double tolerance,
                                                    std::vector<Point>& out, std::size_t max_segments) {
  if (ctrl.size() != 4) return std::nullopt;
  const Point p0 = ctrl[0], p1 = ctrl[1], p2 = ctrl[2], p3 = ctrl[3];
  const double largest =
      std::max(std::max(std::max(std::abs(p0.x), std::abs(p0.y)), std::max(std::abs(p1.x), std::abs(p1.y))),
               std::max(std::max(std::abs(p2.x), std::abs(p2.y)), std::max(std::abs(p3.x), std::abs(p3.y))));
  return flatten_cubic_uniform(ctrl, tolerance, largest, out, max_segments);
}

std::optional<FlattenOutcome> flatten_cubic_uniform(std::span<const Point> ctrl, double tolerance,
                                                    double largest, std::vector<Point>& out,
                                                    std::size_t max_segments) {
  const CubicUniformPlan plan = plan_cubic_uniform(ctrl, tolerance, largest);
  if (!plan.uniform || plan.steps > max_segments) return std::nullopt;
  const Point p0 = ctrl[0], p1 = ctrl[1], p2 = ctrl[2], p3 = ctrl[3];
  const std::size_t n = plan.steps;
  const double step = 1.0 / static_cast<double>(n);
  for (std::size_t i = 1; i < n; ++i) {
    const double t = static_cast<double>(i) * step;
    // de Casteljau from the original points (the walk's vertex arithmetic, flatten_cubic.cpp CubicArc::at).
    const Point q0 = lerp(p0, p1, t), q1 = lerp(p1, p2, t), q2 = lerp(p2, p3, t);
    out.push_back(lerp(lerp(q0, q1, t), lerp(q1, q2, t), t));
  }
  out.push_back(p3);  // exactly the end point
  return FlattenOutcome::kOk;
}

}  // namespace curvescan::detail
