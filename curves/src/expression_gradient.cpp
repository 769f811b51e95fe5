// The interval gradient of an expression (expression.h): forward-mode automatic differentiation where
// every quantity is an Interval, through the one program loop of expression_program.h. The chain rule of
// each function is the textbook one; at kinks (abs at 0, min and max where the arguments overlap) the
// derivative enclosure is the hull of both sides, so it holds Clarke's generalized gradient and the mean
// value inequality holds on boxes across the kink (Clarke, *Optimization and Nonsmooth Analysis*, 1983).
#include <cmath>

#include "curvescan/curves/expression.h"
#include "expression_program.h"

namespace curvescan {
namespace {

using Jet = IntervalGradient;

const Interval kZero = Interval::point(0.0);
const Interval kOne = Interval::point(1.0);

bool is_zero(const Interval& a) noexcept {
  return !a.empty && !a.partial && a.lo == 0.0 && a.hi == 0.0;
}

// The derivatives of an outer function with derivative `outer` at the argument: outer · d.
Jet chain(const Interval& value, const Interval& outer, const Jet& a) noexcept {
  return {value, outer * a.dx, outer * a.dy};
}

Interval square(const Interval& a) noexcept {
  return curvescan::pow(a, Interval::point(2.0));
}

struct GradientMath {
  using Number = Jet;
  Interval vx, vy;
  Jet constant(double v) const noexcept { return {Interval::point(v), kZero, kZero}; }
  Jet x() const noexcept { return {vx, kOne, kZero}; }
  Jet y() const noexcept { return {vy, kZero, kOne}; }
  Jet t() const noexcept {
    return {kZero, kZero, kZero};
  }  // t is 0 in gradients (implicit and explicit curves)
  static Jet negate(const Jet& a) noexcept { return {-a.value, -a.dx, -a.dy}; }
  static Jet add(const Jet& a, const Jet& b) noexcept {
    return {a.value + b.value, a.dx + b.dx, a.dy + b.dy};
  }
  static Jet subtract(const Jet& a, const Jet& b) noexcept {
    return {a.value - b.value, a.dx - b.dx, a.dy - b.dy};
  }
  static Jet multiply(const Jet& a, const Jet& b) noexcept {
    return {a.value * b.value, a.dx * b.value + a.value * b.dx, a.dy * b.value + a.value * b.dy};
  }
  static Jet divide(const Jet& a, const Jet& b) noexcept {
    const Interval q = a.value / b.value;
    return {q, (a.dx - q * b.dx) / b.value, (a.dy - q * b.dy) / b.value};
  }
  static Jet power(const Jet& a, const Jet& b) noexcept {
    const Interval value = curvescan::pow(a.value, b.value);
    if (is_zero(b.dx) && is_zero(b.dy)) {  // a constant exponent: b · a^(b−1) · a'
      if (b.value.lo == b.value.hi && b.value.lo == 0.0) return {value, kZero, kZero};
      const Interval outer = b.value * curvescan::pow(a.value, b.value - kOne);
      return chain(value, outer, a);
    }
    const Interval log_a = curvescan::log(a.value);
    if (is_zero(a.dx) && is_zero(a.dy)) {  // a constant base: a^b · log a · b'
      return chain(value, value * log_a, b);
    }
    // a^b · (b' log a + b a' / a)
    const Interval ratio = b.value / a.value;
    return {value, value * (b.dx * log_a + ratio * a.dx), value * (b.dy * log_a + ratio * a.dy)};
  }
  static Jet atan2(const Jet& y, const Jet& x) noexcept {
    const Interval r2 = square(x.value) + square(y.value);
    return {curvescan::atan2(y.value, x.value), (x.value * y.dx - y.value * x.dx) / r2,
            (x.value * y.dy - y.value * x.dy) / r2};
  }
  static Jet select(const Interval& value, const Jet& a, const Jet& b, bool a_only, bool b_only) noexcept {
    if (a_only) return {value, a.dx, a.dy};
    if (b_only) return {value, b.dx, b.dy};
    return {value, hull(a.dx, b.dx), hull(a.dy, b.dy)};
  }
  static Jet min(const Jet& a, const Jet& b) noexcept {
    return select(curvescan::min(a.value, b.value), a, b, a.value.hi < b.value.lo, b.value.hi < a.value.lo);
  }
  static Jet max(const Jet& a, const Jet& b) noexcept {
    return select(curvescan::max(a.value, b.value), a, b, a.value.lo > b.value.hi, b.value.lo > a.value.hi);
  }
  static Jet sin(const Jet& a) noexcept { return chain(curvescan::sin(a.value), curvescan::cos(a.value), a); }
  static Jet cos(const Jet& a) noexcept {
    return chain(curvescan::cos(a.value), -curvescan::sin(a.value), a);
  }
  static Jet tan(const Jet& a) noexcept {
    const Interval value = curvescan::tan(a.value);
    return chain(value, kOne + square(value), a);
  }
  static Jet asin(const Jet& a) noexcept {
    return chain(curvescan::asin(a.value), kOne / curvescan::sqrt(kOne - square(a.value)), a);
  }
  static Jet acos(const Jet& a) noexcept {
    return chain(curvescan::acos(a.value), -(kOne / curvescan::sqrt(kOne - square(a.value))), a);
  }
  static Jet atan(const Jet& a) noexcept {
    return chain(curvescan::atan(a.value), kOne / (kOne + square(a.value)), a);
  }
  static Jet exp(const Jet& a) noexcept {
    const Interval value = curvescan::exp(a.value);
    return chain(value, value, a);
  }
  static Jet log(const Jet& a) noexcept { return chain(curvescan::log(a.value), kOne / a.value, a); }
  static Jet sqrt(const Jet& a) noexcept {
    const Interval value = curvescan::sqrt(a.value);
    return chain(value, kOne / (Interval::point(2.0) * value), a);
  }
  static Jet abs(const Jet& a) noexcept {
    const Interval sign = a.value.lo > 0 ? kOne : a.value.hi < 0 ? -kOne : Interval{-1.0, 1.0, false, false};
    return chain(curvescan::abs(a.value), sign, a);
  }
};

}  // namespace

IntervalGradient Expression::evaluate_gradient(const Interval& x, const Interval& y) const noexcept {
  return detail::run_program(program_, stack_size_, GradientMath{x, y});
}

}  // namespace curvescan
