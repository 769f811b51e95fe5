// The cascade (computed_style.h): one parser per property, each refusing what the property's grammar
// does not allow so that apply_property can ignore the declaration (CSS 2.1 4.2).
//
// The properties are one table, kPropertyTable, sorted by name: apply_property handles the CSS-wide
// keywords (initial, unset, revert, inherit) once, looks the name up and calls the row's applier, and
// warns when the applier refuses the value. To add a property, add its field to ComputedStyle (and its
// reset to inherit_style when it is not inherited) and one row to kPropertyTable, in name order: for a
// keyword property, keyword_property<&ComputedStyle::field, kTable> with a KeywordTable of keyword ->
// value pairs; otherwise a small named function taking a Declaration that copies the parent's value on
// `inherit`, sets the field from a valid value and returns false for an invalid one. The table's size
// is its array bound; is_style_property then knows the name as a presentation attribute too.
#include "computed_style.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <pugixml.hpp>
#include <utility>

#include "css/syntax.h"
#include "curvescan/svg/number.h"
#include "source_positions.h"
#include "text_font_properties.h"

namespace curvescan::svg::detail {
namespace {

std::optional<PaintSpec> parse_paint(std::string_view text) {
  text = trim_whitespace(text);
  PaintSpec paint;
  if (css::ascii_equal_ignoring_case(text, "none")) return paint;
  if (css::ascii_equal_ignoring_case(text, "currentColor")) {
    paint.kind = PaintSpec::Kind::kCurrentColor;
    return paint;
  }
  if (css::ascii_equal_ignoring_case(text, "context-fill") ||
      css::ascii_equal_ignoring_case(text, "context-stroke")) {
    paint.kind = css::ascii_equal_ignoring_case(text, "context-fill") ? PaintSpec::Kind::kContextFill
                                                                      : PaintSpec::Kind::kContextStroke;
    return paint;
  }
  if (css::ascii_equal_ignoring_case(text.substr(0, 4), "url(")) {
    const std::size_t close = text.find(')');
    if (close == std::string_view::npos) return std::nullopt;
    const std::optional<std::string> id = parse_url_reference(text.substr(0, close + 1));
    // A URL into another document ("url(other.svg#g)") is a valid paint (SVG 2 13.2: <url> [none | <color>])
    // whose reference this reader never resolves (no file is read on a document's behalf): an empty id,
    // which then paints the fallback or none, as a reference to nothing does.
    if (!id && !is_other_document_url(text.substr(0, close + 1))) return std::nullopt;
    paint.kind = PaintSpec::Kind::kUrl;
    paint.url_id = id.value_or(std::string());
    const std::string_view fallback = trim_whitespace(text.substr(close + 1));
    if (!fallback.empty()) {
      const std::optional<PaintSpec> fallback_paint = parse_paint(fallback);
      if (!fallback_paint || fallback_paint->kind == PaintSpec::Kind::kUrl ||
          fallback_paint->kind == PaintSpec::Kind::kContextFill || fallback_paint->kind == PaintSpec::Kind::kContextStroke) {
        return std::nullopt;
      }
      paint.fallback_kind = fallback_paint->kind;
      paint.fallback_color = fallback_paint->color;
    }
    return paint;
  }
  const Result<Color> color = parse_color(text);
  if (!color) return std::nullopt;
  paint.kind = PaintSpec::Kind::kColor;
  paint.color = *color;
  return paint;
}

// <alpha-value>: a number or a percentage, clamped to [0, 1] (CSS Color 4 / SVG 2).
std::optional<double> parse_alpha(std::string_view text) {
  std::string_view rest = trim_whitespace(text);
  const std::optional<double> value = consume_number(rest);
  if (!value) return std::nullopt;
  if (rest == "%") return std::clamp(*value / 100.0, 0.0, 1.0);
  if (!rest.empty()) return std::nullopt;
  return std::clamp(*value, 0.0, 1.0);
}

void warn_invalid(Diagnostics& diagnostics, std::string_view name, std::string_view value) {
  diagnostics.warnings.push_back(std::string(kInvalidValueWarning) + " '" + std::string(value) +
                                 "' of property '" + std::string(name) + "'");
}

// ---- The property table -------------------------------------------------------------------------
// One row per property (kPropertyTable, sorted by name). A row's applier gets the declaration with its
// value trimmed and `inherit` already recognised (the other CSS-wide keywords become `inherit` in
// apply_property), sets the property's field of ComputedStyle (from the parent's when `inherit`) and
// returns false when the value is invalid, so that apply_property warns once and leaves the style
// unchanged. Keyword properties are data: a list of keyword -> value pairs and the field they set
// (keyword_property); the others are the small named functions below.

struct Declaration {
  ComputedStyle& style;
  const ComputedStyle& parent;
  std::string_view name;
  std::string_view value;  ///< trimmed
  bool inherit;            ///< value is "inherit"
  const ResolveContext& context;
  Diagnostics& diagnostics;
};

using Applier = bool (*)(const Declaration&);

template <typename T, std::size_t N>
using KeywordTable = std::array<std::pair<std::string_view, T>, N>;

// A property whose values are keywords: `inherit` copies the parent's `Field`, a keyword of `kKeywords`
// sets its value, anything else is invalid. Keywords match whatever their ASCII case (CSS Values 3, 2.1:
// "all CSS keywords are ASCII case-insensitive"), in presentation attributes as in style sheets, since SVG 2
// parses a presentation attribute with its property's CSS grammar, case-insensitively (SVG 2, 4.2).
template <auto Field, const auto& kKeywords, typename Part>
bool set_keyword(Part& style, const Part& parent, const Declaration& d) {
  if (d.inherit) {
    style.*Field = parent.*Field;
    return true;
  }
  for (const auto& [keyword, value] : kKeywords) {
    if (css::ascii_equal_ignoring_case(keyword, d.value)) {
      style.*Field = value;
      return true;
    }
  }
  return false;
}

template <auto Field, const auto& kKeywords>
bool keyword_property(const Declaration& d) {
  return set_keyword<Field, kKeywords>(d.style, d.parent, d);
}

// The same for a keyword property of text_properties.h, a `Field` of the style's text part.
template <auto Field, const auto& kKeywords>
bool text_keyword_property(const Declaration& d) {
  return set_keyword<Field, kKeywords>(d.style.text, d.parent.text, d);
}

constexpr KeywordTable<FillRule, 2> kFillRules{
    {{"nonzero", FillRule::kNonZero}, {"evenodd", FillRule::kEvenOdd}}};

constexpr KeywordTable<LineJoinValue, 5> kLineJoins{{{"miter", LineJoinValue::kMiter},
                                                     {"miter-clip", LineJoinValue::kMiterClip},
                                                     {"round", LineJoinValue::kRound},
                                                     {"bevel", LineJoinValue::kBevel},
                                                     {"arcs", LineJoinValue::kArcs}}};

constexpr KeywordTable<LineCapValue, 3> kLineCaps{
    {{"butt", LineCapValue::kButt}, {"round", LineCapValue::kRound}, {"square", LineCapValue::kSquare}}};

// visibility: collapse hides as hidden does (SVG has no table rows to collapse).
constexpr KeywordTable<bool, 3> kVisibility{{{"visible", true}, {"hidden", false}, {"collapse", false}}};

// shape-rendering (SVG 1.1 11.7.1): the value of aliased_shapes.
constexpr KeywordTable<bool, 4> kShapeRendering{
    {{"auto", false}, {"geometricPrecision", false}, {"optimizeSpeed", true}, {"crispEdges", true}}};

// image-rendering (SVG 1.1 15.3, inherited; CSS Images 3, 7.5): optimizeSpeed and CSS's pixelated and
// crisp-edges keep an image's pixels sharp (nearest sampling); auto, optimizeQuality, smooth and
// high-quality smooth it (bilinear). The value of pixelated_images.
constexpr KeywordTable<bool, 7> kImageRendering{{{"auto", false},
                                                 {"optimizeQuality", false},
                                                 {"smooth", false},
                                                 {"high-quality", false},
                                                 {"optimizeSpeed", true},
                                                 {"pixelated", true},
                                                 {"crisp-edges", true}}};

// The keywords of display (CSS Display 3, section 2, and CSS 2.1's list), as the value of `display`:
// any of them except none renders an SVG element, since SVG lays out no boxes.
constexpr KeywordTable<bool, 27> kDisplay{{{"none", false},
                                           {"inline", true},
                                           {"block", true},
                                           {"list-item", true},
                                           {"inline-block", true},
                                           {"table", true},
                                           {"inline-table", true},
                                           {"table-row-group", true},
                                           {"table-header-group", true},
                                           {"table-footer-group", true},
                                           {"table-row", true},
                                           {"table-column-group", true},
                                           {"table-column", true},
                                           {"table-cell", true},
                                           {"table-caption", true},
                                           {"run-in", true},
                                           {"compact", true},
                                           {"marker", true},
                                           {"flex", true},
                                           {"inline-flex", true},
                                           {"grid", true},
                                           {"inline-grid", true},
                                           {"contents", true},
                                           {"flow-root", true},
                                           {"ruby", true},
                                           {"flow", true},
                                           {"inline-list-item", true}}};

// direction (CSS Writing Modes 3 section 2.1): the value of right_to_left.
constexpr KeywordTable<bool, 2> kDirections{{{"ltr", false}, {"rtl", true}}};

constexpr KeywordTable<UnicodeBidi, 6> kUnicodeBidi{{{"normal", UnicodeBidi::kNormal},
                                                     {"embed", UnicodeBidi::kEmbed},
                                                     {"isolate", UnicodeBidi::kIsolate},
                                                     {"bidi-override", UnicodeBidi::kBidiOverride},
                                                     {"isolate-override", UnicodeBidi::kIsolateOverride},
                                                     {"plaintext", UnicodeBidi::kPlaintext}}};

// text-rendering (SVG 1.1 10.8; inherited; SVG 2 refers to CSS Fonts), the value of the text's aliased:
// optimizeSpeed lets speed win over legibility and geometric precision, which the specification's own
// example is turning anti-aliasing off; the other three keep exact coverage.
constexpr KeywordTable<bool, 4> kTextRendering{
    {{"auto", false}, {"optimizeLegibility", false}, {"geometricPrecision", false}, {"optimizeSpeed", true}}};

// text-orientation (CSS Writing Modes 3 section 5.1); sideways-right is the CSS Writing Modes 3 draft's
// name for sideways.
constexpr KeywordTable<TextOrientation, 4> kTextOrientations{
    {{"mixed", TextOrientation::kMixed},
     {"upright", TextOrientation::kUpright},
     {"sideways", TextOrientation::kSideways},
     {"sideways-right", TextOrientation::kSideways}}};

// glyph-orientation-vertical (SVG 1.1 10.7.3): auto, or an angle that is a multiple of 90 degrees; CSS
// Writing Modes 3 section 5.1.1 maps auto to mixed, 0deg to upright and 90deg to sideways. 180 and 270
// are not supported.
constexpr KeywordTable<TextOrientation, 5> kGlyphOrientations{{{"auto", TextOrientation::kMixed},
                                                               {"0", TextOrientation::kUpright},
                                                               {"0deg", TextOrientation::kUpright},
                                                               {"90", TextOrientation::kSideways},
                                                               {"90deg", TextOrientation::kSideways}}};

// font-kerning (CSS Fonts 3 6.5): auto and normal on, none off.
constexpr KeywordTable<bool, 3> kFontKerning{{{"auto", true}, {"normal", true}, {"none", false}}};

// font-optical-sizing (CSS Fonts 4 8.4): auto (true) or none.
constexpr KeywordTable<bool, 2> kOpticalSizing{{{"auto", true}, {"none", false}}};

// A length of `d.value` in user units along `axis`, em against the element's own font size.
std::optional<double> parse_length_value(const Declaration& d, LengthAxis axis) {
  const Result<Length> parsed = parse_length(d.value);
  if (!parsed) return std::nullopt;
  return length_to_pixels(*parsed, LengthContext{axis.dpi, d.style.font_size, axis.percent_reference});
}

// fill and stroke (SVG 1.1 11.2 <paint>).
template <PaintSpec ComputedStyle::*Field>
bool paint_property(const Declaration& d) {
  if (d.inherit) {
    d.style.*Field = d.parent.*Field;
    return true;
  }
  const std::optional<PaintSpec> paint = parse_paint(d.value);
  if (!paint) return false;
  d.style.*Field = *paint;
  if (paint->kind == PaintSpec::Kind::kUrl && paint->url_id.empty()) {
    d.diagnostics.warnings.push_back(std::string(d.name) + " '" + std::string(d.value) +
                                     "' refers to another document, which is not read; its fallback or "
                                     "none is painted");
  }
  return true;
}

// opacity, fill-opacity, stroke-opacity: an <alpha-value>.
template <double ComputedStyle::*Field>
bool alpha_property(const Declaration& d) {
  const std::optional<double> alpha = d.inherit ? d.parent.*Field : parse_alpha(d.value);
  if (!alpha) return false;
  d.style.*Field = *alpha;
  return true;
}

bool stroke_width(const Declaration& d) {
  const std::optional<double> width =
      d.inherit ? d.parent.stroke_width : parse_length_value(d, d.context.other());
  if (!width || *width < 0.0) return false;  // SVG: negative widths are an error
  d.style.stroke_width = *width;
  return true;
}

bool stroke_miterlimit(const Declaration& d) {
  const std::optional<double> limit = d.inherit ? d.parent.stroke_miterlimit : parse_number(d.value);
  if (!limit || *limit < 1.0) return false;  // SVG 1.1: values below 1 are an error
  d.style.stroke_miterlimit = *limit;
  return true;
}

bool stroke_dasharray(const Declaration& d) {
  if (d.inherit) {
    d.style.stroke_dasharray = d.parent.stroke_dasharray;
    return true;
  }
  if (css::ascii_equal_ignoring_case(d.value, "none")) {
    d.style.stroke_dasharray.clear();
    return true;
  }
  // Lengths separated by comma-wsp; a negative entry makes the whole declaration invalid (SVG 1.1
  // 11.4), as does anything unparsable.
  const LengthAxis diagonal = d.context.other();
  std::vector<double> dashes;
  std::string_view rest = d.value;
  while (!rest.empty()) {
    std::size_t end = 0;
    while (end < rest.size() && rest[end] != ',' && !is_svg_whitespace(rest[end])) ++end;
    const Result<Length> dash = parse_length(rest.substr(0, end));
    rest.remove_prefix(end);
    skip_comma_whitespace(rest);
    if (!dash.is_ok() || dash->value < 0.0) return false;
    dashes.push_back(
        length_to_pixels(*dash, LengthContext{diagonal.dpi, d.style.font_size, diagonal.percent_reference}));
  }
  if (dashes.empty()) return false;
  d.style.stroke_dasharray = std::move(dashes);
  return true;
}

bool stroke_dashoffset(const Declaration& d) {
  const std::optional<double> offset =
      d.inherit ? d.parent.stroke_dashoffset : parse_length_value(d, d.context.other());
  if (!offset) return false;
  d.style.stroke_dashoffset = *offset;
  return true;
}

bool color_property(const Declaration& d) {
  if (d.inherit) {
    d.style.color = d.parent.color;
    return true;
  }
  const Result<Color> color = parse_color(d.value);
  if (!color) return false;
  d.style.color = *color;
  return true;
}

bool font_size(const Declaration& d) {
  if (d.inherit) {
    d.style.font_size = d.parent.font_size;
    return true;
  }
  if (const std::optional<double> keyword = font_size_keyword(d.value, d.parent.font_size)) {
    d.style.font_size = *keyword;
    return true;
  }
  // em in font-size refers to the parent's font size (CSS 2.1 15.7); % likewise.
  const Result<Length> size = parse_length(d.value);
  if (!size || size->value < 0.0) return false;
  d.style.font_size =
      size->unit == LengthUnit::kPercent
          ? d.parent.font_size * size->value / 100.0
          : length_to_pixels(*size, LengthContext{d.context.dpi.diagonal(), d.parent.font_size, 0.0});
  return true;
}

bool font_family(const Declaration& d) {
  if (d.inherit) {
    d.style.font_family = d.parent.font_family;
    return true;
  }
  std::optional<std::string> family = parse_font_family(d.value);
  if (!family) return false;
  d.style.font_family = std::move(*family);
  return true;
}

bool font_weight(const Declaration& d) {
  const std::optional<int> weight =
      d.inherit ? d.parent.font_weight : parse_font_weight(d.value, d.parent.font_weight);
  if (!weight) return false;
  d.style.font_weight = *weight;
  return true;
}

// font-style: italic or oblique, and an oblique's angle (kept with the font variants).
bool font_style(const Declaration& d) {
  if (d.inherit) {
    d.style.font_italic = d.parent.font_italic;
    d.style.text.font_variants.oblique_angle = d.parent.text.font_variants.oblique_angle;
    return true;
  }
  const std::optional<bool> italic = parse_font_style_italic(d.value);
  if (!italic) return false;
  d.style.font_italic = *italic;
  d.style.text.font_variants.oblique_angle = font_style_oblique_angle(d.value);
  return true;
}

bool text_anchor(const Declaration& d) {
  const std::optional<TextAnchor> anchor = d.inherit ? d.parent.text_anchor : parse_text_anchor(d.value);
  if (!anchor) return false;
  d.style.text_anchor = *anchor;
  return true;
}

// The font shorthand sets style, weight, size and family at once (CSS 2.1 15.8), and resets the font
// variants it covers.
bool font_shorthand(const Declaration& d) {
  if (d.inherit) {
    d.style.font_italic = d.parent.font_italic;
    d.style.font_weight = d.parent.font_weight;
    d.style.font_size = d.parent.font_size;
    d.style.font_family = d.parent.font_family;
    d.style.text.font_variants = d.parent.text.font_variants;
    return true;
  }
  const std::optional<FontShorthand> font = parse_font_shorthand(d.value, d.parent.font_weight);
  if (!font) return false;
  apply_property(d.style, d.parent, "font-size", font->size, d.context, d.diagnostics);
  d.style.font_italic = font->italic;
  d.style.font_weight = font->weight;
  d.style.font_family = font->family;
  const std::optional<Length> kerning = d.style.text.font_variants.kerning_length;  // not a font property
  d.style.text.font_variants = FontVariants{};
  d.style.text.font_variants.kerning_length = kerning;
  d.style.text.font_variants.caps = font->small_caps ? CapsVariant::kSmallCaps : CapsVariant::kNormal;
  d.style.text.font_variants.stretch = font->stretch;
  return true;
}

bool clip_path(const Declaration& d) {
  if (d.inherit) {
    d.style.clip_path_id = d.parent.clip_path_id;
    return true;
  }
  if (css::ascii_equal_ignoring_case(d.value, "none")) {
    d.style.clip_path_id.clear();
    return true;
  }
  const std::optional<std::string> id = parse_url_reference(d.value);
  if (!id) return false;
  d.style.clip_path_id = *id;
  return true;
}

// A row for a property of painting_properties.h: its applier gets the style's painting part.
template <painting::Applier kApply>
bool painting_property(const Declaration& declaration) {
  return kApply(declaration.style.painting, declaration.parent.painting, declaration.value,
                declaration.inherit, declaration.diagnostics);
}

// A row for a property of text_properties.h: its applier gets the style's text part.
template <text::Applier kApply>
bool text_property(const Declaration& declaration) {
  return kApply(declaration.style.text, declaration.parent.text, declaration.value, declaration.inherit);
}

// The same for a keyword property of text_font_variants.h, a `Field` of the style's font variants.
template <auto Field, const auto& kKeywords>
bool font_variant_keyword_property(const Declaration& d) {
  return set_keyword<Field, kKeywords>(d.style.text.font_variants, d.parent.text.font_variants, d);
}

// A row for a property of text_font_variants.h: its applier gets the style's font variants.
template <font_variant::Applier kApply>
bool font_variant_property(const Declaration& declaration) {
  return kApply(declaration.style.text.font_variants, declaration.parent.text.font_variants,
                declaration.value, declaration.inherit);
}

struct PropertyEntry {
  std::string_view name;
  Applier apply;  ///< null: a property read elsewhere (stop-color, by the gradient reader)
};

// Every property of the cascade, sorted by name (checked below) for the binary search of find_property.
// `marker`, `mix-blend-mode` and `isolation` are declared in CSS only (is_css_only_property: they have no
// presentation attribute); so are the newer font properties (is_css_only_font_property, which the cascade
// reads to drop their presentation attributes).
constexpr std::array<PropertyEntry, 69> kPropertyTable{{
    {"alignment-baseline", text_property<text::alignment_baseline>},
    {"baseline-shift", text_property<text::baseline_shift>},
    {"clip-path", clip_path},
    {"clip-rule", keyword_property<&ComputedStyle::clip_rule, kFillRules>},
    {"color", color_property},
    {"color-interpolation", painting_property<painting::color_interpolation>},
    {"direction", text_keyword_property<&TextProperties::right_to_left, kDirections>},
    {"display", keyword_property<&ComputedStyle::display, kDisplay>},
    {"dominant-baseline", text_property<text::dominant_baseline>},
    {"fill", paint_property<&ComputedStyle::fill>},
    {"fill-opacity", alpha_property<&ComputedStyle::fill_opacity>},
    {"fill-rule", keyword_property<&ComputedStyle::fill_rule, kFillRules>},
    {"filter", painting_property<painting::filter>},
    {"font", font_shorthand},
    {"font-family", font_family},
    {"font-feature-settings", font_variant_property<font_variant::font_feature_settings>},
    {"font-kerning", font_variant_keyword_property<&FontVariants::kerning, kFontKerning>},
    {"font-optical-sizing", font_variant_keyword_property<&FontVariants::optical_sizing, kOpticalSizing>},
    {"font-size", font_size},
    {"font-stretch", font_variant_property<font_variant::font_stretch>},
    {"font-style", font_style},
    {"font-variant", font_variant_property<font_variant::font_variant>},
    {"font-variant-caps", font_variant_property<font_variant::font_variant_caps>},
    {"font-variant-east-asian", font_variant_property<font_variant::font_variant_east_asian>},
    {"font-variant-ligatures", font_variant_property<font_variant::font_variant_ligatures>},
    {"font-variant-numeric", font_variant_property<font_variant::font_variant_numeric>},
    {"font-variant-position", font_variant_property<font_variant::font_variant_position>},
    {"font-variation-settings", font_variant_property<font_variant::font_variation_settings>},
    {"font-weight", font_weight},
    {"font-width", font_variant_property<font_variant::font_stretch>},
    {"glyph-orientation-vertical", text_keyword_property<&TextProperties::orientation, kGlyphOrientations>},
    {"image-rendering", keyword_property<&ComputedStyle::pixelated_images, kImageRendering>},
    {"isolation", painting_property<painting::isolation>},
    {"kerning", font_variant_property<font_variant::kerning>},
    {"letter-spacing", text_property<text::letter_spacing>},
    {"marker", painting_property<painting::marker>},
    {"marker-end", painting_property<painting::marker_end>},
    {"marker-mid", painting_property<painting::marker_mid>},
    {"marker-start", painting_property<painting::marker_start>},
    {"mask", painting_property<painting::mask>},
    {"mask-type", painting_property<painting::mask_type>},
    {"mix-blend-mode", painting_property<painting::mix_blend_mode>},
    {"opacity", alpha_property<&ComputedStyle::opacity>},
    {"overflow", painting_property<painting::overflow>},
    {"paint-order", painting_property<painting::paint_order>},
    {"shape-rendering", keyword_property<&ComputedStyle::aliased_shapes, kShapeRendering>},
    {"stop-color", nullptr},
    {"stroke", paint_property<&ComputedStyle::stroke>},
    {"stroke-dasharray", stroke_dasharray},
    {"stroke-dashoffset", stroke_dashoffset},
    {"stroke-linecap", keyword_property<&ComputedStyle::stroke_linecap, kLineCaps>},
    {"stroke-linejoin", keyword_property<&ComputedStyle::stroke_linejoin, kLineJoins>},
    {"stroke-miterlimit", stroke_miterlimit},
    {"stroke-opacity", alpha_property<&ComputedStyle::stroke_opacity>},
    {"stroke-width", stroke_width},
    {"tab-size", text_property<text::tab_size>},
    {"text-anchor", text_anchor},
    {"text-decoration", text_property<text::text_decoration>},
    {"text-decoration-line", text_property<text::text_decoration>},
    {"text-orientation", text_keyword_property<&TextProperties::orientation, kTextOrientations>},
    {"text-rendering", text_keyword_property<&TextProperties::aliased, kTextRendering>},
    {"text-transform", text_property<text::text_transform>},
    {"unicode-bidi", text_keyword_property<&TextProperties::unicode_bidi, kUnicodeBidi>},
    {"vector-effect", painting_property<painting::vector_effect>},
    {"visibility", keyword_property<&ComputedStyle::visible, kVisibility>},
    {"white-space", text_property<text::white_space>},
    {"word-spacing", text_property<text::word_spacing>},
    {"writing-mode", text_property<text::writing_mode>},
    {"xml:space", text_property<text::xml_space>},
}};

static_assert(std::is_sorted(kPropertyTable.begin(), kPropertyTable.end(),
                             [](const PropertyEntry& a, const PropertyEntry& b) { return a.name < b.name; }),
              "kPropertyTable must stay sorted by name");

// The row of `name`, or null.
const PropertyEntry* find_property(std::string_view name) noexcept {
  const auto* row =
      std::lower_bound(kPropertyTable.begin(), kPropertyTable.end(), name,
                       [](const PropertyEntry& entry, std::string_view key) { return entry.name < key; });
  return row != kPropertyTable.end() && row->name == name ? row : nullptr;
}

}  // namespace

ComputedStyle inherit_style(const ComputedStyle& parent) {
  ComputedStyle style = parent;
  style.opacity = 1.0;
  style.display = true;
  style.clip_path_id.clear();
  reset_non_inherited(style.painting);
  reset_non_inherited(style.text);
  return style;
}

bool is_style_property(std::string_view name) noexcept {
  return find_property(name) != nullptr && !is_css_only_property(name);
}

double diagonal_reference(double width, double height) noexcept {
  return std::sqrt((width * width + height * height) / 2.0);
}

LengthAxis ResolveContext::other() const noexcept {
  return {diagonal_reference(viewport_width, viewport_height), dpi.diagonal()};
}

bool is_other_document_url(std::string_view text) {
  text = trim_whitespace(text);
  if (text.empty() || !css::ascii_equal_ignoring_case(text.substr(0, 4), "url(") || text.back() != ')')
    return false;
  std::string_view inside = trim_whitespace(text.substr(4, text.size() - 5));
  if (inside.size() >= 2 && (inside.front() == '"' || inside.front() == '\'') &&
      inside.back() == inside.front())
    inside = trim_whitespace(inside.substr(1, inside.size() - 2));
  return !inside.empty() && inside.front() != '#';
}

std::optional<std::string> parse_url_reference(std::string_view text) {
  text = trim_whitespace(text);
  if (text.empty() || !css::ascii_equal_ignoring_case(text.substr(0, 4), "url(") || text.back() != ')')
    return std::nullopt;
  std::string_view inside = trim_whitespace(text.substr(4, text.size() - 5));
  if (inside.size() >= 2 && (inside.front() == '"' || inside.front() == '\'') &&
      inside.back() == inside.front()) {
    inside = trim_whitespace(inside.substr(1, inside.size() - 2));
  }
  if (inside.size() < 2 || inside.front() != '#') return std::nullopt;
  return std::string(inside.substr(1));
}

std::optional<double> resolve_length(std::string_view attribute, std::string_view text, LengthAxis axis,
                                     double font_size, Diagnostics& diagnostics) {
  const Result<Length> length = parse_length(text);
  if (!length) {
    diagnostics.warnings.push_back("attribute '" + std::string(attribute) + "': " + length.error().message);
    return std::nullopt;
  }
  return length_to_pixels(*length, LengthContext{axis.dpi, font_size, axis.percent_reference});
}

bool apply_property(ComputedStyle& style, const ComputedStyle& parent, std::string_view name,
                    std::string_view raw_value, const ResolveContext& context, Diagnostics& diagnostics) {
  const std::string_view value = trim_whitespace(raw_value);
  // The CSS-wide keywords (CSS Cascade 4, 7.3; ASCII case-insensitive) for every property: each becomes
  // `inherit` from the right source. initial: from the initial values (a default ComputedStyle, which
  // holds them). unset: from what the element has when nothing is declared, its parent's value for an
  // inherited property and the initial value for the others, which is inherit_style(parent). revert in
  // an author sheet goes back to the user agent's sheet, which sets none of these: as unset.
  // xml:space is an XML attribute, not a CSS property: its values are its own.
  if (name != "xml:space" && value.size() <= 12) {
    const std::string keyword = css::ascii_lower(value);
    if (keyword == "initial") {
      static const ComputedStyle kInitialStyle;
      return apply_property(style, kInitialStyle, name, "inherit", context, diagnostics);
    }
    if (keyword == "unset" || keyword == "revert" || keyword == "revert-layer") {
      return apply_property(style, inherit_style(parent), name, "inherit", context, diagnostics);
    }
    if (keyword == "inherit" && value != "inherit") {
      return apply_property(style, parent, name, "inherit", context, diagnostics);
    }
  }
  const Declaration declaration{style, parent, name, value, value == "inherit", context, diagnostics};
  bool valid = true;
  if (const PropertyEntry* entry = find_property(name)) {
    if (entry->apply == nullptr) return true;  // read elsewhere
    valid = entry->apply(declaration);
  } else {
    return true;  // not a property: ignored
  }
  if (!valid) warn_invalid(diagnostics, name, raw_value);
  return valid;
}

std::string Diagnostics::element_prefix(const pugi::xml_node& node) const {
  std::string name = "<" + std::string(node.name()) + "> ";
  // pugixml's offset of an element is that of its name, one byte after the '<'.
  return positions ? positions->describe(node.offset_debug() - 1) + ": " + name : name;
}

void Diagnostics::warn_once(std::string warning) {
  if (unsupported_seen_.insert("warning " + warning).second) warnings.push_back(std::move(warning));
}

void Diagnostics::unsupported(std::string_view feature) {
  if (unsupported_seen_.insert(std::string(feature)).second)
    warnings.push_back(std::string(feature) + " is not supported, ignored");
}

void Diagnostics::unknown_element(std::string_view name) {
  warn_once("<" + std::string(name) + "> is not a known SVG element, not drawn (nor its content)");
}

}  // namespace curvescan::svg::detail
