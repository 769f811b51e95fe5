// Evaluating an expression in double and in interval arithmetic (expression.h) through the one program
// loop of expression_program.h.
#include <cmath>

#include "curvescan/curves/expression.h"
#include "expression_program.h"

namespace curvescan {
namespace {

// The C library's arithmetic; min and max propagate NaN (std::fmin would drop it and hide an undefined
// argument).
struct DoubleMath {
  using Number = double;
  double vx, vy, vt;
  double constant(double v) const noexcept { return v; }
  double x() const noexcept { return vx; }
  double y() const noexcept { return vy; }
  double t() const noexcept { return vt; }
  static double negate(double a) noexcept { return -a; }
  static double add(double a, double b) noexcept { return a + b; }
  static double subtract(double a, double b) noexcept { return a - b; }
  static double multiply(double a, double b) noexcept { return a * b; }
  static double divide(double a, double b) noexcept { return a / b; }
  static double power(double a, double b) noexcept { return std::pow(a, b); }
  static double atan2(double a, double b) noexcept { return std::atan2(a, b); }
  static double min(double a, double b) noexcept {
    return std::isnan(a) || std::isnan(b) ? NAN : (b < a ? b : a);
  }
  static double max(double a, double b) noexcept {
    return std::isnan(a) || std::isnan(b) ? NAN : (a < b ? b : a);
  }
  static double sin(double a) noexcept { return std::sin(a); }
  static double cos(double a) noexcept { return std::cos(a); }
  static double tan(double a) noexcept { return std::tan(a); }
  static double asin(double a) noexcept { return std::asin(a); }
  static double acos(double a) noexcept { return std::acos(a); }
  static double atan(double a) noexcept { return std::atan(a); }
  static double exp(double a) noexcept { return std::exp(a); }
  static double log(double a) noexcept { return std::log(a); }
  static double sqrt(double a) noexcept { return std::sqrt(a); }
  static double abs(double a) noexcept { return std::fabs(a); }
};

struct IntervalMath {
  using Number = Interval;
  Interval vx, vy, vt;
  Interval constant(double v) const noexcept { return Interval::point(v); }
  Interval x() const noexcept { return vx; }
  Interval y() const noexcept { return vy; }
  Interval t() const noexcept { return vt; }
  static Interval negate(const Interval& a) noexcept { return -a; }
  static Interval add(const Interval& a, const Interval& b) noexcept { return a + b; }
  static Interval subtract(const Interval& a, const Interval& b) noexcept { return a - b; }
  static Interval multiply(const Interval& a, const Interval& b) noexcept { return a * b; }
  static Interval divide(const Interval& a, const Interval& b) noexcept { return a / b; }
  static Interval power(const Interval& a, const Interval& b) noexcept { return curvescan::pow(a, b); }
  static Interval atan2(const Interval& a, const Interval& b) noexcept { return curvescan::atan2(a, b); }
  static Interval min(const Interval& a, const Interval& b) noexcept { return curvescan::min(a, b); }
  static Interval max(const Interval& a, const Interval& b) noexcept { return curvescan::max(a, b); }
  static Interval sin(const Interval& a) noexcept { return curvescan::sin(a); }
  static Interval cos(const Interval& a) noexcept { return curvescan::cos(a); }
  static Interval tan(const Interval& a) noexcept { return curvescan::tan(a); }
  static Interval asin(const Interval& a) noexcept { return curvescan::asin(a); }
  static Interval acos(const Interval& a) noexcept { return curvescan::acos(a); }
  static Interval atan(const Interval& a) noexcept { return curvescan::atan(a); }
  static Interval exp(const Interval& a) noexcept { return curvescan::exp(a); }
  static Interval log(const Interval& a) noexcept { return curvescan::log(a); }
  static Interval sqrt(const Interval& a) noexcept { return curvescan::sqrt(a); }
  static Interval abs(const Interval& a) noexcept { return curvescan::abs(a); }
};

}  // namespace

double Expression::evaluate(double x, double y, double t) const noexcept {
  return detail::run_program(program_, stack_size_, DoubleMath{x, y, t});
}

Interval Expression::evaluate(const Interval& x, const Interval& y, const Interval& t) const noexcept {
  return detail::run_program(program_, stack_size_, IntervalMath{x, y, t});
}

}  // namespace curvescan
