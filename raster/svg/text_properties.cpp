// Text layout properties (text_properties.h).
#include "text_properties.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "computed_style.h"
#include "curvescan/svg/number.h"

namespace curvescan::svg::detail {
namespace {

constexpr std::array<std::string_view, 13> kTextProperties{
    "direction",         "unicode-bidi",         "letter-spacing",   "word-spacing",
    "dominant-baseline", "alignment-baseline",   "baseline-shift",   "text-decoration",
    "writing-mode",      "text-decoration-line", "text-orientation", "glyph-orientation-vertical",
    "text-rendering"};

std::optional<Baseline> parse_baseline(std::string_view value, bool alignment) {
  if (value == "auto") return Baseline::kAuto;
  if (alignment && value == "baseline") return Baseline::kAuto;
  if (value == "alphabetic") return Baseline::kAlphabetic;
  if (value == "middle") return Baseline::kMiddle;
  if (value == "central") return Baseline::kCentral;
  if (value == "hanging") return Baseline::kHanging;
  if (value == "mathematical") return Baseline::kMathematical;
  if (value == "text-before-edge" || value == "text-top" || value == "before-edge")
    return Baseline::kTextBeforeEdge;
  if (value == "text-after-edge" || value == "text-bottom" || value == "after-edge")
    return Baseline::kTextAfterEdge;
  if (value == "ideographic") return Baseline::kIdeographic;
  // SVG 1.1's use-script (dominant-baseline) picks the alphabetic baseline for Latin text, the only
  // script whose baseline table is not read here (no-change and reset-size: apply_text_property).
  if (!alignment && value == "use-script") return Baseline::kAuto;
  return std::nullopt;
}

// "normal" -> nullopt inside the optional; a <length-percentage> (CSS Text 4, the letter-spacing and
// word-spacing property definitions: a percentage of letter-spacing and of word-spacing is relative to the
// computed font-size, so 10% is 0.1em; the percentage itself is inherited, as an em is here, and resolved
// against each element's own font size at layout, text_layout_job.h). CSS Text 3 and SVG 2 allowed lengths
// only, SVG 1.1 left the percentage's reference undefined; WebKit (Safari) and Chrome 145 implement CSS Text
// 4's.
std::optional<std::optional<Length>> parse_spacing(std::string_view value) {
  if (value == "normal") return std::optional<Length>();
  const Result<Length> length = parse_length(value);
  if (!length || !std::isfinite(length->value)) return std::nullopt;
  return std::optional<Length>(*length);
}

// text-decoration (SVG 1.1 10.12, CSS 2.1 16.3.1): none | [underline || overline || line-through || blink].
std::optional<TextDecoration> parse_decoration(std::string_view value) {
  TextDecoration decoration;
  if (value == "none") return decoration;
  bool any = false;
  while (!value.empty()) {
    const std::size_t end = std::min(value.find_first_of(" \t\r\n"), value.size());
    const std::string_view word = value.substr(0, end);
    value.remove_prefix(end);
    value = trim_whitespace(value);
    if (word == "underline") {
      decoration.underline = true;
    } else if (word == "overline") {
      decoration.overline = true;
    } else if (word == "line-through") {
      decoration.line_through = true;
    } else if (word != "blink") {  // blink: user agents may not blink (CSS 2.1 16.3.1)
      return std::nullopt;
    }
    any = true;
  }
  if (!any) return std::nullopt;
  return decoration;
}

}  // namespace

void reset_non_inherited(TextProperties& properties) noexcept {
  properties.unicode_bidi = UnicodeBidi::kNormal;
  properties.alignment_baseline = Baseline::kAuto;
  properties.baseline_shift = BaselineShift{};
  // The parent's own decoration joins those of its ancestors before it is reset for the child.
  properties.ancestor_decoration.underline |= properties.decoration.underline;
  properties.ancestor_decoration.overline |= properties.decoration.overline;
  properties.ancestor_decoration.line_through |= properties.decoration.line_through;
  properties.decoration = TextDecoration{};
}

bool is_text_property(std::string_view name) noexcept {
  return std::find(kTextProperties.begin(), kTextProperties.end(), name) != kTextProperties.end() ||
         is_font_variant_property(name);
}

bool apply_text_property(TextProperties& style, const TextProperties& parent, std::string_view name,
                         std::string_view value) {
  const bool inherit = value == "inherit";
  if (is_font_variant_property(name)) return apply_font_variant_property(style.font_variants, parent.font_variants, name, value);
  if (name == "direction") {
    if (inherit) {
      style.right_to_left = parent.right_to_left;
    } else if (value == "ltr" || value == "rtl") {
      style.right_to_left = value == "rtl";
    } else {
      return false;
    }
  } else if (name == "unicode-bidi") {
    if (inherit) {
      style.unicode_bidi = parent.unicode_bidi;
    } else if (value == "normal") {
      style.unicode_bidi = UnicodeBidi::kNormal;
    } else if (value == "embed") {
      style.unicode_bidi = UnicodeBidi::kEmbed;
    } else if (value == "isolate") {
      style.unicode_bidi = UnicodeBidi::kIsolate;
    } else if (value == "bidi-override") {
      style.unicode_bidi = UnicodeBidi::kBidiOverride;
    } else if (value == "isolate-override") {
      style.unicode_bidi = UnicodeBidi::kIsolateOverride;
    } else if (value == "plaintext") {
      style.unicode_bidi = UnicodeBidi::kPlaintext;
    } else {
      return false;
    }
  } else if (name == "letter-spacing" || name == "word-spacing") {
    std::optional<Length>& target = name == "letter-spacing" ? style.letter_spacing : style.word_spacing;
    if (inherit) {
      target = name == "letter-spacing" ? parent.letter_spacing : parent.word_spacing;
    } else if (const std::optional<std::optional<Length>> spacing = parse_spacing(value)) {
      target = *spacing;
    } else {
      return false;
    }
  } else if (name == "dominant-baseline" || name == "alignment-baseline") {
    const bool alignment = name == "alignment-baseline";
    Baseline& target = alignment ? style.alignment_baseline : style.dominant_baseline;
    if (inherit) {
      target = alignment ? parent.alignment_baseline : parent.dominant_baseline;
    } else if (!alignment && (value == "no-change" || value == "reset-size")) {
      // SVG 1.1 10.9.2: no-change keeps the parent's dominant baseline and baseline table; reset-size
      // keeps the baseline and rescales the table to the element's own font-size, which the baseline
      // heights here always are (they are computed from each element's font at layout).
      target = parent.dominant_baseline;
    } else if (const std::optional<Baseline> baseline = parse_baseline(value, alignment)) {
      target = *baseline;
    } else {
      return false;
    }
  } else if (name == "baseline-shift") {
    if (inherit) {
      style.baseline_shift = parent.baseline_shift;
    } else if (value == "baseline") {
      style.baseline_shift = BaselineShift{};
    } else if (value == "sub" || value == "super") {
      style.baseline_shift = {value == "sub" ? BaselineShift::Kind::kSub : BaselineShift::Kind::kSuper,
                              Length{}};
    } else if (const Result<Length> length = parse_length(value); length && std::isfinite(length->value)) {
      style.baseline_shift = {BaselineShift::Kind::kLength, *length};
    } else {
      return false;
    }
  } else if (name == "text-decoration" || name == "text-decoration-line") {
    if (inherit) {
      style.decoration = parent.decoration;
    } else if (const std::optional<TextDecoration> decoration = parse_decoration(value)) {
      style.decoration = *decoration;
    } else {
      return false;
    }
  } else if (name == "text-rendering") {
    // SVG 1.1 10.8 (inherited; SVG 2 refers to CSS Fonts): optimizeSpeed lets speed win over legibility
    // and geometric precision, which the specification's own example is turning anti-aliasing off; the
    // other three keep exact coverage.
    if (inherit) {
      style.aliased = parent.aliased;
    } else if (value == "auto" || value == "optimizeLegibility" || value == "geometricPrecision" ||
               value == "optimizeSpeed") {
      style.aliased = value == "optimizeSpeed";
    } else {
      return false;
    }
  } else if (name == "text-orientation") {
    if (inherit) {
      style.orientation = parent.orientation;
    } else if (value == "mixed" || value == "upright" || value == "sideways" || value == "sideways-right") {
      // sideways-right: the CSS Writing Modes 3 draft's name for sideways.
      style.orientation = value == "mixed"     ? TextOrientation::kMixed
                          : value == "upright" ? TextOrientation::kUpright
                                               : TextOrientation::kSideways;
    } else {
      return false;
    }
  } else if (name == "glyph-orientation-vertical") {
    // SVG 1.1 10.7.3: auto, or an angle that is a multiple of 90 degrees; CSS Writing Modes 3 section 5.1.1
    // maps auto to mixed, 0deg to upright and 90deg to sideways. 180 and 270 are not supported.
    if (inherit) {
      style.orientation = parent.orientation;
    } else if (value == "auto") {
      style.orientation = TextOrientation::kMixed;
    } else if (value == "0" || value == "0deg") {
      style.orientation = TextOrientation::kUpright;
    } else if (value == "90" || value == "90deg") {
      style.orientation = TextOrientation::kSideways;
    } else {
      return false;
    }
  } else if (name == "writing-mode") {
    // SVG 1.1 lr-tb, rl-tb, lr, rl, tb-rl, tb; CSS horizontal-tb, vertical-rl, vertical-lr, sideways-*.
    // A single <text> line has no block direction, so rl and lr differ only between lines: tb = tb-rl
    // = vertical-rl = vertical-lr here.
    if (inherit) {
      style.vertical = parent.vertical;
      style.sideways = parent.sideways;
      style.bottom_to_top = parent.bottom_to_top;
    } else if (value == "lr-tb" || value == "rl-tb" || value == "lr" || value == "rl" ||
               value == "horizontal-tb") {
      style.vertical = style.sideways = style.bottom_to_top = false;
    } else if (value == "tb" || value == "tb-rl" || value == "vertical-rl" || value == "vertical-lr") {
      style.vertical = true;
      style.sideways = style.bottom_to_top = false;
    } else if (value == "sideways-rl" || value == "sideways-lr") {
      style.vertical = style.sideways = true;
      style.bottom_to_top = value == "sideways-lr";
    } else {
      return false;
    }
  }
  return true;
}

}  // namespace curvescan::svg::detail
