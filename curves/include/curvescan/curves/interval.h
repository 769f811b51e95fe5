// Interval arithmetic with outward rounding: the enclosures behind the certified explicit and implicit
// curves (explicit_curve.h, implicit_curve.h) and the interval evaluation of an Expression.
//
// An Interval [lo, hi] encloses every value a function takes over a box of arguments (Moore, *Interval
// Analysis*, 1966; the inclusion property). Every bound is rounded outward: +, −, ×, ÷ and sqrt use the
// error-free transformations (the exact rounding error of a sum from TwoSum, of a product or quotient
// from fma) and step one ulp outward only when the result was inexact, so exact results such as 0·x or
// x² at 0 stay exact; the elementary functions of libm are not correctly rounded (glibc documents at most
// one or two ulps) and their bounds step two ulps outward. Bounds may be infinite: a division by an
// interval containing 0 is the entire line.
//
// Domains: a function evaluated on a box that is partly outside its domain (log of [−1, 2], asin of
// [0, 3]) encloses what it takes on the part inside and sets `partial` (the double evaluation would give
// NaN somewhere in the box); a box wholly outside gives an `empty` interval (NaN everywhere). Both flags
// propagate through every operation. `partial` is also set where the double evaluation can meet an IEEE
// invalid operation (∞ − ∞, 0 · ∞, ∞ / ∞, sin ∞).
#pragma once

namespace curvescan {

/// A closed interval of doubles with the two domain flags above. Invariant when !empty: lo <= hi, neither
/// is NaN. Default: the point 0.
struct Interval {
  double lo = 0.0;
  double hi = 0.0;
  bool partial = false;  ///< the enclosed function is undefined (NaN) at some point of the argument box
  bool empty = false;    ///< the enclosed function is undefined at every point of the argument box

  static Interval point(double value) noexcept { return {value, value, false, false}; }
  static Interval entire() noexcept;
  static Interval undefined() noexcept;  ///< empty and partial
  /// The hull of [a, b] in either order (a and b finite or infinite, not NaN).
  static Interval hull_of(double a, double b) noexcept;

  [[nodiscard]] bool contains(double value) const noexcept { return !empty && lo <= value && value <= hi; }
  [[nodiscard]] bool contains_zero() const noexcept { return contains(0.0); }
  [[nodiscard]] bool is_bounded() const noexcept;  ///< not empty, both bounds finite
  [[nodiscard]] double width() const noexcept { return hi - lo; }
  [[nodiscard]] double magnitude() const noexcept;  ///< max |v| over the interval (+inf if unbounded)
};

/// The smallest interval holding both (flags or'ed; an empty operand is ignored, its `partial` kept).
Interval hull(const Interval& a, const Interval& b) noexcept;

Interval operator-(const Interval& a) noexcept;
Interval operator+(const Interval& a, const Interval& b) noexcept;
Interval operator-(const Interval& a, const Interval& b) noexcept;
Interval operator*(const Interval& a, const Interval& b) noexcept;
Interval operator/(const Interval& a, const Interval& b) noexcept;

/// Elementary functions: enclosures of the libm functions of the same name over the interval (domains
/// as described above; tan's poles and atan2's branch cut give the whole range).
Interval sin(const Interval& a) noexcept;
Interval cos(const Interval& a) noexcept;
Interval tan(const Interval& a) noexcept;
Interval asin(const Interval& a) noexcept;
Interval acos(const Interval& a) noexcept;
Interval atan(const Interval& a) noexcept;
Interval atan2(const Interval& y, const Interval& x) noexcept;
Interval exp(const Interval& a) noexcept;
Interval log(const Interval& a) noexcept;
Interval sqrt(const Interval& a) noexcept;
Interval abs(const Interval& a) noexcept;
Interval min(const Interval& a, const Interval& b) noexcept;
Interval max(const Interval& a, const Interval& b) noexcept;
/// std::pow over boxes: an integer point exponent uses the exact power rules (even powers fold at 0);
/// otherwise exp(b·log a) for positive bases; negative bases with a non-integer exponent are `partial`.
Interval pow(const Interval& a, const Interval& b) noexcept;

}  // namespace curvescan
