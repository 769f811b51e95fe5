// Font property parsers (text_font_properties.h).
#include "text_font_properties.h"

#include <array>
#include <utility>

#include "curvescan/svg/length.h"
#include "curvescan/svg/number.h"
#include "text_font_variants.h"

namespace curvescan::svg::detail {

std::optional<int> parse_font_weight(std::string_view value, int parent_weight) noexcept {
  value = trim_whitespace(value);
  if (value == "normal") return 400;
  if (value == "bold") return 700;
  // CSS Fonts 4 2.2.1, "Meaning of Relative Weights".
  if (value == "bolder") {
    if (parent_weight < 350) return 400;
    if (parent_weight < 550) return 700;
    if (parent_weight < 900) return 900;
    return parent_weight;
  }
  if (value == "lighter") {
    if (parent_weight < 100) return parent_weight;
    if (parent_weight < 550) return 100;
    if (parent_weight < 750) return 400;
    return 700;
  }
  const std::optional<double> number = parse_number(value);
  if (!number || !(*number >= 1.0 && *number <= 1000.0)) return std::nullopt;
  return static_cast<int>(*number + 0.5);
}

std::optional<bool> parse_font_style_italic(std::string_view value) noexcept {
  value = trim_whitespace(value);
  if (value == "normal") return false;
  if (value == "italic" || font_style_oblique_angle(value)) return true;
  return std::nullopt;
}

std::optional<TextAnchor> parse_text_anchor(std::string_view value) noexcept {
  value = trim_whitespace(value);
  if (value == "start") return TextAnchor::kStart;
  if (value == "middle") return TextAnchor::kMiddle;
  if (value == "end") return TextAnchor::kEnd;
  return std::nullopt;
}

std::optional<double> font_size_keyword(std::string_view value, double parent_size) noexcept {
  value = trim_whitespace(value);
  constexpr std::array<std::pair<std::string_view, double>, 7> kAbsolute{{{"xx-small", 3.0 / 5.0},
                                                                          {"x-small", 3.0 / 4.0},
                                                                          {"small", 8.0 / 9.0},
                                                                          {"medium", 1.0},
                                                                          {"large", 6.0 / 5.0},
                                                                          {"x-large", 3.0 / 2.0},
                                                                          {"xx-large", 2.0}}};
  for (const auto& [name, factor] : kAbsolute) {
    if (value == name) return kMediumFontSize * factor;
  }
  if (value == "larger") return parent_size * 1.2;
  if (value == "smaller") return parent_size / 1.2;
  return std::nullopt;
}

std::optional<std::string> parse_font_family(std::string_view value) {
  value = trim_whitespace(value);
  if (value.empty()) return std::nullopt;
  std::string_view rest = value;
  while (true) {
    const std::size_t comma = rest.find(',');
    if (trim_whitespace(rest.substr(0, comma)).empty()) return std::nullopt;
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  return std::string(value);
}

std::optional<FontShorthand> parse_font_shorthand(std::string_view value, int parent_weight) {
  std::string_view rest = trim_whitespace(value);
  FontShorthand font;
  // Up to four of style, variant, weight, stretch (any order), then the size, which must parse as a
  // length, a percentage or a size keyword.
  for (int token_count = 0; token_count < 5; ++token_count) {
    std::size_t end = 0;
    while (end < rest.size() && !is_svg_whitespace(rest[end])) ++end;
    const std::string_view token = rest.substr(0, end);
    if (token.empty()) return std::nullopt;
    const std::string_view size_part = token.substr(0, token.find('/'));
    if (font_size_keyword(size_part, kMediumFontSize) || parse_length(size_part).is_ok()) {
      const bool is_number_only = parse_number(size_part).has_value();
      // A bare number before the size is a weight ("700 12px"); a bare number as the size is not valid
      // CSS (it needs a unit), except 0.
      if (!is_number_only || *parse_number(size_part) == 0.0) {
        font.size = std::string(size_part);
        rest = trim_whitespace(rest.substr(end));
        if (rest.empty()) return std::nullopt;
        if (!parse_font_family(rest)) return std::nullopt;
        font.family = std::string(rest);
        return font;
      }
    }
    if (token == "normal") {
      // normal resets whichever of the four it stands for.
    } else if (token == "small-caps") {
      font.small_caps = true;
    } else if (const std::optional<double> stretch = parse_font_stretch(token); stretch && token.back() != '%') {
      font.stretch = *stretch;
    } else if (const std::optional<bool> italic = parse_font_style_italic(token)) {
      font.italic = *italic;
    } else if (const std::optional<int> weight = parse_font_weight(token, parent_weight)) {
      font.weight = *weight;
    } else {
      return std::nullopt;
    }
    rest = trim_whitespace(rest.substr(end));
  }
  return std::nullopt;
}

}  // namespace curvescan::svg::detail
