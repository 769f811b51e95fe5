// The elementary functions on Intervals (interval.h). Monotone functions map their endpoints; sin, cos and
// tan locate their extrema and poles by the period, conservatively (a candidate within rounding of an
// endpoint counts as inside, which can only widen the enclosure). libm's results are within two ulps
// (the glibc manual's table of errors), so bounds from libm step two ulps outward.
#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>

#include "curvescan/curves/interval.h"
#include "interval_rounding.h"

namespace curvescan {

using detail::kInfinity;

namespace {

constexpr int kLibmUlps = 2;
constexpr double kPi = std::numbers::pi;
// Beyond this magnitude the period of sin is resolved too coarsely to locate extrema: the whole range.
constexpr double kLargeAngle = 1e12;

double libm_down(double v) noexcept {
  return std::isnan(v) ? -kInfinity : detail::widen_down(v, kLibmUlps);
}
double libm_up(double v) noexcept {
  return std::isnan(v) ? kInfinity : detail::widen_up(v, kLibmUlps);
}

Interval clamp_to(Interval r, double lo, double hi) noexcept {
  r.lo = std::clamp(r.lo, lo, hi);
  r.hi = std::clamp(r.hi, lo, hi);
  return r;
}

// A monotone increasing function f over a (within its domain), bounds widened for libm's error.
template <class F>
Interval increasing(const Interval& a, F f) noexcept {
  return {libm_down(f(a.lo)), libm_up(f(a.hi)), a.partial, false};
}

// Whether [lo, hi] may contain a point offset + k·period for an integer k. Conservative by a margin for
// the rounding of the subtraction and division (a few ulps of k) and for π in double being 1.2e-16
// relative off the true π (so k is off by up to 1.2e-16 |k|): 1e-15 (1 + |k|) covers both several
// times. A margin much wider than that makes every piece near a pole of tan look like it holds the pole,
// and the explicit flattener splits them without end.
bool may_contain_shifted(double lo, double hi, double offset, double period) noexcept {
  const double k_lo = (lo - offset) / period;
  const double k_hi = (hi - offset) / period;
  const double margin = 1e-15 * (1.0 + std::abs(k_lo) + std::abs(k_hi));
  return std::floor(k_hi + margin) >= std::ceil(k_lo - margin);
}

bool has_infinite_bound(const Interval& a) noexcept {
  return !std::isfinite(a.lo) || !std::isfinite(a.hi);
}

// sin over a: the endpoint values, and ±1 where a maximum (π/2 + 2kπ) or minimum (−π/2 + 2kπ) may lie
// inside. cos(x) is evaluated the same way with the extrema at 2kπ and π + 2kπ.
Interval periodic_unit(const Interval& a, double (*f)(double), double max_at, double min_at) noexcept {
  if (a.empty) return a;
  Interval r{-1.0, 1.0, a.partial || has_infinite_bound(a), false};  // sin(±inf) is NaN
  if (has_infinite_bound(a) || a.hi - a.lo >= 2 * kPi ||
      std::max(std::abs(a.lo), std::abs(a.hi)) > kLargeAngle) {
    return r;
  }
  const double at_lo = f(a.lo);
  const double at_hi = f(a.hi);
  r.lo = may_contain_shifted(a.lo, a.hi, min_at, 2 * kPi) ? -1.0 : libm_down(std::min(at_lo, at_hi));
  r.hi = may_contain_shifted(a.lo, a.hi, max_at, 2 * kPi) ? 1.0 : libm_up(std::max(at_lo, at_hi));
  return clamp_to(r, -1.0, 1.0);
}

double libm_sin(double v) noexcept {
  return std::sin(v);
}
double libm_cos(double v) noexcept {
  return std::cos(v);
}

}  // namespace

Interval sin(const Interval& a) noexcept {
  return periodic_unit(a, libm_sin, kPi / 2, -kPi / 2);
}
Interval cos(const Interval& a) noexcept {
  return periodic_unit(a, libm_cos, 0.0, kPi);
}

Interval tan(const Interval& a) noexcept {
  if (a.empty) return a;
  Interval r = Interval::entire();
  r.partial = a.partial || has_infinite_bound(a);
  // A pole (π/2 + kπ) inside: tan takes every value there (libm returns large finite numbers near it).
  if (has_infinite_bound(a) || a.hi - a.lo >= kPi || std::max(std::abs(a.lo), std::abs(a.hi)) > kLargeAngle ||
      may_contain_shifted(a.lo, a.hi, kPi / 2, kPi)) {
    return r;
  }
  const double at_lo = std::tan(a.lo);
  const double at_hi = std::tan(a.hi);
  if (at_lo > at_hi) return r;  // a pole between after all
  r.lo = libm_down(at_lo);
  r.hi = libm_up(at_hi);
  return r;
}

Interval asin(const Interval& a) noexcept {
  if (a.empty || a.hi < -1.0 || a.lo > 1.0) return Interval::undefined();
  const Interval inside{std::max(a.lo, -1.0), std::min(a.hi, 1.0), a.partial || a.lo < -1.0 || a.hi > 1.0,
                        false};
  return clamp_to(increasing(inside, [](double v) { return std::asin(v); }), -kPi / 2 - 1e-15,
                  kPi / 2 + 1e-15);
}

Interval acos(const Interval& a) noexcept {
  if (a.empty || a.hi < -1.0 || a.lo > 1.0) return Interval::undefined();
  const bool outside = a.lo < -1.0 || a.hi > 1.0;
  const double lo = std::max(a.lo, -1.0);
  const double hi = std::min(a.hi, 1.0);
  Interval r{libm_down(std::acos(hi)), libm_up(std::acos(lo)), a.partial || outside, false};
  return clamp_to(r, 0.0, kPi + 1e-15);
}

Interval atan(const Interval& a) noexcept {
  if (a.empty) return a;
  return clamp_to(increasing(a, [](double v) { return std::atan(v); }), -kPi / 2 - 1e-15, kPi / 2 + 1e-15);
}

Interval atan2(const Interval& y, const Interval& x) noexcept {
  if (y.empty || x.empty) return Interval::undefined();
  const bool partial = y.partial || x.partial;
  const Interval whole{-kPi - 1e-15, kPi + 1e-15, partial, false};
  // The branch cut (the negative x axis, where atan2 jumps from π to −π, and the sign of zero decides) or
  // the origin inside, or unbounded boxes: the whole range.
  if (has_infinite_bound(x) || has_infinite_bound(y) || (x.lo <= 0 && y.lo <= 0 && y.hi >= 0)) return whole;
  // Otherwise the box is a convex set away from the origin and the cut: atan2 is continuous on it and its
  // extremes, angles of a convex polygon seen from outside, are at corners.
  const double corners[] = {std::atan2(y.lo, x.lo), std::atan2(y.lo, x.hi), std::atan2(y.hi, x.lo),
                            std::atan2(y.hi, x.hi)};
  Interval r{libm_down(*std::min_element(std::begin(corners), std::end(corners))),
             libm_up(*std::max_element(std::begin(corners), std::end(corners))), partial, false};
  return clamp_to(r, -kPi - 1e-15, kPi + 1e-15);
}

Interval exp(const Interval& a) noexcept {
  if (a.empty) return a;
  Interval r = increasing(a, [](double v) { return std::exp(v); });
  r.lo = std::max(r.lo, 0.0);
  return r;
}

Interval log(const Interval& a) noexcept {
  if (a.empty || a.hi < 0) return Interval::undefined();
  // log(0) = −inf, log of a negative part is NaN.
  Interval r{a.lo <= 0 ? -kInfinity : libm_down(std::log(a.lo)), libm_up(std::log(a.hi)),
             a.partial || a.lo < 0, false};
  if (a.hi == 0) r.hi = -kInfinity;
  return r;
}

namespace {

// |a|^n bounds for a >= 0 and an integer n >= 1, by directed products (exact where the products are).
double power_down(double a, long n) noexcept {
  double result = 1.0;
  double base = a;
  while (n > 0) {
    if (n & 1) result = detail::mul_down(result, base);
    n >>= 1;
    if (n > 0) base = detail::mul_down(base, base);
  }
  return result;
}
double power_up(double a, long n) noexcept {
  double result = 1.0;
  double base = a;
  while (n > 0) {
    if (n & 1) result = detail::mul_up(result, base);
    n >>= 1;
    if (n > 0) base = detail::mul_up(base, base);
  }
  return result;
}

// a^n for an integer n >= 1: monotone for odd n, folded at 0 for even n.
Interval integer_power(const Interval& a, long n) noexcept {
  if (n % 2 == 1) {
    const double lo = a.lo < 0 ? -power_up(-a.lo, n) : power_down(a.lo, n);
    const double hi = a.hi < 0 ? -power_down(-a.hi, n) : power_up(a.hi, n);
    return {lo, hi, a.partial, false};
  }
  const Interval m = abs(a);
  return {power_down(m.lo, n), power_up(m.hi, n), a.partial, false};
}

// The largest integer exponent taken by repeated squaring; beyond it std::pow's result is widened.
constexpr double kLargestExactExponent = 1 << 20;

// Whether b holds a negative odd integer. Every double beyond 2^53 in magnitude is even, so the odd ones
// start at -(2^53 - 1).
bool contains_negative_odd_integer(const Interval& b) noexcept {
  const double hi = std::min(b.hi, -1.0);
  double k = std::max(std::ceil(b.lo), -9007199254740991.0);
  if (std::fmod(k, 2.0) == 0.0) k += 1.0;
  return k <= hi;
}

}  // namespace

Interval pow(const Interval& a, const Interval& b) noexcept {
  // pow(1, NaN) and pow(NaN, 0) are 1 in C: an argument undefined everywhere still leaves that value.
  if (a.empty && b.empty) return Interval::undefined();
  if (b.empty) return a.contains(1.0) ? Interval{1.0, 1.0, true, false} : Interval::undefined();
  if (a.empty) return b.contains(0.0) ? Interval{1.0, 1.0, true, false} : Interval::undefined();
  const bool flags = a.partial || b.partial;
  if (b.lo == b.hi && std::isfinite(b.lo) && b.lo == std::floor(b.lo) &&
      std::abs(b.lo) <= kLargestExactExponent) {
    const long n = static_cast<long>(b.lo);
    // pow(x, 0) is 1 for every x, NaN included; but where the exponent itself is undefined (b.partial)
    // the power is NaN too (pow(0, NaN) is NaN).
    if (n == 0) return {1.0, 1.0, b.partial, false};
    Interval r = integer_power(a, std::abs(n));
    r.partial = r.partial || flags;
    if (n < 0) r = Interval::point(1.0) / r;
    return r;
  }
  if (has_infinite_bound(a) || has_infinite_bound(b)) {
    Interval r = Interval::entire();
    r.partial = true;
    return r;
  }
  if (a.lo < 0) {
    // Negative bases: NaN for non-integer exponents, any sign for integer ones inside b.
    Interval r = Interval::entire();
    r.partial = true;
    return r;
  }
  if (a.lo == 0) {
    // pow(0, b) is 0 for b > 0, +inf for b < 0, 1 for b = 0: fold those into exp(b · log a) of the rest.
    const Interval top = exp(b * log(Interval{a.hi, a.hi, false, false}));
    Interval r{0.0, kInfinity, flags, false};
    // a^b increases with a for b > 0 and decreases for b < 0, so a.hi^b bounds it on the far side.
    if (b.lo > 0) r.hi = top.hi;
    if (b.hi < 0) r.lo = top.lo;
    // A base that reaches 0 may be -0 in the double evaluation (a product that underflows keeps its
    // sign: x^3 * y at x = -1e-300, y = 0), and pow(-0, n) is -inf for a negative odd integer n (C
    // 7.12.7.4): the enclosure must reach -inf then.
    if (contains_negative_odd_integer(b)) r.lo = -kInfinity;
    return r;
  }
  Interval r = exp(b * log(a));
  r.partial = r.partial || flags;
  return r;
}

}  // namespace curvescan
