// The text layout properties of the cascade beside the font properties (text_font_properties.h):
// direction and unicode-bidi (CSS Writing Modes 3 section 2), letter-spacing and word-spacing (CSS Text 3
// sections 8.1-8.2; SVG 1.1 10.11), baseline-shift, dominant-baseline and alignment-baseline (SVG 1.1
// 10.9.2-10.9.3, CSS Inline 3), text-decoration (SVG 1.1 10.12) and writing-mode (SVG 1.1 10.7; CSS
// Writing Modes 3 section 3.1), white-space and xml:space (SVG 2 11.7), text-transform (CSS Text 3 2.1),
// and the font variants of text_font_variants.h. Lengths are kept as written and resolved at layout time
// against the element's font size (text_element.cpp).
#pragma once

#include <optional>
#include <string_view>

#include "curvescan/svg/length.h"
#include "text_font_variants.h"

namespace curvescan::svg::detail {

struct Diagnostics;  // computed_style.h

/// unicode-bidi (CSS Writing Modes 3 section 2.2): how an element's text takes part in the bidi algorithm.
enum class UnicodeBidi { kNormal, kEmbed, kIsolate, kBidiOverride, kIsolateOverride, kPlaintext };

/// The baselines of dominant-baseline and alignment-baseline (SVG 1.1 10.9.2, SVG 2 / CSS Inline 3).
/// kAuto: alignment-baseline "auto"/"baseline" (the parent's dominant baseline), dominant-baseline "auto"
/// (alphabetic for horizontal text).
enum class Baseline {
  kAuto,
  kAlphabetic,
  kMiddle,          ///< half the x-height above the alphabetic baseline
  kCentral,         ///< halfway between the ascender and the descender
  kHanging,         ///< Indic hanging baseline: 0.8 of the ascender (no BASE table read)
  kMathematical,    ///< 0.5 of the ascender
  kTextBeforeEdge,  ///< the ascender (text-top, before-edge)
  kTextAfterEdge,   ///< the descender (text-bottom, after-edge)
  kIdeographic,     ///< the descender
};

/// How the white space of an element's character data is processed: SVG 1.1's xml:space while no
/// white-space property is declared on the element or an ancestor (SVG 2 11.7, "Duplicate white-space
/// directives": where white-space is set, xml:space is ignored), else white-space's collapsing half
/// (CSS Text 3 section 3, the white-space-collapse longhand of CSS Text 4). The wrapping half of
/// white-space is moot: SVG text without inline-size does not wrap. text_whitespace.h applies it.
enum class WhiteSpace {
  kXmlDefault,   ///< xml:space="default", the initial state (SVG 1.1 10.15)
  kXmlPreserve,  ///< xml:space="preserve": SVG 2's UA sheet maps it to white-space-collapse: preserve-spaces
  kCollapse,     ///< normal, nowrap
  kPreserve,     ///< pre, pre-wrap, break-spaces
  kPreserveBreaks,  ///< pre-line
};

/// text-transform (CSS Text 3 section 2.1): one case transform, plus full-width and full-size-kana.
struct TextTransform {
  enum class Case { kNone, kCapitalize, kUppercase, kLowercase } case_transform = Case::kNone;
  bool full_width = false;
  bool full_size_kana = false;
  [[nodiscard]] bool any() const noexcept {
    return case_transform != Case::kNone || full_width || full_size_kana;
  }
};

/// text-orientation (CSS Writing Modes 3 section 5.1) of vertical text, and SVG 1.1's
/// glyph-orientation-vertical (10.7.3: auto is mixed, 0deg upright, 90deg sideways).
enum class TextOrientation { kMixed, kUpright, kSideways };

struct BaselineShift {
  enum class Kind { kBaseline, kSub, kSuper, kLength } kind = Kind::kBaseline;
  Length length;  ///< kLength: a length, or a percentage of the font size (SVG 1.1: "line-height")
};

struct TextDecoration {
  bool underline = false;
  bool overline = false;
  bool line_through = false;
  [[nodiscard]] bool any() const noexcept { return underline || overline || line_through; }
};

struct TextProperties {
  // Inherited.
  bool right_to_left = false;  ///< direction: rtl
  /// writing-mode tb, tb-rl, vertical-rl, vertical-lr: lines run top to bottom (text_element.cpp).
  bool vertical = false;
  /// writing-mode sideways-rl and sideways-lr (CSS Writing Modes 3 section 3.1): a vertical line whose
  /// glyphs are all set sideways, in horizontal typographic mode (alphabetic baseline); sideways-lr runs
  /// bottom to top with the glyphs' tops to the left.
  bool sideways = false;
  bool bottom_to_top = false;
  /// vertical-lr and sideways-lr: the block flow direction is left to right, so that the lines of forced
  /// line breaks stack rightwards (CSS Writing Modes 3 section 3.1); leftwards for the other vertical modes.
  bool lines_left_to_right = false;
  TextOrientation orientation = TextOrientation::kMixed;
  WhiteSpace white_space = WhiteSpace::kXmlDefault;
  /// tab-size (CSS Text 3 section 4.2): the distance between tab stops, `tab_size_spaces` times the
  /// advance of the space, or `tab_size_length` when set. It applies to block containers: a <text> uses its
  /// own value (a <tspan>'s is inherited and unused).
  double tab_size_spaces = 8.0;
  std::optional<Length> tab_size_length;
  TextTransform transform;
  /// text-rendering: optimizeSpeed. The <text>'s value draws all of its glyphs and decorations without
  /// anti-aliasing (a pixel in when its centre is), as shape-rendering crispEdges draws shapes; a
  /// <tspan>'s own value does not split the element's rendering (SVG 2 lists text-rendering for the
  /// <text> element, and resvg ignores it on a tspan too).
  bool aliased = false;
  std::optional<Length> letter_spacing;  ///< nullopt: normal
  std::optional<Length> word_spacing;    ///< nullopt: normal
  Baseline dominant_baseline = Baseline::kAuto;
  /// font-variant and its longhands, font-feature-settings, font-kerning, kerning, font-stretch.
  FontVariants font_variants;
  /// The decorations declared by the ancestors (a <g> around a <text>: CSS Text Decoration 3 2.1,
  /// decorations propagate to every in-flow descendant). Not a property: gathered by
  /// reset_non_inherited as the cascade descends. A <text> draws these as if it declared them itself.
  TextDecoration ancestor_decoration;
  // Not inherited.
  UnicodeBidi unicode_bidi = UnicodeBidi::kNormal;
  Baseline alignment_baseline = Baseline::kAuto;
  BaselineShift baseline_shift;
  /// The decoration this element declares (it is drawn over its descendants' text too, with this
  /// element's fill and stroke: SVG 1.1 10.12).
  TextDecoration decoration;
};

/// Resets the properties that are not inherited to their initial values.
void reset_non_inherited(TextProperties& properties) noexcept;

/// The appliers of the properties handled here that are not keyword sets, one per property, each a row of
/// the cascade's property table (computed_style.cpp, which also holds the keyword tables of direction,
/// unicode-bidi, text-rendering, text-orientation and glyph-orientation-vertical): `value` is trimmed,
/// `inherit` says it is "inherit" (`parent` serves it). Each returns false when the value is invalid (the
/// caller warns and ignores it).
namespace text {
using Applier = bool (*)(TextProperties& style, const TextProperties& parent, std::string_view value,
                         bool inherit);
bool letter_spacing(TextProperties&, const TextProperties&, std::string_view, bool);
bool word_spacing(TextProperties&, const TextProperties&, std::string_view, bool);
bool dominant_baseline(TextProperties&, const TextProperties&, std::string_view, bool);
bool alignment_baseline(TextProperties&, const TextProperties&, std::string_view, bool);
bool baseline_shift(TextProperties&, const TextProperties&, std::string_view, bool);
/// text-decoration, and text-decoration-line (CSS Text Decoration 3), read alike.
bool text_decoration(TextProperties&, const TextProperties&, std::string_view, bool);
bool writing_mode(TextProperties&, const TextProperties&, std::string_view, bool);
/// white-space (CSS Text 3 section 3; SVG 2 11.7): normal, pre, nowrap, pre-wrap, pre-line, break-spaces.
bool white_space(TextProperties&, const TextProperties&, std::string_view, bool);
/// xml:space (XML 1.0 2.10, SVG 1.1 10.15): an attribute, not a property (no `inherit`); it changes the
/// element's white space processing only while no white-space declaration is in effect (WhiteSpace).
bool xml_space(TextProperties&, const TextProperties&, std::string_view, bool);
/// tab-size (CSS Text 3 section 4.2): a non-negative <number> (of spaces) or <length>.
bool tab_size(TextProperties&, const TextProperties&, std::string_view, bool);
/// text-transform (CSS Text 3 section 2.1): none | [capitalize | uppercase | lowercase] || full-width ||
/// full-size-kana.
bool text_transform(TextProperties&, const TextProperties&, std::string_view, bool);
/// Whether `name` is a text property SVG 2 section 6.6 gives no presentation attribute (text-transform,
/// tab-size).
[[nodiscard]] bool is_css_only_text_property(std::string_view name) noexcept;
}  // namespace text

}  // namespace curvescan::svg::detail
