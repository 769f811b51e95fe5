// The tokens of an expression (expression.h): numbers, names, the operators + - * / ^, parentheses and
// commas. Whitespace separates tokens and is otherwise ignored.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/status.h"

namespace curvescan::detail {

enum class TokenKind : unsigned char { kNumber, kName, kOperator, kEnd };

struct Token {
  TokenKind kind = TokenKind::kEnd;
  std::string_view text;   ///< the characters of the token (a view into the expression)
  double number = 0.0;     ///< the value of a kNumber
  std::size_t column = 0;  ///< 1-based position of the first character
};

/// The tokens of `text`, ending with one kEnd token. Errors name the column of the offending character.
Result<std::vector<Token>> tokenize_expression(std::string_view text);

/// "column N: " for error messages.
std::string column_prefix(std::size_t column);

}  // namespace curvescan::detail
