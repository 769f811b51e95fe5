// The recursive-descent parser of expressions (grammar in expression.h). It emits the postfix program
// directly: a node is appended when its operands are, so the program is the post-order of the parse tree.
// The recursion is bounded by ExpressionLimits::max_depth, counted on every nesting rule.
#include <algorithm>
#include <array>
#include <numbers>
#include <string>

#include "curvescan/curves/expression.h"
#include "expression_tokenizer.h"

namespace curvescan {

using detail::column_prefix;
using detail::ExpressionNode;
using detail::ExpressionOp;
using detail::Token;
using detail::TokenKind;

namespace {

struct FunctionName {
  std::string_view name;
  ExpressionOp op;
  int arity;
};

constexpr std::array<FunctionName, 14> kFunctions{{
    {"sin", ExpressionOp::kSin, 1},
    {"cos", ExpressionOp::kCos, 1},
    {"tan", ExpressionOp::kTan, 1},
    {"asin", ExpressionOp::kAsin, 1},
    {"acos", ExpressionOp::kAcos, 1},
    {"atan", ExpressionOp::kAtan, 1},
    {"exp", ExpressionOp::kExp, 1},
    {"log", ExpressionOp::kLog, 1},
    {"sqrt", ExpressionOp::kSqrt, 1},
    {"abs", ExpressionOp::kAbs, 1},
    {"atan2", ExpressionOp::kAtan2, 2},
    {"min", ExpressionOp::kMin, 2},
    {"max", ExpressionOp::kMax, 2},
    {"pow", ExpressionOp::kPower, 2},
}};

const char* variable_name(ExpressionVariable v) {
  switch (v) {
    case ExpressionVariable::kX:
      return "x";
    case ExpressionVariable::kY:
      return "y";
    case ExpressionVariable::kT:
      return "t";
  }
  return "?";
}

}  // namespace

class ExpressionParser {
 public:
  ExpressionParser(std::vector<Token> tokens, std::span<const ExpressionVariable> allowed,
                   const ExpressionLimits& limits)
      : tokens_(std::move(tokens)), allowed_(allowed), limits_(limits) {}

  Result<Expression> parse() {
    if (!expression(0)) return error_;
    if (peek().kind != TokenKind::kEnd) {
      fail(peek().column, peek().text == ")"
                              ? "unmatched ')'"
                              : "expected an operator, found '" + std::string(peek().text) + "'");
      return error_;
    }
    Expression result;
    result.program_ = std::move(program_);
    result.stack_size_ = max_stack_;
    return result;
  }

 private:
  const Token& peek() const { return tokens_[position_]; }
  const Token& next() { return tokens_[position_ < tokens_.size() - 1 ? position_++ : position_]; }
  bool is_operator(const Token& token, char c) const {
    return token.kind == TokenKind::kOperator && token.text[0] == c;
  }

  bool fail(std::size_t column, const std::string& message, ErrorKind kind = ErrorKind::kInvalidArgument) {
    error_ = Error{kind, column_prefix(column) + message};
    return false;
  }

  bool enter(int depth, std::size_t column) {
    if (depth >= limits_.max_depth) {
      return fail(column, "the expression nests deeper than " + std::to_string(limits_.max_depth) + " levels",
                  ErrorKind::kLimitExceeded);
    }
    return true;
  }

  // Appends one node; `pops` operands are consumed and one value pushed.
  bool emit(ExpressionOp op, double constant, int pops, std::size_t column) {
    if (program_.size() >= limits_.max_nodes) {
      return fail(column, "the expression has more than " + std::to_string(limits_.max_nodes) + " terms",
                  ErrorKind::kLimitExceeded);
    }
    program_.push_back({op, constant});
    stack_ = stack_ - static_cast<std::size_t>(pops) + 1;
    max_stack_ = std::max(max_stack_, stack_);
    return true;
  }

  bool expression(int depth) {
    if (!enter(depth, peek().column) || !term(depth)) return false;
    while (is_operator(peek(), '+') || is_operator(peek(), '-')) {
      const Token& op = next();
      if (!term(depth)) return false;
      if (!emit(op.text[0] == '+' ? ExpressionOp::kAdd : ExpressionOp::kSubtract, 0, 2, op.column))
        return false;
    }
    return true;
  }

  bool term(int depth) {
    if (!unary(depth)) return false;
    while (is_operator(peek(), '*') || is_operator(peek(), '/')) {
      const Token& op = next();
      if (!unary(depth)) return false;
      if (!emit(op.text[0] == '*' ? ExpressionOp::kMultiply : ExpressionOp::kDivide, 0, 2, op.column))
        return false;
    }
    return true;
  }

  bool unary(int depth) {
    if (!enter(depth, peek().column)) return false;
    if (is_operator(peek(), '-') || is_operator(peek(), '+')) {
      const Token& op = next();
      if (!unary(depth + 1)) return false;
      return op.text[0] == '+' || emit(ExpressionOp::kNegate, 0, 1, op.column);
    }
    return power(depth);
  }

  bool power(int depth) {
    if (!primary(depth)) return false;
    if (is_operator(peek(), '^')) {
      const Token& op = next();
      if (!unary(depth + 1)) return false;
      return emit(ExpressionOp::kPower, 0, 2, op.column);
    }
    return true;
  }

  bool primary(int depth) {
    const Token& token = next();
    switch (token.kind) {
      case TokenKind::kNumber:
        return emit(ExpressionOp::kConstant, token.number, 0, token.column);
      case TokenKind::kName:
        return name(token, depth);
      case TokenKind::kEnd:
        return fail(token.column, "the expression ends where a number, name or '(' was expected");
      case TokenKind::kOperator:
        break;
    }
    if (is_operator(token, '(')) {
      if (!expression(depth + 1)) return false;
      if (!is_operator(peek(), ')')) {
        return fail(peek().column, "expected ')' to close the '(' at column " + std::to_string(token.column));
      }
      next();
      return true;
    }
    return fail(token.column, "expected a number, name or '(', found '" + std::string(token.text) + "'");
  }

  bool name(const Token& token, int depth) {
    const std::string_view text = token.text;
    if (is_operator(peek(), '(')) {
      const auto function = std::find_if(kFunctions.begin(), kFunctions.end(),
                                         [&](const FunctionName& f) { return f.name == text; });
      if (function == kFunctions.end()) {
        return fail(token.column,
                    "unknown function '" + std::string(text) +
                        "' (known: sin cos tan asin acos atan atan2 exp log sqrt abs min max pow)");
      }
      const Token& open = next();
      for (int i = 0; i < function->arity; ++i) {
        if (i > 0) {
          if (!is_operator(peek(), ',')) {
            return fail(peek().column,
                        std::string(text) + " takes " + std::to_string(function->arity) + " arguments");
          }
          next();
        }
        if (!expression(depth + 1)) return false;
      }
      if (!is_operator(peek(), ')')) {
        return fail(peek().column,
                    is_operator(peek(), ',')
                        ? std::string(text) + " takes " + std::to_string(function->arity) +
                              (function->arity == 1 ? " argument" : " arguments")
                        : "expected ')' to close the '(' at column " + std::to_string(open.column));
      }
      next();
      return emit(function->op, 0, function->arity, token.column);
    }
    if (text == "pi") return emit(ExpressionOp::kConstant, std::numbers::pi, 0, token.column);
    if (text == "e") return emit(ExpressionOp::kConstant, std::numbers::e, 0, token.column);
    const ExpressionVariable variables[] = {ExpressionVariable::kX, ExpressionVariable::kY,
                                            ExpressionVariable::kT};
    const ExpressionOp ops[] = {ExpressionOp::kX, ExpressionOp::kY, ExpressionOp::kT};
    for (int i = 0; i < 3; ++i) {
      if (text != variable_name(variables[i])) continue;
      if (std::find(allowed_.begin(), allowed_.end(), variables[i]) == allowed_.end()) break;
      return emit(ops[i], 0, 0, token.column);
    }
    std::string known;
    for (const ExpressionVariable v : allowed_)
      known += std::string(known.empty() ? "" : ", ") + variable_name(v);
    const bool is_function = std::any_of(kFunctions.begin(), kFunctions.end(),
                                         [&](const FunctionName& f) { return f.name == text; });
    if (is_function)
      return fail(token.column, "the function '" + std::string(text) + "' needs '(' and its arguments");
    return fail(token.column, "unknown name '" + std::string(text) + "' (this expression may use " +
                                  (known.empty() ? std::string("no variables") : known) + ", pi and e)");
  }

  std::vector<Token> tokens_;
  std::size_t position_ = 0;
  std::span<const ExpressionVariable> allowed_;
  ExpressionLimits limits_;
  std::vector<ExpressionNode> program_;
  std::size_t stack_ = 0;
  std::size_t max_stack_ = 0;
  Error error_;
};

Result<Expression> Expression::parse(std::string_view text, std::span<const ExpressionVariable> allowed,
                                     const ExpressionLimits& limits) {
  if (text.size() > limits.max_length) {
    return Error{ErrorKind::kLimitExceeded, "the expression is " + std::to_string(text.size()) +
                                                " characters long, more than the limit of " +
                                                std::to_string(limits.max_length)};
  }
  Result<std::vector<Token>> tokens = detail::tokenize_expression(text);
  if (!tokens) return tokens.error();
  return ExpressionParser(std::move(*tokens), allowed, limits).parse();
}

bool Expression::uses(ExpressionVariable variable) const noexcept {
  const ExpressionOp op = variable == ExpressionVariable::kX   ? ExpressionOp::kX
                          : variable == ExpressionVariable::kY ? ExpressionOp::kY
                                                               : ExpressionOp::kT;
  return std::any_of(program_.begin(), program_.end(), [op](const ExpressionNode& n) { return n.op == op; });
}

}  // namespace curvescan
