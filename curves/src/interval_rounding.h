// Directed rounding for interval arithmetic (interval.h), without changing the FPU rounding mode: the
// result rounded to nearest, then one ulp outward unless an error-free transformation proves it exact
// (TwoSum for sums, fma for products, quotients and square roots: Ogita, Rump and Oishi, "Accurate sum and
// dot product", SIAM J. Sci. Comput. 26, 2005). Under- and overflow, where those transformations are not
// exact, step outward unconditionally.
#pragma once

#include <cfloat>
#include <cmath>
#include <limits>

namespace curvescan::detail {

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Below this magnitude a rounding error may be lost to underflow: always step outward.
inline constexpr double kTinyMagnitude = 0x1p-900;

inline double step_down(double v) noexcept {
  return v == -kInfinity ? v : std::nextafter(v, -kInfinity);
}
inline double step_up(double v) noexcept {
  return v == kInfinity ? v : std::nextafter(v, kInfinity);
}

/// A rounded-to-nearest result whose exact value lies at most `ulps` ulps away: the lower bound.
inline double widen_down(double v, int ulps) noexcept {
  for (int i = 0; i < ulps; ++i) v = step_down(v);
  return v;
}
inline double widen_up(double v, int ulps) noexcept {
  for (int i = 0; i < ulps; ++i) v = step_up(v);
  return v;
}

// Overflow of finite operands to ±inf: the exact value is beyond DBL_MAX, so the bound on the near side is
// DBL_MAX (the far side keeps the infinity).
inline double overflow_down(double r) noexcept {
  return r == kInfinity ? DBL_MAX : r;
}
inline double overflow_up(double r) noexcept {
  return r == -kInfinity ? -DBL_MAX : r;
}

/// The rounding error of a + b: sign of (exact − rounded), by TwoSum (Knuth); finite inputs and result.
inline double sum_error(double a, double b, double s) noexcept {
  const double bb = s - a;
  return (a - (s - bb)) + (b - bb);
}

inline double add_down(double a, double b) noexcept {
  const double s = a + b;
  if (!std::isfinite(a) || !std::isfinite(b)) return s;
  if (!std::isfinite(s)) return overflow_down(s);
  return sum_error(a, b, s) < 0 ? step_down(s) : s;
}
inline double add_up(double a, double b) noexcept {
  const double s = a + b;
  if (!std::isfinite(a) || !std::isfinite(b)) return s;
  if (!std::isfinite(s)) return overflow_up(s);
  return sum_error(a, b, s) > 0 ? step_up(s) : s;
}

// Products of bounds: 0 · ±inf is 0 here (a bound of a set of reals, not an IEEE operation; the caller
// flags the invalid operation separately).
inline double product_error(double a, double b, double p) noexcept {
  return std::fma(a, b, -p);
}
inline double mul_down(double a, double b) noexcept {
  if (a == 0.0 || b == 0.0) return 0.0;
  const double p = a * b;
  if (!std::isfinite(a) || !std::isfinite(b)) return p;
  if (!std::isfinite(p)) return overflow_down(p);
  if (std::abs(p) < kTinyMagnitude) return step_down(p);
  return product_error(a, b, p) < 0 ? step_down(p) : p;
}
inline double mul_up(double a, double b) noexcept {
  if (a == 0.0 || b == 0.0) return 0.0;
  const double p = a * b;
  if (!std::isfinite(a) || !std::isfinite(b)) return p;
  if (!std::isfinite(p)) return overflow_up(p);
  if (std::abs(p) < kTinyMagnitude) return step_up(p);
  return product_error(a, b, p) > 0 ? step_up(p) : p;
}

// Quotients of bounds, b != 0; finite / inf = 0 and inf / finite = inf (the caller flags inf / inf).
inline int quotient_error_sign(double a, double b, double q) noexcept {
  const double r = std::fma(-q, b, a);  // a − q·b exactly: the exact quotient is q + r / b
  if (r == 0.0) return 0;
  return (r > 0) == (b > 0) ? 1 : -1;
}
inline double div_down(double a, double b) noexcept {
  const double q = a / b;
  if (a == 0.0) return 0.0;
  if (!std::isfinite(a) || !std::isfinite(b)) return q;
  if (!std::isfinite(q)) return overflow_down(q);
  if (std::abs(q) < kTinyMagnitude || std::abs(a) < kTinyMagnitude) return step_down(q);
  return quotient_error_sign(a, b, q) < 0 ? step_down(q) : q;
}
inline double div_up(double a, double b) noexcept {
  const double q = a / b;
  if (a == 0.0) return 0.0;
  if (!std::isfinite(a) || !std::isfinite(b)) return q;
  if (!std::isfinite(q)) return overflow_up(q);
  if (std::abs(q) < kTinyMagnitude || std::abs(a) < kTinyMagnitude) return step_up(q);
  return quotient_error_sign(a, b, q) > 0 ? step_up(q) : q;
}

// Square roots of a >= 0.
inline double sqrt_down(double a) noexcept {
  const double s = std::sqrt(a);
  if (a == 0.0 || !std::isfinite(a)) return s;
  if (a < kTinyMagnitude) return step_down(s);
  return std::fma(-s, s, a) < 0 ? step_down(s) : s;
}
inline double sqrt_up(double a) noexcept {
  const double s = std::sqrt(a);
  if (a == 0.0 || !std::isfinite(a)) return s;
  if (a < kTinyMagnitude) return step_up(s);
  return std::fma(-s, s, a) > 0 ? step_up(s) : s;
}

}  // namespace curvescan::detail
