// Text layout properties (text_properties.h).
#include "text_properties.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "computed_style.h"
#include "css/syntax.h"
#include "curvescan/svg/number.h"

namespace curvescan::svg::detail {
namespace {

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
  // script whose baseline table is not read here (no-change and reset-size: text::dominant_baseline).
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
  if (css::ascii_equal_ignoring_case(value, "none")) return decoration;
  bool any = false;
  while (!value.empty()) {
    const std::size_t end = std::min(value.find_first_of(" \t\r\n"), value.size());
    const std::string_view word = value.substr(0, end);
    value.remove_prefix(end);
    value = trim_whitespace(value);
    if (css::ascii_equal_ignoring_case(word, "underline")) {
      decoration.underline = true;
    } else if (css::ascii_equal_ignoring_case(word, "overline")) {
      decoration.overline = true;
    } else if (css::ascii_equal_ignoring_case(word, "line-through")) {
      decoration.line_through = true;
    } else if (!css::ascii_equal_ignoring_case(
                   word, "blink")) {  // blink: user agents may not blink (CSS 2.1 16.3.1)
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

namespace text {

namespace {

// One of letter-spacing and word-spacing.
bool set_spacing(std::optional<Length>& target, const std::optional<Length>& inherited,
                 std::string_view value, bool inherit) {
  if (inherit) {
    target = inherited;
  } else if (const std::optional<std::optional<Length>> spacing = parse_spacing(value)) {
    target = *spacing;
  } else {
    return false;
  }
  return true;
}

}  // namespace

bool letter_spacing(TextProperties& style, const TextProperties& parent, std::string_view value,
                    bool inherit) {
  return set_spacing(style.letter_spacing, parent.letter_spacing, value, inherit);
}

bool word_spacing(TextProperties& style, const TextProperties& parent, std::string_view value, bool inherit) {
  return set_spacing(style.word_spacing, parent.word_spacing, value, inherit);
}

bool dominant_baseline(TextProperties& style, const TextProperties& parent, std::string_view value,
                       bool inherit) {
  if (inherit || value == "no-change" || value == "reset-size") {
    // SVG 1.1 10.9.2: no-change keeps the parent's dominant baseline and baseline table; reset-size
    // keeps the baseline and rescales the table to the element's own font-size, which the baseline
    // heights here always are (they are computed from each element's font at layout).
    style.dominant_baseline = parent.dominant_baseline;
  } else if (const std::optional<Baseline> baseline = parse_baseline(value, false)) {
    style.dominant_baseline = *baseline;
  } else {
    return false;
  }
  return true;
}

bool alignment_baseline(TextProperties& style, const TextProperties& parent, std::string_view value,
                        bool inherit) {
  if (inherit) {
    style.alignment_baseline = parent.alignment_baseline;
  } else if (const std::optional<Baseline> baseline = parse_baseline(value, true)) {
    style.alignment_baseline = *baseline;
  } else {
    return false;
  }
  return true;
}

bool baseline_shift(TextProperties& style, const TextProperties& parent, std::string_view value,
                    bool inherit) {
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
  return true;
}

bool text_decoration(TextProperties& style, const TextProperties& parent, std::string_view value,
                     bool inherit) {
  if (inherit) {
    style.decoration = parent.decoration;
  } else if (const std::optional<TextDecoration> decoration = parse_decoration(value)) {
    style.decoration = *decoration;
  } else {
    return false;
  }
  return true;
}

bool writing_mode(TextProperties& style, const TextProperties& parent, std::string_view value, bool inherit) {
  // SVG 1.1 lr-tb, rl-tb, lr, rl, tb-rl, tb; CSS horizontal-tb, vertical-rl, vertical-lr, sideways-*.
  // rl and lr differ only in the direction lines stack in (forced line breaks of white-space): tb = tb-rl
  // = vertical-rl, and vertical-lr, along one line.
  if (inherit) {
    style.vertical = parent.vertical;
    style.sideways = parent.sideways;
    style.bottom_to_top = parent.bottom_to_top;
    style.lines_left_to_right = parent.lines_left_to_right;
    return true;
  }
  if (value == "lr-tb" || value == "rl-tb" || value == "lr" || value == "rl" || value == "horizontal-tb") {
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
  style.lines_left_to_right = value == "vertical-lr" || value == "sideways-lr";
  return true;
}

bool white_space(TextProperties& style, const TextProperties& parent, std::string_view value, bool inherit) {
  // CSS Text 3 section 3, the white-space table: normal and nowrap collapse spaces and segment breaks,
  // pre, pre-wrap and break-spaces preserve both, pre-line collapses spaces and preserves breaks (the
  // wrapping they differ in does not happen in SVG text without inline-size). Keywords in any ASCII case
  // (CSS Values 3 2.1).
  if (inherit) {
    style.white_space = parent.white_space;
    return true;
  }
  const std::string keyword = css::ascii_lower(value);
  if (keyword == "normal" || keyword == "nowrap") {
    style.white_space = WhiteSpace::kCollapse;
  } else if (keyword == "pre" || keyword == "pre-wrap" || keyword == "break-spaces") {
    style.white_space = WhiteSpace::kPreserve;
  } else if (keyword == "pre-line") {
    style.white_space = WhiteSpace::kPreserveBreaks;
  } else {
    return false;
  }
  return true;
}

bool xml_space(TextProperties& style, const TextProperties& /*parent*/, std::string_view value,
               bool inherit) {
  // Its values are its own (XML 1.0 2.10: exactly "default" or "preserve"); `inherit` is none of them.
  if (inherit || (value != "default" && value != "preserve")) return false;
  // SVG 2 11.7 "Duplicate white-space directives": once white-space is set (on this element, in any
  // order of its attributes, or inherited from an ancestor), xml:space is ignored.
  if (style.white_space == WhiteSpace::kXmlDefault || style.white_space == WhiteSpace::kXmlPreserve)
    style.white_space = value == "preserve" ? WhiteSpace::kXmlPreserve : WhiteSpace::kXmlDefault;
  return true;
}

bool tab_size(TextProperties& style, const TextProperties& parent, std::string_view value, bool inherit) {
  if (inherit) {
    style.tab_size_spaces = parent.tab_size_spaces;
    style.tab_size_length = parent.tab_size_length;
    return true;
  }
  // CSS Text 3 section 4.2: <number [0,inf]> | <length [0,inf]>; a number counts spaces. No percentage.
  if (const std::optional<double> spaces = parse_number(value)) {
    if (!std::isfinite(*spaces) || *spaces < 0.0) return false;
    style.tab_size_spaces = *spaces;
    style.tab_size_length.reset();
    return true;
  }
  const Result<Length> length = parse_length(value);
  if (!length || !std::isfinite(length->value) || length->value < 0.0 || length->unit == LengthUnit::kPercent)
    return false;
  style.tab_size_length = *length;
  return true;
}

bool text_transform(TextProperties& style, const TextProperties& parent, std::string_view value,
                    bool inherit) {
  if (inherit) {
    style.transform = parent.transform;
    return true;
  }
  TextTransform transform;
  if (css::ascii_equal_ignoring_case(value, "none")) {
    style.transform = transform;
    return true;
  }
  // Each of the three parts at most once, in any order (CSS Values 3 2.2, the || combinator).
  bool any = false;
  while (!value.empty()) {
    const std::size_t end = std::min(value.find_first_of(" \t\r\n\f"), value.size());
    const std::string word = css::ascii_lower(value.substr(0, end));
    value = trim_whitespace(value.substr(end));
    using Case = TextTransform::Case;
    const Case word_case = word == "capitalize"  ? Case::kCapitalize
                           : word == "uppercase" ? Case::kUppercase
                           : word == "lowercase" ? Case::kLowercase
                                                 : Case::kNone;
    if (word_case != Case::kNone) {
      if (transform.case_transform != Case::kNone) return false;
      transform.case_transform = word_case;
    } else if (word == "full-width") {
      if (transform.full_width) return false;
      transform.full_width = true;
    } else if (word == "full-size-kana") {
      if (transform.full_size_kana) return false;
      transform.full_size_kana = true;
    } else {
      return false;
    }
    any = true;
  }
  if (!any) return false;
  style.transform = transform;
  return true;
}

bool is_css_only_text_property(std::string_view name) noexcept {
  return name == "text-transform" || name == "tab-size";
}

}  // namespace text

}  // namespace curvescan::svg::detail
