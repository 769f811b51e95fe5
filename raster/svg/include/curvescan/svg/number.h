// SVG numbers: the lexical layer shared by path data, lengths, transform lists and point lists.
//
// Grammar (SVG 1.1 section 8.3.9 "The grammar for path data", and the identical "number" of section 4.2):
//   number   ::= sign? (digits "." digits? | "." digits | digits) exponent?
//   exponent ::= ("e" | "E") sign? digits
//   wsp      ::= (#x20 | #x9 | #xD | #xA)
//   comma-wsp ::= (wsp+ ","? wsp*) | ("," wsp*)
// A number ends at the first character that cannot continue it, so "1.5.5" is two numbers (1.5 and .5)
// and "-1-2" is two numbers: the compact forms path data allows. An "e" not followed by an optional sign
// and a digit does not start an exponent, so "3em" is the number 3 followed by the unit "em".
#pragma once

#include <optional>
#include <string_view>
#include <vector>

namespace curvescan::svg {

/// True for the four XML whitespace characters (SVG "wsp").
[[nodiscard]] constexpr bool is_svg_whitespace(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

/// Removes leading wsp from `text`.
void skip_whitespace(std::string_view& text) noexcept;
/// Removes a leading comma-wsp (or just wsp) from `text`; true when a comma was removed.
bool skip_comma_whitespace(std::string_view& text) noexcept;
/// `text` without leading and trailing wsp.
[[nodiscard]] std::string_view trim_whitespace(std::string_view text) noexcept;

/// Consumes one number from the front of `text` (no leading whitespace skipped) and returns it. nullopt,
/// `text` unchanged, when `text` does not start with a number or the number is outside the range of a
/// finite double (e.g. "1e999"): SVG coordinates must be finite.
[[nodiscard]] std::optional<double> consume_number(std::string_view& text) noexcept;

/// The whole of `text` (surrounding wsp allowed) as one number, or nullopt.
[[nodiscard]] std::optional<double> parse_number(std::string_view text) noexcept;

/// Numbers separated by comma-wsp, as in `points`, `viewBox` and `stroke-dasharray`.
struct NumberList {
  std::vector<double> values;  ///< the numbers read before the end or the first error
  bool complete = true;        ///< false when something other than a number list was found
};
[[nodiscard]] NumberList parse_number_list(std::string_view text);

}  // namespace curvescan::svg
