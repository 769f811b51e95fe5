// Expressions: the formulas of explicit curves y = f(x) and implicit curves f(x, y) = 0 (Ince after Elias,
// *Lecture 11: Curves*, "Representations of curves"), parsed once and evaluated in double and in interval
// arithmetic (interval.h) from the same program.
//
// Grammar (docs/curve-spec.md, "Expressions"):
//   expression := term (("+" | "-") term)*
//   term       := unary (("*" | "/") unary)*
//   unary      := ("-" | "+") unary | power
//   power      := primary ("^" unary)?            right-associative: 2^3^2 = 2^9; -x^2 = -(x^2)
//   primary    := number | name | name "(" expression ("," expression)* ")" | "(" expression ")"
// Names: the variables the caller allows (x, y, t), the constants pi and e, and the functions sin cos tan
// asin acos atan exp log sqrt abs (one argument), atan2 min max pow (two). Numbers are decimal, with an
// optional exponent (1.5e-3). The double evaluation is the C library's: x/0 is ±inf, log(-1) is NaN,
// pow is std::pow; min and max return NaN if either argument is NaN.
//
// Why our own: the curves library depends on nothing but the C++ standard library, and the certified
// curves need the interval and derivative evaluations of the same tree. muParser (Debian: libmuparser-dev)
// evaluates doubles only; Boost.Interval has no parser and would be this library's first dependency, and
// its rounding policies change the FPU mode where ours (interval_rounding.h) never do.
//
// Limits: the text, the nesting depth and the number of nodes are bounded (ExpressionLimits); evaluation is
// a loop over the postfix program with a stack, so no input recurses deeper than the parse depth limit.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

#include "curvescan/curves/interval.h"
#include "curvescan/status.h"

namespace curvescan {

/// The variables an expression may use.
enum class ExpressionVariable : unsigned char { kX, kY, kT };

struct ExpressionLimits {
  std::size_t max_length = 4096;  ///< characters of text
  int max_depth = 64;             ///< nesting of parentheses, function calls, unary minus and powers
  std::size_t max_nodes = 4096;   ///< constants, variables and operations in the program
};

/// An enclosure of a function and of its partial derivatives over a box (forward-mode automatic
/// differentiation in interval arithmetic). Where the function has a kink (abs, min, max) the derivative
/// enclosure holds both one-sided derivatives (Clarke's generalized gradient), so the mean value
/// inequality |f(b) − f(a)| <= |b − a| · sup |f'| still holds for the Lipschitz function.
struct IntervalGradient {
  Interval value;
  Interval dx;  ///< ∂f/∂x
  Interval dy;  ///< ∂f/∂y
};

namespace detail {

enum class ExpressionOp : unsigned char {
  kConstant,
  kX,
  kY,
  kT,
  kNegate,
  kAdd,
  kSubtract,
  kMultiply,
  kDivide,
  kPower,
  kSin,
  kCos,
  kTan,
  kAsin,
  kAcos,
  kAtan,
  kExp,
  kLog,
  kSqrt,
  kAbs,
  kAtan2,
  kMin,
  kMax,
};

/// One instruction of the postfix program: a value pushed (constant, variable) or an operation on the top
/// of the stack.
struct ExpressionNode {
  ExpressionOp op = ExpressionOp::kConstant;
  double constant = 0.0;
};

}  // namespace detail

/// A parsed expression. Evaluation is noexcept and total.
class Expression {
 public:
  /// Parses `text`, which may use only the `allowed` variables. Errors say what is wrong and where, with
  /// a 1-based column: "column 5: unknown function 'sinn'"; limits exceeded are kLimitExceeded.
  static Result<Expression> parse(std::string_view text, std::span<const ExpressionVariable> allowed,
                                  const ExpressionLimits& limits = {});

  /// The value at (x, y, t) in double arithmetic.
  [[nodiscard]] double evaluate(double x, double y = 0.0, double t = 0.0) const noexcept;
  /// An enclosure of the values over the box x × y × t.
  [[nodiscard]] Interval evaluate(const Interval& x, const Interval& y = {},
                                  const Interval& t = {}) const noexcept;
  /// Enclosures of the value and of ∂/∂x, ∂/∂y over the box x × y (t = 0).
  [[nodiscard]] IntervalGradient evaluate_gradient(const Interval& x, const Interval& y) const noexcept;

  [[nodiscard]] bool uses(ExpressionVariable variable) const noexcept;
  /// The postfix program, for tests and tools.
  [[nodiscard]] std::span<const detail::ExpressionNode> program() const noexcept { return program_; }

 private:
  std::vector<detail::ExpressionNode> program_;
  std::size_t stack_size_ = 0;
  friend class ExpressionParser;
};

}  // namespace curvescan
