// The root <svg>'s background-color as the canvas background (canvas_background.h).
#include "canvas_background.h"

#include <string>
#include <string_view>

#include "cascade.h"
#include "css/syntax.h"
#include "curvescan/svg/color.h"

namespace curvescan::svg::detail {

namespace {

std::string_view trimmed(std::string_view text) {
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f'; };
  while (!text.empty() && space(text.front())) text.remove_prefix(1);
  while (!text.empty() && space(text.back())) text.remove_suffix(1);
  return text;
}

bool is_keyword(std::string_view text, std::string_view keyword) {
  return css::ascii_equal_ignoring_case(text, keyword);
}

bool is_css_wide_keyword(std::string_view text) {
  return is_keyword(text, "inherit") || is_keyword(text, "initial") || is_keyword(text, "unset") ||
         is_keyword(text, "revert");
}

bool valid_background_color(std::string_view text) {
  text = trimmed(text);
  return is_keyword(text, "currentcolor") || is_css_wide_keyword(text) || parse_color(text).is_ok();
}

}  // namespace

std::optional<Color> canvas_background_color(const pugi::xml_node& root, const css::StyleSheets* sheets,
                                             const Color& current_color) {
  // declared_value reads the style sheets and the style attribute only: background-color has no
  // presentation attribute.
  const std::optional<std::string> declared =
      declared_value(root, "background-color", sheets, valid_background_color);
  if (!declared) return std::nullopt;
  const std::string_view text = trimmed(*declared);
  // background-color is not inherited and the root has no parent: every CSS-wide keyword gives the
  // initial value, transparent.
  if (is_css_wide_keyword(text)) return std::nullopt;
  Color color = current_color;
  if (!is_keyword(text, "currentcolor")) {
    const Result<Color> parsed = parse_color(text);
    if (!parsed) return std::nullopt;  // unreachable: valid_background_color accepted it
    color = *parsed;
  }
  if (!(color.a > 0.0)) return std::nullopt;
  return color;
}

}  // namespace curvescan::svg::detail
