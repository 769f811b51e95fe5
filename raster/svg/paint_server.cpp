// Gradient paint servers (paint_server.h).
#include "paint_server.h"

#include <algorithm>
#include <cmath>
#include <string_view>
#include <vector>

#include "cascade.h"
#include "css/syntax.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/svg/number.h"
#include "curvescan/svg/transform.h"
#include "href_chain.h"
#include "transform_origin.h"
#include "xml_names.h"

namespace curvescan::svg::detail {
namespace {

// A stop's property through the cascade (cascade.h): presentation attribute, style sheets, style attribute;
// the highest valid one, so an invalid declaration falls back to the next (CSS Cascade 4, 4.1). initial and
// unset are valid and give the initial value (neither property is inherited): the caller's default.
std::string stop_property(const pugi::xml_node& stop, std::string_view name, const css::StyleSheets* sheets,
                          bool (*valid)(std::string_view)) {
  std::string value = cascaded_value(stop, name, sheets, [valid](std::string_view text) {
                        const std::string keyword = css::ascii_lower(trim_whitespace(text));
                        return keyword == "initial" || keyword == "unset" || valid(trim_whitespace(text));
                      }).value_or(std::string());
  const std::string keyword = css::ascii_lower(trim_whitespace(value));
  return keyword == "initial" || keyword == "unset" ? std::string() : value;
}

bool is_inherit(std::string_view text) {
  return css::ascii_lower(trim_whitespace(text)) == "inherit";
}

bool valid_stop_color(std::string_view text) {
  return css::ascii_equal_ignoring_case(trim_whitespace(text), "currentColor") || is_inherit(text) ||
         parse_color(text).is_ok();
}

// <alpha-value>: a number or a percentage.
bool valid_stop_opacity(std::string_view text) {
  if (is_inherit(text)) return true;
  if (!text.empty() && text.back() == '%') text.remove_suffix(1);
  return parse_number(text).has_value();
}

// A stop property with `inherit` resolved: the value of the nearest of the stop and its ancestors in the
// document whose value is not inherit (SVG 1.1 13.2.4: a stop's properties inherit from its ancestors,
// never from the shape it paints); `where` is set to that element. "" for the initial value.
std::string resolved_stop_property(const pugi::xml_node& stop, std::string_view name,
                                   const css::StyleSheets* sheets, bool (*valid)(std::string_view),
                                   pugi::xml_node& where) {
  for (where = stop; where && where.type() == pugi::node_element; where = where.parent()) {
    std::string value = stop_property(where, name, sheets, valid);
    if (!is_inherit(value)) return value;
  }
  return {};
}

// The `color` property of `node` along the document tree (it is inherited), for currentColor.
Color tree_color(pugi::xml_node node, const css::StyleSheets* sheets) {
  const auto valid = [](std::string_view text) {
    const std::string keyword = css::ascii_lower(trim_whitespace(text));
    return keyword == "inherit" || keyword == "unset" || keyword == "initial" || keyword == "currentcolor" ||
           parse_color(text).is_ok();
  };
  for (; node && node.type() == pugi::node_element; node = node.parent()) {
    const std::optional<std::string> value = cascaded_value(node, "color", sheets, valid);
    if (!value) continue;
    const std::string keyword = css::ascii_lower(trim_whitespace(*value));
    if (keyword == "initial") break;
    if (keyword == "inherit" || keyword == "unset" || keyword == "currentcolor")
      continue;  // color: currentColor is inherit
    if (const Result<Color> color = parse_color(*value)) return *color;
  }
  return Color{0, 0, 0, 1};  // color's initial value: black (the canvas text colour)
}

std::vector<GradientStop> stops_of(const std::vector<pugi::xml_node>& chain, const css::StyleSheets* sheets) {
  for (const pugi::xml_node& node : chain) {
    std::vector<GradientStop> stops;
    for (const pugi::xml_node& stop : node.children("stop")) {
      GradientStop entry;
      // offset: a number or a percentage (13.2.4), clamped by normalize_gradient_stops.
      std::string_view offset_text = trim_whitespace(stop.attribute("offset").value());
      const bool percent = !offset_text.empty() && offset_text.back() == '%';
      if (percent) offset_text.remove_suffix(1);
      entry.offset = parse_number(offset_text).value_or(0.0) / (percent ? 100.0 : 1.0);
      Color color{0, 0, 0, 1};  // stop-color's initial value is black
      pugi::xml_node color_from;
      const std::string color_text =
          resolved_stop_property(stop, "stop-color", sheets, valid_stop_color, color_from);
      if (css::ascii_equal_ignoring_case(trim_whitespace(color_text), "currentColor")) {
        color = tree_color(color_from, sheets);
      } else if (!color_text.empty()) {
        if (const Result<Color> parsed = parse_color(color_text)) color = *parsed;
      }
      double stop_opacity = 1.0;
      pugi::xml_node opacity_from;
      const std::string opacity_property =
          resolved_stop_property(stop, "stop-opacity", sheets, valid_stop_opacity, opacity_from);
      std::string_view opacity_text = trim_whitespace(opacity_property);
      const bool opacity_percent = !opacity_text.empty() && opacity_text.back() == '%';
      if (opacity_percent) opacity_text.remove_suffix(1);
      if (const std::optional<double> value = parse_number(opacity_text)) {
        stop_opacity = std::clamp(*value / (opacity_percent ? 100.0 : 1.0), 0.0, 1.0);
      }
      entry.color = Color{color.r, color.g, color.b, color.a * stop_opacity};
      stops.push_back(entry);
    }
    if (!stops.empty()) return stops;
  }
  return {};
}

}  // namespace

ResolvedGradient resolve_gradient(const pugi::xml_node& element, const IdIndex& ids,
                                  const ResolveContext& context, Diagnostics& diagnostics) {
  const std::vector<pugi::xml_node> chain = href_chain(element, ids, {"linearGradient", "radialGradient"},
                                                       kMaxGradientChain, "gradient", diagnostics);
  ResolvedGradient gradient;
  gradient.radial = local_name(element) == "radialGradient";
  gradient.bounding_box_units =
      std::string_view(chain_attribute(chain, "gradientUnits").value()) != "userSpaceOnUse";
  if (const pugi::xml_attribute transform = chain_attribute(chain, "gradientTransform")) {
    const Result<Affine> parsed = parse_transform(transform.value());
    // A singular transform (matrix(0 0 0 0 0 0)) would map the gradient to a line: it is ignored, as a
    // singular patternTransform is (pattern.h) and as resvg does, with a warning.
    const double determinant = parsed ? parsed->a * parsed->d - parsed->b * parsed->c : 0.0;
    if (parsed && determinant != 0.0 && std::isfinite(determinant)) {
      gradient.transform = paint_server_transform(element, *parsed, context, diagnostics);
    } else if (parsed) {
      diagnostics.warnings.push_back("gradientTransform '" + std::string(transform.value()) +
                                     "' is singular; ignored");
    } else {
      diagnostics.warnings.push_back("gradientTransform: " + parsed.error().message);
    }
  }
  // The geometry attributes (x1 ... y2, cx ... fr) come only from gradients of the element's own kind:
  // a linearGradient has no cx to pass on (13.2.2, 13.2.3 name the attributes each kind inherits).
  std::vector<pugi::xml_node> same_kind;
  for (const pugi::xml_node& node : chain) {
    if (local_name(node) == local_name(element)) same_kind.push_back(node);
  }
  // A coordinate: in bounding-box units a number or a percentage is a fraction of the box (7.11); in
  // user space a length, percentages of the viewport.
  const auto coordinate = [&](const char* name, const char* fallback, LengthAxis axis) {
    const pugi::xml_attribute attribute = chain_attribute(same_kind, name);
    const std::string_view text = attribute ? attribute.value() : fallback;
    const Result<Length> length = parse_length(text);
    if (!length) {
      diagnostics.warnings.push_back("gradient attribute '" + std::string(name) +
                                     "': " + length.error().message);
      return 0.0;
    }
    if (gradient.bounding_box_units)
      return length->unit == LengthUnit::kPercent ? length->value / 100.0 : length->value;
    return length_to_pixels(*length, LengthContext{axis.dpi, 16.0, axis.percent_reference});
  };
  const LengthAxis w = context.horizontal(), h = context.vertical(), diagonal = context.other();
  const std::string_view spread_text = chain_attribute(chain, "spreadMethod").value();
  gradient.spread = spread_text == "reflect"  ? SpreadMethod::kReflect
                    : spread_text == "repeat" ? SpreadMethod::kRepeat
                                              : SpreadMethod::kPad;
  gradient.stops = stops_of(chain, context.style_sheets);
  if (gradient.stops.empty()) return gradient;  // 13.2.4: no stops, as if "none"
  if (!gradient.radial) {
    gradient.linear = LinearGradient{{coordinate("x1", "0%", w), coordinate("y1", "0%", h)},
                                     {coordinate("x2", "100%", w), coordinate("y2", "0%", h)}};
    return gradient;
  }
  RadialGradient& geometry = gradient.circle;
  geometry.center = {coordinate("cx", "50%", w), coordinate("cy", "50%", h)};
  // A negative r or fr is an error (SVG 1.1 13.2.3, SVG 2 14.3.3); it is read as 0, as resvg does: r 0
  // paints the last stop's colour, fr 0 is the focal point. Reported, never silent.
  const auto radius = [&](const char* name, const char* fallback, LengthAxis reference) {
    const double value = coordinate(name, fallback, reference);
    if (!(value < 0.0)) return value;
    diagnostics.warnings.push_back("gradient attribute '" + std::string(name) + "' is negative; read as 0");
    return 0.0;
  };
  geometry.radius = radius("r", "50%", diagonal);
  // fx and fy default to the (possibly inherited) cx and cy (13.2.3).
  const pugi::xml_attribute fx = chain_attribute(same_kind, "fx"), fy = chain_attribute(same_kind, "fy");
  geometry.focal = {fx ? coordinate("fx", "50%", w) : geometry.center.x,
                    fy ? coordinate("fy", "50%", h) : geometry.center.y};
  geometry.focal_radius = radius("fr", "0%", diagonal);
  return gradient;
}

std::optional<Paint> gradient_paint(const ResolvedGradient& gradient, const Rect& bbox, double opacity,
                                    bool* refused_for_box, const Affine& space) {
  if (refused_for_box) *refused_for_box = false;
  Affine gradient_to_user = space;
  if (gradient.bounding_box_units) {
    if (!(bbox.width() > 0.0) || !(bbox.height() > 0.0)) {
      if (refused_for_box) *refused_for_box = true;
      return std::nullopt;
    }
    gradient_to_user =
        space * Affine::translate(bbox.x0, bbox.y0) * Affine::scale(bbox.width(), bbox.height());
  }
  if (gradient.transform) gradient_to_user = gradient_to_user * *gradient.transform;
  if (gradient.stops.empty()) return std::nullopt;  // 13.2.4: no stops, as if "none"
  std::vector<GradientStop> stops = gradient.stops;
  for (GradientStop& stop : stops) stop.color.a *= opacity;
  return gradient.radial ? radial_gradient_paint(gradient.circle, stops, gradient.spread, gradient_to_user)
                         : linear_gradient_paint(gradient.linear, stops, gradient.spread, gradient_to_user);
}

}  // namespace curvescan::svg::detail
