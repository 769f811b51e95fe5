// Splitting an expression into tokens (expression_tokenizer.h).
#include "expression_tokenizer.h"

#include <cctype>
#include <charconv>
#include <cmath>

namespace curvescan::detail {

std::string column_prefix(std::size_t column) {
  return "column " + std::to_string(column) + ": ";
}

namespace {

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}
bool is_name_start(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
}
bool is_name_char(char c) {
  return is_name_start(c) || is_digit(c);
}

// The length of the number at the start of `text`: digits, an optional fraction, an optional exponent
// (e or E, an optional sign, at least one digit). 0 if it is not a number.
std::size_t number_length(std::string_view text) {
  std::size_t i = 0;
  std::size_t digits = 0;
  while (i < text.size() && is_digit(text[i])) ++i, ++digits;
  if (i < text.size() && text[i] == '.') {
    ++i;
    while (i < text.size() && is_digit(text[i])) ++i, ++digits;
  }
  if (digits == 0) return 0;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
    if (j < text.size() && is_digit(text[j])) {
      while (j < text.size() && is_digit(text[j])) ++j;
      i = j;
    }
  }
  return i;
}

}  // namespace

Result<std::vector<Token>> tokenize_expression(std::string_view text) {
  std::vector<Token> tokens;
  std::size_t i = 0;
  while (i < text.size()) {
    const char c = text[i];
    const std::size_t column = i + 1;
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      ++i;
      continue;
    }
    if (is_digit(c) || c == '.') {
      const std::size_t length = number_length(text.substr(i));
      if (length == 0)
        return Error{ErrorKind::kInvalidArgument, column_prefix(column) + "'.' is not a number"};
      Token token{TokenKind::kNumber, text.substr(i, length), 0.0, column};
      // from_chars takes no leading '.', so parse "0" + text for ".5".
      const std::string digits = (c == '.' ? "0" : "") + std::string(token.text);
      const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), token.number);
      if (error == std::errc::result_out_of_range) {
        return Error{
            ErrorKind::kInvalidArgument,
            column_prefix(column) + "the number " + std::string(token.text) + " is out of the double range"};
      }
      if (error != std::errc() || end != digits.data() + digits.size()) {
        return Error{ErrorKind::kInvalidArgument,
                     column_prefix(column) + "malformed number " + std::string(token.text)};
      }
      tokens.push_back(token);
      i += length;
      if (i < text.size() && (is_name_start(text[i]) || text[i] == '.')) {
        return Error{ErrorKind::kInvalidArgument, column_prefix(i + 1) +
                                                      "expected an operator after the number " +
                                                      std::string(token.text) + " (write 2*x, not 2x)"};
      }
      continue;
    }
    if (is_name_start(c)) {
      std::size_t j = i;
      while (j < text.size() && is_name_char(text[j])) ++j;
      tokens.push_back({TokenKind::kName, text.substr(i, j - i), 0.0, column});
      i = j;
      continue;
    }
    if (c == '+' || c == '-' || c == '*' || c == '/' || c == '^' || c == '(' || c == ')' || c == ',') {
      tokens.push_back({TokenKind::kOperator, text.substr(i, 1), 0.0, column});
      ++i;
      continue;
    }
    const unsigned char byte = static_cast<unsigned char>(c);
    const std::string shown = byte >= 0x20 && byte < 0x7f ? "'" + std::string(1, c) + "'"
                                                          : "byte " + std::to_string(static_cast<int>(byte));
    return Error{ErrorKind::kInvalidArgument,
                 column_prefix(column) + "unexpected " + shown +
                     (byte >= 0x80 ? " (expressions are ASCII: write - for minus, * for times)" : "")};
  }
  tokens.push_back({TokenKind::kEnd, text.substr(text.size()), 0.0, text.size() + 1});
  return tokens;
}

}  // namespace curvescan::detail
