// The one evaluator of an expression's postfix program (expression.h), generic over the arithmetic: double,
// Interval, and the interval gradient (value and partial derivatives). `Math` supplies the constants,
// variables and operations of its number type; the loop is the same for all, so the three evaluations
// cannot disagree about the meaning of the tree.
#pragma once

#include <span>
#include <vector>

#include "curvescan/curves/expression.h"

namespace curvescan::detail {

template <class Math>
typename Math::Number run_program(std::span<const ExpressionNode> program, std::size_t stack_size,
                                  const Math& math) noexcept {
  using Number = typename Math::Number;
  std::vector<Number> stack;
  stack.reserve(stack_size);
  for (const ExpressionNode& node : program) {
    switch (node.op) {
      case ExpressionOp::kConstant:
        stack.push_back(math.constant(node.constant));
        continue;
      case ExpressionOp::kX:
        stack.push_back(math.x());
        continue;
      case ExpressionOp::kY:
        stack.push_back(math.y());
        continue;
      case ExpressionOp::kT:
        stack.push_back(math.t());
        continue;
      default:
        break;
    }
    const bool binary = node.op == ExpressionOp::kAdd || node.op == ExpressionOp::kSubtract ||
                        node.op == ExpressionOp::kMultiply || node.op == ExpressionOp::kDivide ||
                        node.op == ExpressionOp::kPower || node.op == ExpressionOp::kAtan2 ||
                        node.op == ExpressionOp::kMin || node.op == ExpressionOp::kMax;
    if (binary) {
      const Number b = stack.back();
      stack.pop_back();
      Number& a = stack.back();
      switch (node.op) {
        case ExpressionOp::kAdd:
          a = math.add(a, b);
          break;
        case ExpressionOp::kSubtract:
          a = math.subtract(a, b);
          break;
        case ExpressionOp::kMultiply:
          a = math.multiply(a, b);
          break;
        case ExpressionOp::kDivide:
          a = math.divide(a, b);
          break;
        case ExpressionOp::kPower:
          a = math.power(a, b);
          break;
        case ExpressionOp::kAtan2:
          a = math.atan2(a, b);
          break;
        case ExpressionOp::kMin:
          a = math.min(a, b);
          break;
        case ExpressionOp::kMax:
          a = math.max(a, b);
          break;
        default:
          break;
      }
      continue;
    }
    Number& a = stack.back();
    switch (node.op) {
      case ExpressionOp::kNegate:
        a = math.negate(a);
        break;
      case ExpressionOp::kSin:
        a = math.sin(a);
        break;
      case ExpressionOp::kCos:
        a = math.cos(a);
        break;
      case ExpressionOp::kTan:
        a = math.tan(a);
        break;
      case ExpressionOp::kAsin:
        a = math.asin(a);
        break;
      case ExpressionOp::kAcos:
        a = math.acos(a);
        break;
      case ExpressionOp::kAtan:
        a = math.atan(a);
        break;
      case ExpressionOp::kExp:
        a = math.exp(a);
        break;
      case ExpressionOp::kLog:
        a = math.log(a);
        break;
      case ExpressionOp::kSqrt:
        a = math.sqrt(a);
        break;
      case ExpressionOp::kAbs:
        a = math.abs(a);
        break;
      default:
        break;
    }
  }
  return stack.empty() ? math.constant(0.0) : stack.back();
}

}  // namespace curvescan::detail
