// The font properties of the cascade (CSS 2.1 chapter 15 "Fonts", CSS Fonts 3/4, SVG 1.1 10.10 "Font
// selection properties") and text-anchor (SVG 1.1 10.9.1): parsers that refuse what the grammar does not
// allow, so that computed_style.cpp can ignore an invalid declaration (CSS 2.1 4.2).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "curvescan/text/text_layout.h"

namespace curvescan::svg::detail {

/// The initial font-size (CSS 2.1 15.7: "medium" is the user agent's default) in px: 16, as browsers.
/// rsvg-convert uses 12 (docs/svg.md).
inline constexpr double kMediumFontSize = 16.0;

/// font-weight (CSS Fonts 4 section 2.2): normal = 400, bold = 700, a number in [1, 1000], or bolder /
/// lighter relative to `parent_weight` (the table of CSS Fonts 4 2.2.1). nullopt for anything else.
[[nodiscard]] std::optional<int> parse_font_weight(std::string_view value, int parent_weight) noexcept;

/// font-style: normal -> false, italic and oblique [<angle>] -> true (fontconfig picks an oblique face for an
/// italic request when the family has no italic). nullopt for anything else.
[[nodiscard]] std::optional<bool> parse_font_style_italic(std::string_view value) noexcept;

/// text-anchor: start, middle, end.
[[nodiscard]] std::optional<TextAnchor> parse_text_anchor(std::string_view value) noexcept;

/// The font-size keywords (CSS Fonts 3 section 3.5, table "absolute-size"): xx-small 3/5, x-small 3/4,
/// small 8/9, medium 1, large 6/5, x-large 3/2, xx-large 2 times kMediumFontSize; larger and smaller
/// scale the parent's size by 1.2 (CSS 2.1 15.7 suggests 1.2 between adjacent sizes). nullopt when
/// `value` is not a keyword.
[[nodiscard]] std::optional<double> font_size_keyword(std::string_view value, double parent_size) noexcept;

/// A font-family list, trimmed; nullopt when it is empty or a name is empty ("A,,B", "A,").
[[nodiscard]] std::optional<std::string> parse_font_family(std::string_view value);

/// The `font` shorthand (CSS 2.1 15.8, CSS Fonts 4 2.8): [style || small-caps || weight || stretch]? size
/// [/ line-height]? family. Parts the shorthand omits reset to their initial values (normal style,
/// weight 400, no small capitals, normal width; the caller resets the other font-variant longhands,
/// font-feature-settings and font-kerning too). System fonts
/// (caption, icon, ...) are not supported and give nullopt; so does a missing size or family.
struct FontShorthand {
  bool italic = false;
  int weight = 400;
  bool small_caps = false;
  double stretch = 100.0;  ///< percent: the font-stretch keywords only (CSS Fonts 4 2.8)
  std::string size;  ///< the font-size token, for the font-size parser
  std::string family;
};
[[nodiscard]] std::optional<FontShorthand> parse_font_shorthand(std::string_view value, int parent_weight);

}  // namespace curvescan::svg::detail
