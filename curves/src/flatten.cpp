// The flattener: one adaptive de Casteljau walk for polynomial Béziers of any degree and rational Béziers.
//
// Essay. Cairo and plutovg halve: test the piece, split it at t = 1/2 if it is not flat, repeat on both
// halves. Halving lands on parameter lengths that are powers of two, so a segment is on average much
// shorter than it could be: ~1.6x the fewest segments a tolerance allows. Instead we walk along the curve
// and, at each vertex, look for (nearly) the longest piece that passes the flatness test:
//
//   remaining := the curve on [t0, 1] (one de Casteljau split of the ORIGINAL control points at t0)
//   trial     := remaining on [0, u] (one more split), err := chord_distance_bound(trial)
//
// The error of a short chord grows like u^2 (the chord's sagitta is curvature·length^2/8), so from one
// trial the longest passing u is predicted as u·sqrt(tol/err); we aim slightly below it, keep a bracket
// [longest pass, shortest fail] and stop once a pass uses >= kAcceptFraction of the tolerance, the bracket
// is tight, or the trial budget is spent. The next step starts from the accepted parameter length
// (rescaled to the new remaining curve), so on smooth curves the first trial usually passes: ~1-3 bound
// evaluations per segment. The bound is exact for cubics and conics (flatness_bound.h), so "passes" means
// "really within tolerance" and the walk approaches the greedy optimum (docs/flattening.md has the table).
//
// Every piece is re-split from the original control points, so rounding does not accumulate along the
// walk: each vertex is the de Casteljau point of the original curve at its parameter, to a few ulps of the
// coordinates. Work is bounded by the caller's max_segments: at most that many segments, at most
// kMaxTrialsPerSegment bound evaluations for one segment and 8 per segment of the cap over the whole walk
// (WalkTrials, flatten_step_search.h), and t strictly increases at every step.
//
// Polynomial curves walk on Points, rational ones on homogeneous points (w·x, w·y, w) whose de Casteljau
// split is the rational curve's split (Umetani, *Parametric Curve*, §4.1); one template, two thin adapters.
//
// Cost per call (most calls are small TrueType quadratics needing 1-3 segments). Curves up to
// kStackCount control points walk in stack buffers: no heap allocation. Before the walk, a polynomial
// curve gets the parameter-space test (Wang's bound): C(t) minus its linear interpolant
// L(t) = (1-t)·P_0 + t·P_n is bounded by n(n-1)/8 · max_i |P_i - 2P_{i+1} + P_{i+2}| (for a quadratic it
// is exactly D·t(1-t) with D = P_0 - 2P_1 + P_2, max |D|/4). L(t) lies on the chord and sweeps all of it,
// so that number bounds the Hausdorff distance in both directions; when it is within tolerance the
// whole curve is one segment and the exact bound is never evaluated. A quadratic that needs more could be
// cut into n = ceil(sqrt(|D| / (4·tol))) equal parameter steps with no bound evaluation at all, but that
// was measured (docs/flattening.md, glyph quadratics) at 1.33x the walk's segments: every extra edge costs
// the rasterizer more than the bound tests it saves. Instead quadratics and conics walk with the same exact
// bound in closed form, O(1) per trial and no split (flatten_quadratic.h, flatten_conic.h), and cubics with a
// closed-form bound of the sub-arc of the original control points (flatten_cubic.h); curves those
// closed forms decline (tolerances near the coordinates' resolution, coordinates beyond 1e100) and every
// other degree take the general walk below. All walks share the step search (flatten_step_search.h).
#include "curvescan/curves/flatten.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>

#include "flatness_bound.h"
#include "flatten_conic.h"
#include "flatten_cubic.h"
#include "flatten_cubic_uniform.h"
#include "flatten_quadratic.h"
#include "flatten_split.h"
#include "flatten_step_search.h"

namespace curvescan {
namespace {

// Curves with up to this many control points (degree 7) walk in stack buffers.
constexpr std::size_t kStackCount = 8;

struct Homogeneous {
  double wx, wy, w;
};

// The walk over the coefficient type Node; `ops` supplies lerp(a, b, u), project(node) -> Point and
// bound(span<const Node>) -> double (chord_distance_bound of the piece).
template <class Node, class Ops>
FlattenOutcome walk(std::span<const Node> curve, Point end, double tolerance, std::vector<Point>& out,
                    Ops& ops, std::size_t max_segments) {
  const std::size_t count = curve.size();
  std::array<Node, 3 * kStackCount> stack_buffer;
  std::vector<Node> heap_buffer;
  Node* buffer = stack_buffer.data();
  if (count > kStackCount) {
    heap_buffer.resize(3 * count);
    buffer = heap_buffer.data();
  }
  const std::span<Node> remaining(buffer, count), trial(buffer + count, count),
      scratch(buffer + 2 * count, count);
  auto lerp_fn = [&ops](Node a, Node b, double u) { return ops.lerp(a, b, u); };
  std::copy(curve.begin(), curve.end(), remaining.begin());

  double t0 = 0.0;     // parameter of the last vertex on the original curve
  double guess = 1.0;  // first trial length, in the parameter of `remaining` (1 = the whole rest)
  bool within_tolerance = true;
  detail::WalkTrials trials(max_segments);
  for (std::size_t segments = 1;; ++segments) {
    if (segments >= max_segments) {
      out.push_back(end);
      return FlattenOutcome::kSegmentLimit;
    }
    detail::StepSearch search(guess, tolerance, trials.next_cap());
    for (bool done = false; !done;) {
      const double u = search.length();
      double err;
      if (u >= 1.0) {
        err = ops.bound(std::span<const Node>(remaining));
      } else {
        detail::split_bezier<Node>(remaining, u, trial, {}, scratch, lerp_fn);
        err = ops.bound(std::span<const Node>(trial));
      }
      done = search.record(err);
    }
    // No pass: the tolerance is below the floating-point resolution of the coordinates (step search).
    if (!search.passed()) within_tolerance = false;
    const double pass_u = search.accepted();
    if (pass_u >= 1.0) break;
    if (!trials.spend(search.evaluations())) {  // the walk's allowance is spent: end as at the segment cap
      out.push_back(end);
      return FlattenOutcome::kSegmentLimit;
    }

    // Advance on the ORIGINAL curve (no accumulated rounding); t strictly increases.
    double t1 = t0 + pass_u * (1.0 - t0);
    if (!(t1 > t0)) t1 = std::nextafter(t0, 2.0);
    if (t1 >= 1.0) break;
    detail::split_bezier<Node>(curve, t1, {}, remaining, scratch, lerp_fn);
    out.push_back(ops.project(remaining[0]));
    // Next step: the accepted parameter length, corrected by the model, in the new remaining's parameter.
    guess = (t1 - t0) * detail::StepSearch::predicted_growth(search.accepted_error(), tolerance) / (1.0 - t1);
    t0 = t1;
  }
  out.push_back(end);  // exactly ctrl.back(), not a projection of it
  return within_tolerance ? FlattenOutcome::kOk : FlattenOutcome::kSegmentLimit;
}

struct PolynomialOps {
  static Point lerp(Point a, Point b, double u) noexcept { return curvescan::lerp(a, b, u); }
  static Point project(Point p) noexcept { return p; }
  static double bound(std::span<const Point> piece) noexcept {
    return detail::chord_distance_bound(piece, {});
  }
};

struct RationalOps {
  std::span<Point> points;  // one per control point, storage owned by the caller
  std::span<double> weights;
  static Homogeneous lerp(Homogeneous a, Homogeneous b, double u) noexcept {
    return {a.wx + (b.wx - a.wx) * u, a.wy + (b.wy - a.wy) * u, a.w + (b.w - a.w) * u};
  }
  static Point project(Homogeneous h) noexcept { return {h.wx / h.w, h.wy / h.w}; }
  double bound(std::span<const Homogeneous> piece) noexcept {
    for (std::size_t i = 0; i < piece.size(); ++i) {
      points[i] = project(piece[i]);
      weights[i] = piece[i].w;
    }
    return detail::chord_distance_bound(points, weights);
  }
};

/// sup_t |C(t) - L(t)| <= n(n-1)/8 · max_i |P_i - 2P_{i+1} + P_{i+2}|, L the linear interpolant of the end
/// points (Wang's bound; |C''| <= n(n-1)·max|second difference| and an interpolation error is
/// <= max|C''|/8); exact for n = 2. Zero for a line; NaN in, NaN out.
double interpolant_deviation_bound(std::span<const Point> ctrl) noexcept {
  const std::size_t n = ctrl.size() - 1;
  double max_squared = 0.0;
  for (std::size_t i = 0; i + 2 <= n; ++i) {
    const Vec2 second = (ctrl[i] - ctrl[i + 1]) + (ctrl[i + 2] - ctrl[i + 1]);
    const double squared = second.length_squared();
    if (!(squared <= max_squared)) max_squared = squared;  // NaN propagates
  }
  return static_cast<double>(n * (n - 1)) / 8.0 * std::sqrt(max_squared);
}

bool all_finite(std::span<const Point> ctrl) noexcept {
  return std::all_of(ctrl.begin(), ctrl.end(), [](Point p) { return p.is_finite(); });
}

/// Every difference Q_i - Q_j must be finite for any bound (and any de Casteljau lerp a + (b - a)·u) to
/// exist: coordinates within the double range but more than DBL_MAX apart are treated like non-finite
/// input. Checking each axis' extent max - min covers all pairs at once (|Q_i - Q_j| per axis <= extent).
/// Checking only Q_i - Q_0 was not enough: {(0, 0), (1e308, 1e308), (0, -1e308)} passes it, but
/// Q_2 - Q_1 overflows, every split point is NaN, and each of the walk's 2^22 segments spent its whole
/// trial budget on NaN bounds (54 s; fuzz/regressions/curve_spec/quadratic_control_points_1e308_*).
bool extent_finite(std::span<const Point> ctrl) noexcept {
  const auto [min_x, max_x] =
      std::minmax_element(ctrl.begin(), ctrl.end(), [](Point a, Point b) { return a.x < b.x; });
  const auto [min_y, max_y] =
      std::minmax_element(ctrl.begin(), ctrl.end(), [](Point a, Point b) { return a.y < b.y; });
  return std::isfinite(max_x->x - min_x->x) && std::isfinite(max_y->y - min_y->y);
}

/// The finest tolerance the walk can certify at the magnitude of these coordinates: every vertex is a
/// de Casteljau point carrying a few ulps of the largest coordinate per lerp level (flatten_split.h), so a
/// chord cannot be placed closer than that to the curve. kResolutionUlps ulps of the largest coordinate:
/// 32 covers the n lerp levels of the degrees used (each <= 1 ulp, plus the projection of a rational
/// point) and stays below the finest tolerance the contract tests ask for (1e-7 at coordinates 1e7, i.e.
/// 450 ulps). Below it the walk used to fail every trial of every segment (200 bound evaluations each)
/// up to the segment cap; it now walks at this tolerance instead and reports kSegmentLimit.
constexpr double kResolutionUlps = 32.0;
double largest_coordinate(std::span<const Point> ctrl) noexcept {
  double largest = 0.0;
  for (const Point p : ctrl) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
  return largest;
}
double resolution_floor_of(double largest) noexcept {
  return kResolutionUlps * std::numeric_limits<double>::epsilon() * largest;
}
double resolution_floor(std::span<const Point> ctrl) noexcept {
  return resolution_floor_of(largest_coordinate(ctrl));
}

/// The outcome of a walk at the resolution floor instead of the requested tolerance: complete, not
/// certified at the requested tolerance.
FlattenOutcome uncertified(FlattenOutcome at_floor) noexcept {
  return at_floor == FlattenOutcome::kOk ? FlattenOutcome::kSegmentLimit : at_floor;
}

}  // namespace

double flatten_resolution(std::span<const Point> ctrl) noexcept {
  return resolution_floor(ctrl);
}

FlattenOutcome flatten_bezier(std::span<const Point> ctrl, double tolerance, std::vector<Point>& out,
                              std::size_t max_segments) {
  if (ctrl.size() < 2) return FlattenOutcome::kInvalid;
  if (!all_finite(ctrl) || !std::isfinite(tolerance) || !extent_finite(ctrl)) {
    return FlattenOutcome::kNonFinite;
  }
  if (!(tolerance > 0.0)) return FlattenOutcome::kInvalid;
  // Fast path proven by the interpolant bound (essay above). The bound is finite here because the
  // differences are (a second difference of finite differences can overflow only to inf: then the walk).
  const double deviation = interpolant_deviation_bound(ctrl);
  if (deviation <= tolerance) {
    out.push_back(ctrl.back());
    return FlattenOutcome::kOk;
  }
  // A tolerance finer than the coordinates can resolve: walk at the resolvable one and say so.
  const double largest = largest_coordinate(ctrl);  // also the uniform plan's (the same maximum, exact)
  const double resolvable = resolution_floor_of(largest);
  if (tolerance < resolvable) return uncertified(flatten_bezier(ctrl, resolvable, out, max_segments));
  // Quadratics (every TrueType outline segment) step in closed form: O(1) per segment, no split.
  if (ctrl.size() == 3) {
    if (const std::optional<FlattenOutcome> outcome =
            detail::flatten_quadratic(ctrl, tolerance, out, max_segments)) {
      return *outcome;
    }
  }
  // Cubics of nearly constant speed (circle arcs, the stroker's narrow pieces) in Wang's uniform steps:
  // one de Casteljau point per vertex, no step search (docs/flattening.md §1e). The others step with a
  // closed-form bound of the sub-arc: O(1) per trial.
  if (ctrl.size() == 4) {
    // deviation is Wang's bound of the whole cubic, 3/4·max(|D0|, |D1|): within 4τ the uniform plan has at
    // most two steps and leaves the curve to the walk, so it is not asked (a choice of cost only).
    if (deviation > 4.0 * tolerance) {
      if (const std::optional<FlattenOutcome> outcome =
              detail::flatten_cubic_uniform(ctrl, tolerance, largest, out, max_segments)) {
        return *outcome;
      }
    }
    if (const std::optional<FlattenOutcome> outcome = detail::flatten_cubic(ctrl, tolerance, out, max_segments)) {
      return *outcome;
    }
  }
  PolynomialOps ops;
  return walk<Point>(ctrl, ctrl.back(), tolerance, out, ops, max_segments);
}

// flatten_bezier's steps for three control points, in the same order and with the same arithmetic (so the
// same outcome and polyline, bit for bit), with the loops over the control points unrolled and no degree
// dispatch. The general function stays the plain reference; tests/unit/flatten holds the two equal.
FlattenOutcome flatten_quadratic_bezier(Point p0, Point p1, Point p2, double tolerance,
                                        std::vector<Point>& out, std::size_t max_segments) {
  // all_finite and extent_finite at once: the three differences are finite exactly when the points are
  // finite (a difference with an infinite or NaN operand is infinite or NaN) and the per-axis extents are
  // (the extent is the largest |difference|). Either failure is kNonFinite, as is a non-finite tolerance.
  const Vec2 d01 = p1 - p0;
  const Vec2 d12 = p2 - p1;
  const Vec2 d02 = p2 - p0;
  if (!d01.is_finite() || !d12.is_finite() || !d02.is_finite() || !std::isfinite(tolerance)) {
    return FlattenOutcome::kNonFinite;
  }
  if (!(tolerance > 0.0)) return FlattenOutcome::kInvalid;
  // interpolant_deviation_bound for n = 2: n(n-1)/8 = 1/4 times |P0 - 2P1 + P2| (exact: Wang's bound is
  // the maximum of |D|·t(1-t) for a quadratic).
  const Vec2 second = (p0 - p1) + (p2 - p1);
  if (0.25 * std::sqrt(second.length_squared()) <= tolerance) {
    out.push_back(p2);
    return FlattenOutcome::kOk;
  }
  const std::array<Point, 3> ctrl{p0, p1, p2};
  // resolution_floor(ctrl), the largest |coordinate| taken pairwise.
  const double largest =
      std::max(std::max(std::max(std::abs(p0.x), std::abs(p0.y)), std::max(std::abs(p1.x), std::abs(p1.y))),
               std::max(std::abs(p2.x), std::abs(p2.y)));
  const double resolvable = kResolutionUlps * std::numeric_limits<double>::epsilon() * largest;
  if (tolerance < resolvable) {
    return uncertified(flatten_quadratic_bezier(p0, p1, p2, resolvable, out, max_segments));
  }
  if (const std::optional<FlattenOutcome> outcome =
          detail::flatten_quadratic(ctrl, tolerance, out, max_segments)) {
    return *outcome;
  }
  PolynomialOps ops;
  return walk<Point>(std::span<const Point>(ctrl), p2, tolerance, out, ops, max_segments);
}

FlattenOutcome flatten_quadratic_bezier_past_one_segment(Point p0, Point p1, Point p2, double tolerance,
                                                         std::vector<Point>& out, std::size_t max_segments) {
  // flatten_quadratic_bezier past its first test takes the closed form whenever that applies: the closed
  // form needs a tolerance of at least 10^6 ulps of the largest coordinate (kMaxVertexMarginFraction),
  // far above the resolution floor of 32 ulps, so where it applies the floor's branch is never taken.
  // Where it does not apply it appends nothing, and the whole function decides.
  const std::array<Point, 3> ctrl{p0, p1, p2};
  if (const std::optional<FlattenOutcome> outcome =
          detail::flatten_quadratic(ctrl, tolerance, out, max_segments)) {
    return *outcome;
  }
  return flatten_quadratic_bezier(p0, p1, p2, tolerance, out, max_segments);
}

FlattenOutcome flatten_rational(std::span<const Point> ctrl, std::span<const double> weights,
                                double tolerance, std::vector<Point>& out, std::size_t max_segments) {
  if (ctrl.size() < 2 || weights.size() != ctrl.size()) return FlattenOutcome::kInvalid;
  const bool weights_finite =
      std::all_of(weights.begin(), weights.end(), [](double w) { return std::isfinite(w); });
  if (!all_finite(ctrl) || !weights_finite || !std::isfinite(tolerance) || !extent_finite(ctrl)) {
    return FlattenOutcome::kNonFinite;
  }
  if (!(tolerance > 0.0) ||
      std::any_of(weights.begin(), weights.end(), [](double w) { return !(w > 0.0); })) {
    return FlattenOutcome::kInvalid;
  }
  // Equal weights: the curve is the polynomial Bézier of the same points, with its exact cubic bound.
  if (std::all_of(weights.begin(), weights.end(), [&](double w) { return w == weights.front(); })) {
    return flatten_bezier(ctrl, tolerance, out, max_segments);
  }
  const double resolvable = resolution_floor(ctrl);
  if (tolerance < resolvable)
    return uncertified(flatten_rational(ctrl, weights, resolvable, out, max_segments));
  // Conics (arcs, circles, ellipses) walk with an O(1) exact bound per trial, no split.
  if (ctrl.size() == 3) {
    if (const std::optional<FlattenOutcome> outcome =
            detail::flatten_conic(ctrl, weights, tolerance, out, max_segments)) {
      return *outcome;
    }
  }
  // Weights scaled by their maximum (the curve does not change) so that w·x overflows only if x does not
  // fit; a product that still overflows (or a weight that underflows to 0) is reported like non-finite input.
  const double w_max = *std::max_element(weights.begin(), weights.end());
  std::array<Homogeneous, kStackCount> homogeneous_stack;
  std::array<Point, kStackCount> points_stack;
  std::array<double, kStackCount> weights_stack;
  std::vector<Homogeneous> homogeneous_heap;
  std::vector<Point> points_heap;
  std::vector<double> weights_heap;
  std::span<Homogeneous> homogeneous(homogeneous_stack.data(), ctrl.size());
  std::span<Point> points(points_stack.data(), ctrl.size());
  std::span<double> bound_weights(weights_stack.data(), ctrl.size());
  if (ctrl.size() > kStackCount) {
    homogeneous_heap.resize(ctrl.size());
    points_heap.resize(ctrl.size());
    weights_heap.resize(ctrl.size());
    homogeneous = homogeneous_heap;
    points = points_heap;
    bound_weights = weights_heap;
  }
  for (std::size_t i = 0; i < ctrl.size(); ++i) {
    const double w = weights[i] / w_max;
    homogeneous[i] = {ctrl[i].x * w, ctrl[i].y * w, w};
    if (!std::isfinite(homogeneous[i].wx) || !std::isfinite(homogeneous[i].wy) || !(homogeneous[i].w > 0.0)) {
      return FlattenOutcome::kNonFinite;
    }
  }
  RationalOps ops{points, bound_weights};
  return walk<Homogeneous>(std::span<const Homogeneous>(homogeneous), ctrl.back(), tolerance, out, ops,
                           max_segments);
}

}  // namespace curvescan
