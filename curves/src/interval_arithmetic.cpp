// The four operations, square root, abs, min and max on Intervals (interval.h), outward rounded through
// interval_rounding.h. Moore, *Interval Analysis* (1966), chapter 2, for the endpoint formulas.
#include <algorithm>
#include <cmath>
#include <iterator>

#include "curvescan/curves/interval.h"
#include "interval_rounding.h"

namespace curvescan {

using detail::kInfinity;

Interval Interval::entire() noexcept {
  return {-kInfinity, kInfinity, false, false};
}
Interval Interval::undefined() noexcept {
  return {0.0, 0.0, true, true};
}
Interval Interval::hull_of(double a, double b) noexcept {
  return {std::min(a, b), std::max(a, b), false, false};
}

bool Interval::is_bounded() const noexcept {
  return !empty && std::isfinite(lo) && std::isfinite(hi);
}
double Interval::magnitude() const noexcept {
  return empty ? 0.0 : std::max(std::abs(lo), std::abs(hi));
}

namespace {

// An operation's flags from its operands: empty if either is (the double evaluation is NaN everywhere).
Interval with_flags(Interval result, const Interval& a, const Interval& b) noexcept {
  result.partial = result.partial || a.partial || b.partial;
  if (a.empty || b.empty) return Interval::undefined();
  if (std::isnan(result.lo)) result.lo = -kInfinity;
  if (std::isnan(result.hi)) result.hi = kInfinity;
  return result;
}

bool can_be_plus_infinity(const Interval& a) noexcept {
  return a.hi == kInfinity;
}
bool can_be_minus_infinity(const Interval& a) noexcept {
  return a.lo == -kInfinity;
}
bool can_be_infinite(const Interval& a) noexcept {
  return can_be_plus_infinity(a) || can_be_minus_infinity(a);
}

}  // namespace

Interval hull(const Interval& a, const Interval& b) noexcept {
  if (a.empty && b.empty) return Interval::undefined();
  if (a.empty) return {b.lo, b.hi, true, false};
  if (b.empty) return {a.lo, a.hi, true, false};
  return {std::min(a.lo, b.lo), std::max(a.hi, b.hi), a.partial || b.partial, false};
}

Interval operator-(const Interval& a) noexcept {
  return {-a.hi, -a.lo, a.partial, a.empty};
}

Interval operator+(const Interval& a, const Interval& b) noexcept {
  Interval r{detail::add_down(a.lo, b.lo), detail::add_up(a.hi, b.hi), false, false};
  // inf + (−inf) is NaN in the double evaluation.
  r.partial = (can_be_plus_infinity(a) && can_be_minus_infinity(b)) ||
              (can_be_minus_infinity(a) && can_be_plus_infinity(b));
  return with_flags(r, a, b);
}

Interval operator-(const Interval& a, const Interval& b) noexcept {
  return a + (-b);
}

Interval operator*(const Interval& a, const Interval& b) noexcept {
  if (a.empty || b.empty) return with_flags({}, a, b);
  const double lows[] = {detail::mul_down(a.lo, b.lo), detail::mul_down(a.lo, b.hi),
                         detail::mul_down(a.hi, b.lo), detail::mul_down(a.hi, b.hi)};
  const double highs[] = {detail::mul_up(a.lo, b.lo), detail::mul_up(a.lo, b.hi), detail::mul_up(a.hi, b.lo),
                          detail::mul_up(a.hi, b.hi)};
  Interval r{*std::min_element(std::begin(lows), std::end(lows)),
             *std::max_element(std::begin(highs), std::end(highs)), false, false};
  // 0 · inf is NaN in the double evaluation.
  r.partial = (a.contains_zero() && can_be_infinite(b)) || (b.contains_zero() && can_be_infinite(a));
  return with_flags(r, a, b);
}

Interval operator/(const Interval& a, const Interval& b) noexcept {
  if (a.empty || b.empty) return with_flags({}, a, b);
  if (b.contains_zero()) {
    // x / 0 is ±inf (the sign of zero decides), 0 / 0 is NaN: the whole line.
    Interval r = Interval::entire();
    r.partial = a.contains_zero() || (can_be_infinite(a) && can_be_infinite(b));
    return with_flags(r, a, b);
  }
  const double lows[] = {detail::div_down(a.lo, b.lo), detail::div_down(a.lo, b.hi),
                         detail::div_down(a.hi, b.lo), detail::div_down(a.hi, b.hi)};
  const double highs[] = {detail::div_up(a.lo, b.lo), detail::div_up(a.lo, b.hi), detail::div_up(a.hi, b.lo),
                          detail::div_up(a.hi, b.hi)};
  Interval r{*std::min_element(std::begin(lows), std::end(lows)),
             *std::max_element(std::begin(highs), std::end(highs)), false, false};
  if (can_be_infinite(a) && can_be_infinite(b)) {  // inf / inf is NaN
    r = Interval::entire();
    r.partial = true;
  }
  return with_flags(r, a, b);
}

Interval sqrt(const Interval& a) noexcept {
  if (a.empty || a.hi < 0) return Interval::undefined();
  Interval r{a.lo <= 0 ? 0.0 : detail::sqrt_down(a.lo), detail::sqrt_up(a.hi), a.partial || a.lo < 0, false};
  return r;
}

Interval abs(const Interval& a) noexcept {
  if (a.empty) return a;
  if (a.lo >= 0) return a;
  if (a.hi <= 0) return -a;
  return {0.0, std::max(-a.lo, a.hi), a.partial, false};
}

// min and max propagate NaN, as the double evaluation does (expression.h).
Interval min(const Interval& a, const Interval& b) noexcept {
  return with_flags({std::min(a.lo, b.lo), std::min(a.hi, b.hi), false, false}, a, b);
}
Interval max(const Interval& a, const Interval& b) noexcept {
  return with_flags({std::max(a.lo, b.lo), std::max(a.hi, b.hi), false, false}, a, b);
}

}  // namespace curvescan
