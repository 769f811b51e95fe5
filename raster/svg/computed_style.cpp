// The cascade (computed_style.h): one parser per property, each refusing what the property's grammar
// does not allow so that apply_property can ignore the declaration (CSS 2.1 4.2).
#include "computed_style.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <pugixml.hpp>

#include "css/syntax.h"
#include "curvescan/svg/number.h"
#include "source_positions.h"
#include "text_font_properties.h"

namespace curvescan::svg::detail {
namespace {

constexpr std::array<std::string_view, 27> kProperties{"fill",
                                                       "fill-opacity",
                                                       "fill-rule",
                                                       "stroke",
                                                       "stroke-width",
                                                       "stroke-opacity",
                                                       "stroke-linejoin",
                                                       "stroke-linecap",
                                                       "stroke-miterlimit",
                                                       "stroke-dasharray",
                                                       "stroke-dashoffset",
                                                       "opacity",
                                                       "display",
                                                       "visibility",
                                                       "color",
                                                       "font-size",
                                                       "clip-rule",
                                                       "clip-path",
                                                       "stop-color",
                                                       "font-family",
                                                       "font-weight",
                                                       "font-style",
                                                       "text-anchor",
                                                       "font",
                                                       "xml:space",
                                                       "shape-rendering",
                                                       "image-rendering"};

std::optional<PaintSpec> parse_paint(std::string_view text) {
  text = trim_whitespace(text);
  PaintSpec paint;
  if (text == "none") return paint;
  if (text == "currentColor") {
    paint.kind = PaintSpec::Kind::kCurrentColor;
    return paint;
  }
  if (text == "context-fill" || text == "context-stroke") {
    paint.kind = text == "context-fill" ? PaintSpec::Kind::kContextFill : PaintSpec::Kind::kContextStroke;
    return paint;
  }
  if (text.substr(0, 4) == "url(") {
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

std::optional<FillRule> parse_fill_rule(std::string_view text) {
  text = trim_whitespace(text);
  if (text == "nonzero") return FillRule::kNonZero;
  if (text == "evenodd") return FillRule::kEvenOdd;
  return std::nullopt;
}

// The keywords of display (CSS Display 3, section 2, and CSS 2.1's list): any of them except none
// renders an SVG element, since SVG lays out no boxes.
bool is_display_keyword(std::string_view value) {
  static constexpr std::array<std::string_view, 27> kKeywords{
      "none",         "inline",          "block",           "list-item",          "inline-block",
      "table",        "inline-table",    "table-row-group", "table-header-group", "table-footer-group",
      "table-row",    "table-column-group", "table-column", "table-cell",         "table-caption",
      "run-in",       "compact",         "marker",          "flex",               "inline-flex",
      "grid",         "inline-grid",     "contents",        "flow-root",          "ruby",
      "flow",         "inline-list-item"};
  return std::find(kKeywords.begin(), kKeywords.end(), value) != kKeywords.end();
}

void warn_invalid(Diagnostics& diagnostics, std::string_view name, std::string_view value) {
  diagnostics.warnings.push_back(std::string(kInvalidValueWarning) + " '" + std::string(value) +
                                 "' of property '" + std::string(name) + "'");
  // A value is invalid here when it needs a substitution this reader does not make (CSS Variables 1):
  // say so once, besides the value.
  if (css::ascii_lower(value).find("var(") != std::string::npos) diagnostics.unsupported("CSS var()");
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
  return std::find(kProperties.begin(), kProperties.end(), name) != kProperties.end() ||
         is_painting_property(name) || is_text_property(name);
}

double diagonal_reference(double width, double height) noexcept {
  return std::sqrt((width * width + height * height) / 2.0);
}

LengthAxis ResolveContext::other() const noexcept {
  return {diagonal_reference(viewport_width, viewport_height), dpi.diagonal()};
}

bool is_other_document_url(std::string_view text) {
  text = trim_whitespace(text);
  if (text.substr(0, 4) != "url(" || text.back() != ')') return false;
  std::string_view inside = trim_whitespace(text.substr(4, text.size() - 5));
  if (inside.size() >= 2 && (inside.front() == '"' || inside.front() == '\'') &&
      inside.back() == inside.front())
    inside = trim_whitespace(inside.substr(1, inside.size() - 2));
  return !inside.empty() && inside.front() != '#';
}

std::optional<std::string> parse_url_reference(std::string_view text) {
  text = trim_whitespace(text);
  if (text.substr(0, 4) != "url(" || text.back() != ')') return std::nullopt;
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

void apply_property(ComputedStyle& style, const ComputedStyle& parent, std::string_view name,
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
      apply_property(style, kInitialStyle, name, "inherit", context, diagnostics);
      return;
    }
    if (keyword == "unset" || keyword == "revert" || keyword == "revert-layer") {
      apply_property(style, inherit_style(parent), name, "inherit", context, diagnostics);
      return;
    }
    if (keyword == "inherit" && value != "inherit") {
      apply_property(style, parent, name, "inherit", context, diagnostics);
      return;
    }
  }
  const bool inherit = value == "inherit";
  const auto invalid = [&] { warn_invalid(diagnostics, name, raw_value); };
  const LengthAxis diagonal = context.other();
  const auto length = [&](LengthAxis axis) -> std::optional<double> {
    const Result<Length> parsed = parse_length(value);
    if (!parsed) return std::nullopt;
    return length_to_pixels(*parsed, LengthContext{axis.dpi, style.font_size, axis.percent_reference});
  };

  if (name == "fill" || name == "stroke") {
    PaintSpec& target = name == "fill" ? style.fill : style.stroke;
    if (inherit) {
      target = name == "fill" ? parent.fill : parent.stroke;
    } else if (const std::optional<PaintSpec> paint = parse_paint(value)) {
      target = *paint;
      if (paint->kind == PaintSpec::Kind::kUrl && paint->url_id.empty()) {
        diagnostics.warnings.push_back(
            std::string(name) + " '" + std::string(value) +
            "' refers to another document, which is not read; its fallback or none "
            "is painted");
      }
    } else {
      invalid();
    }
  } else if (name == "fill-opacity" || name == "stroke-opacity" || name == "opacity") {
    double& target = name == "fill-opacity"     ? style.fill_opacity
                     : name == "stroke-opacity" ? style.stroke_opacity
                                                : style.opacity;
    const double inherited = name == "fill-opacity"     ? parent.fill_opacity
                             : name == "stroke-opacity" ? parent.stroke_opacity
                                                        : parent.opacity;
    if (inherit) {
      target = inherited;
    } else if (const std::optional<double> alpha = parse_alpha(value)) {
      target = *alpha;
    } else {
      invalid();
    }
  } else if (name == "fill-rule" || name == "clip-rule") {
    FillRule& target = name == "fill-rule" ? style.fill_rule : style.clip_rule;
    if (inherit) {
      target = name == "fill-rule" ? parent.fill_rule : parent.clip_rule;
    } else if (const std::optional<FillRule> rule = parse_fill_rule(value)) {
      target = *rule;
    } else {
      invalid();
    }
  } else if (name == "stroke-width") {
    const std::optional<double> width = inherit ? parent.stroke_width : length(diagonal);
    if (width && *width >= 0.0) {
      style.stroke_width = *width;
    } else {
      invalid();  // SVG: negative widths are an error
    }
  } else if (name == "stroke-linejoin") {
    if (inherit)
      style.stroke_linejoin = parent.stroke_linejoin;
    else if (value == "miter")
      style.stroke_linejoin = LineJoinValue::kMiter;
    else if (value == "miter-clip")
      style.stroke_linejoin = LineJoinValue::kMiterClip;
    else if (value == "round")
      style.stroke_linejoin = LineJoinValue::kRound;
    else if (value == "bevel")
      style.stroke_linejoin = LineJoinValue::kBevel;
    else if (value == "arcs")
      style.stroke_linejoin = LineJoinValue::kArcs;
    else
      invalid();
  } else if (name == "stroke-linecap") {
    if (inherit)
      style.stroke_linecap = parent.stroke_linecap;
    else if (value == "butt")
      style.stroke_linecap = LineCapValue::kButt;
    else if (value == "round")
      style.stroke_linecap = LineCapValue::kRound;
    else if (value == "square")
      style.stroke_linecap = LineCapValue::kSquare;
    else
      invalid();
  } else if (name == "stroke-miterlimit") {
    const std::optional<double> limit = inherit ? parent.stroke_miterlimit : parse_number(value);
    if (limit && *limit >= 1.0) {
      style.stroke_miterlimit = *limit;
    } else {
      invalid();  // SVG 1.1: values below 1 are an error
    }
  } else if (name == "stroke-dasharray") {
    if (inherit) {
      style.stroke_dasharray = parent.stroke_dasharray;
    } else if (value == "none") {
      style.stroke_dasharray.clear();
    } else {
      // Lengths separated by comma-wsp; a negative entry makes the whole declaration invalid (SVG 1.1
      // 11.4), as does anything unparsable.
      std::vector<double> dashes;
      std::string_view rest = value;
      bool ok = true;
      while (ok && !rest.empty()) {
        std::size_t end = 0;
        while (end < rest.size() && rest[end] != ',' && !is_svg_whitespace(rest[end])) ++end;
        const Result<Length> dash = parse_length(rest.substr(0, end));
        rest.remove_prefix(end);
        skip_comma_whitespace(rest);
        ok = dash.is_ok() && dash->value >= 0.0;
        if (ok)
          dashes.push_back(length_to_pixels(
              *dash, LengthContext{diagonal.dpi, style.font_size, diagonal.percent_reference}));
      }
      if (ok && !dashes.empty()) {
        style.stroke_dasharray = std::move(dashes);
      } else {
        invalid();
      }
    }
  } else if (name == "stroke-dashoffset") {
    const std::optional<double> offset = inherit ? parent.stroke_dashoffset : length(diagonal);
    if (offset)
      style.stroke_dashoffset = *offset;
    else
      invalid();
  } else if (name == "display") {
    if (inherit) {
      style.display = parent.display;
    } else if (is_display_keyword(value)) {
      style.display = value != "none";
    } else {
      invalid();
    }
  } else if (name == "visibility") {
    if (inherit)
      style.visible = parent.visible;
    else if (value == "visible")
      style.visible = true;
    else if (value == "hidden" || value == "collapse")
      style.visible = false;
    else
      invalid();
  } else if (name == "shape-rendering") {
    if (inherit)
      style.aliased_shapes = parent.aliased_shapes;
    else if (value == "auto" || value == "geometricPrecision")
      style.aliased_shapes = false;
    else if (value == "optimizeSpeed" || value == "crispEdges")
      style.aliased_shapes = true;
    else
      invalid();
  } else if (name == "image-rendering") {
    // SVG 1.1 15.3 (inherited) and CSS Images 3, 7.5: optimizeSpeed and CSS's pixelated and crisp-edges
    // keep an image's pixels sharp (nearest sampling); auto, optimizeQuality, smooth and high-quality
    // smooth it (bilinear).
    if (inherit)
      style.pixelated_images = parent.pixelated_images;
    else if (value == "auto" || value == "optimizeQuality" || value == "smooth" || value == "high-quality")
      style.pixelated_images = false;
    else if (value == "optimizeSpeed" || value == "pixelated" || value == "crisp-edges")
      style.pixelated_images = true;
    else
      invalid();
  } else if (name == "color") {
    if (inherit) {
      style.color = parent.color;
    } else if (const Result<Color> color = parse_color(value)) {
      style.color = *color;
    } else {
      invalid();
    }
  } else if (name == "font-size") {
    // em in font-size refers to the parent's font size (CSS 2.1 15.7); % likewise.
    const Result<Length> size = parse_length(value);
    if (inherit) {
      style.font_size = parent.font_size;
    } else if (const std::optional<double> keyword = font_size_keyword(value, parent.font_size)) {
      style.font_size = *keyword;
    } else if (size && size->value >= 0.0) {
      style.font_size =
          size->unit == LengthUnit::kPercent
              ? parent.font_size * size->value / 100.0
              : length_to_pixels(*size, LengthContext{context.dpi.diagonal(), parent.font_size, 0.0});
    } else {
      invalid();
    }
  } else if (name == "font-family") {
    if (inherit) {
      style.font_family = parent.font_family;
    } else if (std::optional<std::string> family = parse_font_family(value)) {
      style.font_family = std::move(*family);
    } else {
      invalid();
    }
  } else if (name == "font-weight") {
    if (inherit) {
      style.font_weight = parent.font_weight;
    } else if (const std::optional<int> weight = parse_font_weight(value, parent.font_weight)) {
      style.font_weight = *weight;
    } else {
      invalid();
    }
  } else if (name == "font-style") {
    if (inherit) {
      style.font_italic = parent.font_italic;
      style.text.font_variants.oblique_angle = parent.text.font_variants.oblique_angle;
    } else if (const std::optional<bool> italic = parse_font_style_italic(value)) {
      style.font_italic = *italic;
      style.text.font_variants.oblique_angle = font_style_oblique_angle(value);
    } else {
      invalid();
    }
  } else if (name == "text-anchor") {
    if (inherit) {
      style.text_anchor = parent.text_anchor;
    } else if (const std::optional<TextAnchor> anchor = parse_text_anchor(value)) {
      style.text_anchor = *anchor;
    } else {
      invalid();
    }
  } else if (name == "font") {
    // The shorthand sets style, weight, size and family at once (CSS 2.1 15.8).
    if (inherit) {
      style.font_italic = parent.font_italic;
      style.font_weight = parent.font_weight;
      style.font_size = parent.font_size;
      style.font_family = parent.font_family;
      style.text.font_variants = parent.text.font_variants;
    } else if (const std::optional<FontShorthand> font = parse_font_shorthand(value, parent.font_weight)) {
      apply_property(style, parent, "font-size", font->size, context, diagnostics);
      style.font_italic = font->italic;
      style.font_weight = font->weight;
      style.font_family = font->family;
      const std::optional<Length> kerning = style.text.font_variants.kerning_length;  // not a font property
      style.text.font_variants = FontVariants{};
      style.text.font_variants.kerning_length = kerning;
      style.text.font_variants.caps = font->small_caps ? CapsVariant::kSmallCaps : CapsVariant::kNormal;
      style.text.font_variants.stretch = font->stretch;
    } else {
      invalid();
    }
  } else if (name == "xml:space") {
    if (value == "preserve" || value == "default") {
      style.preserve_spaces = value == "preserve";
    } else {
      invalid();
    }
  } else if (name == "clip-path") {
    if (inherit) {
      style.clip_path_id = parent.clip_path_id;
    } else if (value == "none") {
      style.clip_path_id.clear();
    } else if (const std::optional<std::string> id = parse_url_reference(value)) {
      style.clip_path_id = *id;
    } else {
      invalid();
    }
  } else if (is_painting_declaration(name)) {
    if (!apply_painting_property(style.painting, parent.painting, name, value, diagnostics)) invalid();
  } else if (is_text_property(name)) {
    if (!apply_text_property(style.text, parent.text, name, value)) invalid();
  }
}

std::string Diagnostics::element_prefix(const pugi::xml_node& node) const {
  std::string name = "<" + std::string(node.name()) + "> ";
  // pugixml's offset of an element is that of its name, one byte after the '<'.
  return positions ? positions->describe(node.offset_debug() - 1) + ": " + name : name;
}

void Diagnostics::unsupported(std::string_view feature) {
  if (unsupported_seen_.insert(std::string(feature)).second)
    warnings.push_back(std::string(feature) + " is not supported, ignored");
}

}  // namespace curvescan::svg::detail
