// The flatness bound of the flattener: Hausdorff(piece, chord) <= sqrt(max|d|^2 + max over^2), with the
// ranges of d and s computed exactly up to degree 3 (and for conics). Proof in flatness_bound.h.
#include "flatness_bound.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "flatten_split.h"

namespace curvescan::detail {
namespace {

// Relative safety margin added to every bound (in units of R = max|Q_i - Q_0|). What it covers:
// the frame coordinates d_i, s_i are computed from Q_i - Q_0 (one rounding), the unit chord vector (a
// hypot and a division) and a dot or cross product: at most ~8 ulps of R in all. Evaluating a Bernstein
// polynomial of degree <= 3 by de Casteljau adds at most 3 ulps of its coefficient range. A root of the
// derivative computed with error delta underestimates the extremum by at most
// max|d''|·delta^2 / 2 <= 12·delta^2 (normalized cubic coefficients are <= 1 in magnitude, so
// |d''| <= 6·4), and delta <= ~1e-8 even for a double root (the square root of the discriminant's
// rounding), so <= 1.2e-15. Total well under 1e-13; 1e-9 leaves four orders of magnitude of headroom and
// costs nothing measurable (1e-9 of a piece is far below any useful tolerance).
constexpr double kRoundingMargin = 1e-9;

// Below this ratio L/R the chord direction is numerically meaningless (and a loop that closes on itself
// has no useful chord frame anyway): fall back to the radius bound R.
constexpr double kDegenerateChord = 1e-9;

// Degree up to which the coefficient arrays live on the stack.
constexpr std::size_t kSmallCount = 16;

/// [lo, hi], grown by include(); a NaN value is ignored (the comparisons are false).
struct Range {
  double lo;
  double hi;
  void include(double v) noexcept {
    if (v < lo) lo = v;
    if (v > hi) hi = v;
  }
};

double clamp01(double t) noexcept {
  return t > 0.0 ? (t < 1.0 ? t : 1.0) : 0.0;
}  // NaN -> 0

/// Value at t of the polynomial with the N Bernstein coefficients c, by de Casteljau. N is a compile-time
/// constant (2..4 here) so that the levels unroll: this runs at every root of every bound evaluation.
template <std::size_t N>
double bernstein_value(std::array<double, N> work, double t) noexcept {
  for (std::size_t level = N - 1; level > 0; --level) {
    for (std::size_t i = 0; i < level; ++i) work[i] += (work[i + 1] - work[i]) * t;
  }
  return work[0];
}

template <std::size_t N>
std::array<double, N> fixed(std::span<const double> c) noexcept {
  std::array<double, N> a;
  std::copy_n(c.begin(), N, a.begin());
  return a;
}

/// Includes f(t) for every real root t of a·t^2 + b·t + c (clamped to [0, 1]) in `range`. Evaluating f at
/// a point of [0, 1] that is not a root is harmless: it is a value of the function, so it can never push
/// the range past the true one. That is why a slightly negative discriminant (a double root blurred by
/// rounding) simply evaluates at the vertex -b/2a.
template <class F>
void include_at_roots(double a, double b, double c, F f, Range& range) noexcept {
  if (a == 0.0) {
    if (b != 0.0) range.include(f(clamp01(-c / b)));
    return;
  }
  const double disc = b * b - 4.0 * a * c;
  if (!(disc > 0.0)) {
    range.include(f(clamp01(-b / (2.0 * a))));
    return;
  }
  // Numerically stable pair of roots (no cancellation between -b and the square root).
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  range.include(f(clamp01(q / a)));
  if (q != 0.0) range.include(f(clamp01(c / q)));
}

/// Exact range on [0, 1] of the polynomial with the N Bernstein coefficients c, degree N - 1 = 1..3.
template <std::size_t N>
Range polynomial_range_exact(const std::array<double, N>& c) noexcept {
  Range range{std::min(c.front(), c.back()), std::max(c.front(), c.back())};
  auto value = [&c](double t) { return bernstein_value<N>(c, t); };
  if constexpr (N == 3) {
    // derivative / 2 = (c1 - c0)(1 - t) + (c2 - c1) t: linear.
    include_at_roots(0.0, c[0] - 2.0 * c[1] + c[2], c[1] - c[0], value, range);
  } else if constexpr (N == 4) {
    // derivative / 3 = a(1-t)^2 + 2b t(1-t) + e t^2 with a, b, e the forward differences
    // = (a - 2b + e) t^2 + 2(b - a) t + a.
    const double a = c[1] - c[0], b = c[2] - c[1], e = c[3] - c[2];
    include_at_roots(a - 2.0 * b + e, 2.0 * (b - a), a, value, range);
  }
  return range;
}

/// Exact range on [0, 1] of N/D, N and D quadratics with Bernstein coefficients num (= w_i c_i) and den
/// (= w_i > 0). With N = a t^2 + b t + c and D = al t^2 + be t + ga, the derivative's numerator
/// N'D - ND' = (a·be - b·al) t^2 + 2(a·ga - c·al) t + (b·ga - c·be): the t^3 terms cancel.
Range rational_quadratic_range_exact(std::span<const double> num, std::span<const double> den) noexcept {
  const std::array<double, 3> n3 = fixed<3>(num), d3 = fixed<3>(den);
  auto value = [&n3, &d3](double t) { return bernstein_value<3>(n3, t) / bernstein_value<3>(d3, t); };
  Range range{std::min(num[0] / den[0], num[2] / den[2]), std::max(num[0] / den[0], num[2] / den[2])};
  const double a = num[0] - 2.0 * num[1] + num[2], b = 2.0 * (num[1] - num[0]), c = num[0];
  const double al = den[0] - 2.0 * den[1] + den[2], be = 2.0 * (den[1] - den[0]), ga = den[0];
  include_at_roots(a * be - b * al, 2.0 * (a * ga - c * al), b * ga - c * be, value, range);
  return range;
}

/// A proven enclosure of the range on [0, 1] of sum num_i B_i / sum den_i B_i (den_i > 0; den all ones
/// for a polynomial), any degree: the union of the coefficient hulls of the four quarter pieces, obtained
/// by exact halvings (t = 1/2 is exact in binary).
Range rational_range_enclosure(std::span<const double> num, std::span<const double> den) noexcept {
  struct Pair {
    double num, den;
  };
  auto lerp_pair = [](Pair p, Pair q, double u) {
    return Pair{p.num + (q.num - p.num) * u, p.den + (q.den - p.den) * u};
  };
  const std::size_t count = num.size();
  std::array<Pair, 5 * kSmallCount> stack_buffer{};
  std::vector<Pair> heap_buffer;
  std::span<Pair> buffer(stack_buffer);
  if (count > kSmallCount) {
    heap_buffer.resize(5 * count);
    buffer = heap_buffer;
  }
  std::span<Pair> whole = buffer.subspan(0, count), half = buffer.subspan(count, count),
                  quarter_left = buffer.subspan(2 * count, count),
                  quarter_right = buffer.subspan(3 * count, count),
                  scratch = buffer.subspan(4 * count, count);
  for (std::size_t i = 0; i < count; ++i) whole[i] = {num[i], den[i]};
  Range range{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (int side = 0; side < 2; ++side) {
    const std::span<const Pair> source(whole);
    split_bezier<Pair>(source, 0.5, side == 0 ? half : std::span<Pair>(),
                       side == 0 ? std::span<Pair>() : half, scratch, lerp_pair);
    split_bezier<Pair>(std::span<const Pair>(half), 0.5, quarter_left, quarter_right, scratch, lerp_pair);
    for (const Pair& p : quarter_left) range.include(p.num / p.den);
    for (const Pair& p : quarter_right) range.include(p.num / p.den);
  }
  return range;
}

/// Range of the (rational) Bernstein function, exact where a closed form exists, else the enclosure.
Range function_range(std::span<const double> num, std::span<const double> den, bool polynomial) noexcept {
  const std::size_t degree = num.size() - 1;
  if (polynomial && degree == 1) return polynomial_range_exact<2>(fixed<2>(num));
  if (polynomial && degree == 2) return polynomial_range_exact<3>(fixed<3>(num));
  if (polynomial && degree == 3) return polynomial_range_exact<4>(fixed<4>(num));
  if (!polynomial && degree <= 2) {
    if (degree == 2) return rational_quadratic_range_exact(num, den);
    // A rational line segment runs monotonically between its end points.
    return {std::min(num[0] / den[0], num[1] / den[1]), std::max(num[0] / den[0], num[1] / den[1])};
  }
  return rational_range_enclosure(num, den);
}

/// max |Q_i - Q_0|; +inf if a difference overflows. Squared lengths and one square root (hypot is several
/// times slower) unless a square overflows or may have lost precision to underflow: then hypot.
double radius_from_start(std::span<const Point> ctrl) noexcept {
  double radius_squared = 0.0;
  for (const Point& p : ctrl) {
    const double r2 = (p - ctrl.front()).length_squared();
    if (std::isnan(r2)) return r2;
    radius_squared = std::max(radius_squared, r2);
  }
  constexpr double kSafeLow = 1e-280;  // above the subnormal range with margin: squares kept full precision
  if (radius_squared > kSafeLow && std::isfinite(radius_squared)) {
    return std::sqrt(radius_squared);
  }
  double radius = 0.0;
  for (const Point& p : ctrl) radius = std::max(radius, (p - ctrl.front()).length());
  return radius;
}

/// Fills the normalized frame coordinates (d_i, s_i)/R; returns L/R, or a negative value when the chord is
/// degenerate.
double chord_frame(std::span<const Point> ctrl, double radius, std::span<double> across,
                   std::span<double> along) noexcept {
  const Vec2 chord = (ctrl.back() - ctrl.front()) / radius;
  const double length = std::sqrt(chord.length_squared());  // normalized: |chord| <= 1, no overflow
  if (!(length > kDegenerateChord)) return -1.0;
  const Vec2 unit = chord / length;
  for (std::size_t i = 0; i < ctrl.size(); ++i) {
    const Vec2 v = (ctrl[i] - ctrl.front()) / radius;
    across[i] = unit.cross(v);
    along[i] = unit.dot(v);
  }
  // In exact arithmetic these are the frame coordinates of the end points; the margin covers the rest.
  across.front() = 0.0;
  along.front() = 0.0;
  across.back() = 0.0;
  along.back() = length;
  return length;
}

double with_margin(double normalized_bound, double radius) noexcept {
  return radius * (normalized_bound + kRoundingMargin);
}

}  // namespace

double chord_distance_bound(std::span<const Point> ctrl, std::span<const double> weights) noexcept {
  const std::size_t count = ctrl.size();
  const double radius = radius_from_start(ctrl);
  if (radius == 0.0) return 0.0;
  if (!std::isfinite(radius)) return radius;
  const bool polynomial = weights.empty();
  for (const double w : weights) {
    if (!(w > 0.0) || !std::isfinite(w)) return std::numeric_limits<double>::quiet_NaN();
  }

  std::array<double, 3 * kSmallCount> stack_buffer;  // every entry used is written first
  std::vector<double> heap_buffer;
  std::span<double> buffer(stack_buffer);
  if (count > kSmallCount) {
    heap_buffer.resize(3 * count);
    buffer = heap_buffer;
  }
  const std::span<double> across = buffer.subspan(0, count), along = buffer.subspan(count, count),
                          den = buffer.subspan(2 * count, count);
  const double length = chord_frame(ctrl, radius, across, along);
  if (length < 0.0) return with_margin(1.0, radius);

  if (polynomial) {
    // Only the enclosure (degree > 3) reads the denominators of a polynomial.
    if (count > 4) std::fill(den.begin(), den.end(), 1.0);
  } else {
    // Weights scaled by their maximum (the curve does not change) so that w_i·c_i cannot overflow.
    const double w_max = *std::max_element(weights.begin(), weights.end());
    for (std::size_t i = 0; i < count; ++i) {
      den[i] = weights[i] / w_max;
      across[i] *= den[i];
      along[i] *= den[i];
    }
  }
  const Range d = function_range(across, den, polynomial);
  const Range s = function_range(along, den, polynomial);
  const double max_across = std::max(-d.lo, d.hi);
  const double max_over = std::max({0.0, -s.lo, s.hi - length});
  // Both (B) and the radius bound hold; take the smaller. NaN input gives NaN.
  const double bound = std::sqrt(max_across * max_across + max_over * max_over);  // normalized: both <= ~2
  return with_margin(bound < 1.0 ? bound : 1.0, radius);
}

double chord_distance_hull_bound(std::span<const Point> ctrl) noexcept {
  const double radius = radius_from_start(ctrl);
  if (radius == 0.0) return 0.0;
  if (!std::isfinite(radius)) return radius;
  std::vector<double> across(ctrl.size()), along(ctrl.size());
  const double length = chord_frame(ctrl, radius, across, along);
  if (length < 0.0) return with_margin(1.0, radius);
  double max_across = 0.0, max_over = 0.0;
  for (std::size_t i = 0; i < ctrl.size(); ++i) {
    max_across = std::max(max_across, std::abs(across[i]));
    max_over = std::max({max_over, -along[i], along[i] - length});
  }
  return with_margin(std::hypot(max_across, max_over), radius);
}

}  // namespace curvescan::detail
