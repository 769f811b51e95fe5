// SVG number lexing (number.h): the extent of a number is found by the SVG 1.1 grammar, then converted by
// std::from_chars, which rounds correctly and reports overflow.
#include "curvescan/svg/number.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <system_error>

namespace curvescan::svg {
namespace {

constexpr bool is_digit(char c) noexcept {
  return c >= '0' && c <= '9';
}

// Length of the run of digits at text[from...].
std::size_t digit_run(std::string_view text, std::size_t from) noexcept {
  std::size_t end = from;
  while (end < text.size() && is_digit(text[end])) ++end;
  return end - from;
}

}  // namespace

void skip_whitespace(std::string_view& text) noexcept {
  std::size_t i = 0;
  while (i < text.size() && is_svg_whitespace(text[i])) ++i;
  text.remove_prefix(i);
}

bool skip_comma_whitespace(std::string_view& text) noexcept {
  skip_whitespace(text);
  if (text.empty() || text.front() != ',') return false;
  text.remove_prefix(1);
  skip_whitespace(text);
  return true;
}

std::string_view trim_whitespace(std::string_view text) noexcept {
  skip_whitespace(text);
  while (!text.empty() && is_svg_whitespace(text.back())) text.remove_suffix(1);
  return text;
}

std::optional<double> consume_number(std::string_view& text) noexcept {
  std::size_t i = 0;
  bool negative = false;
  if (i < text.size() && (text[i] == '+' || text[i] == '-')) {
    negative = text[i] == '-';
    ++i;
  }
  const std::size_t mantissa_start = i;
  const std::size_t integer_digits = digit_run(text, i);
  i += integer_digits;
  std::size_t fraction_digits = 0;
  if (i < text.size() && text[i] == '.') {
    fraction_digits = digit_run(text, i + 1);
    // "1." is a number (digits "." digits?), "." alone is not.
    if (integer_digits > 0 || fraction_digits > 0) i += 1 + fraction_digits;
  }
  if (integer_digits == 0 && fraction_digits == 0) return std::nullopt;
  if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
    std::size_t j = i + 1;
    if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
    const std::size_t exponent_digits = digit_run(text, j);
    if (exponent_digits > 0) i = j + exponent_digits;  // else the "e" belongs to what follows (a unit)
  }
  // from_chars takes no leading '+'; the sign is applied afterwards (exact: negation is exact).
  double magnitude = 0.0;
  const char* first = text.data() + mantissa_start;
  const char* last = text.data() + i;
  const auto [end, error] = std::from_chars(first, last, magnitude, std::chars_format::general);
  if (error != std::errc() || end != last || !std::isfinite(magnitude)) return std::nullopt;
  text.remove_prefix(i);
  return negative ? -magnitude : magnitude;
}

std::optional<double> parse_number(std::string_view text) noexcept {
  text = trim_whitespace(text);
  const std::optional<double> value = consume_number(text);
  if (!value || !text.empty()) return std::nullopt;
  return value;
}

NumberList parse_number_list(std::string_view text) {
  NumberList list;
  skip_whitespace(text);
  while (!text.empty()) {
    const std::optional<double> value = consume_number(text);
    if (!value) {
      list.complete = false;
      return list;
    }
    list.values.push_back(*value);
    // A trailing comma ("1,2,") is an error: a comma must be followed by another number.
    if (skip_comma_whitespace(text) && text.empty()) {
      list.complete = false;
      return list;
    }
  }
  return list;
}

}  // namespace curvescan::svg
