// transform-origin (transform_origin.h).
#include "transform_origin.h"

#include <cctype>
#include <string>
#include <utility>
#include <vector>

#include "cascade.h"

namespace curvescan::svg::detail {

std::optional<Point> transform_origin_point(std::string_view text, double width, double height,
                                            double font_size, Resolution dpi, Diagnostics& diagnostics) {
  std::vector<std::string_view> parts;
  for (std::size_t at = 0; at < text.size();) {
    while (at < text.size() && std::isspace(static_cast<unsigned char>(text[at])) != 0) ++at;
    std::size_t end = at;
    while (end < text.size() && std::isspace(static_cast<unsigned char>(text[end])) == 0) ++end;
    if (end > at) parts.push_back(text.substr(at, end - at));
    at = end;
  }
  if (parts.empty() || parts.size() > 3) return std::nullopt;
  if (parts.size() == 3) {
    const std::optional<double> z =
        resolve_length("transform-origin", parts[2], LengthAxis{0.0, dpi.diagonal()}, font_size, diagnostics);
    if (!z || *z != 0.0) return std::nullopt;
    parts.pop_back();
  }
  const auto is_vertical = [](std::string_view k) { return k == "top" || k == "bottom"; };
  const auto is_horizontal = [](std::string_view k) { return k == "left" || k == "right"; };
  // Two keywords may come in either order ("top left"); a vertical one first is swapped.
  if (parts.size() == 2 && (is_vertical(parts[0]) || (parts[0] == "center" && is_horizontal(parts[1])))) {
    std::swap(parts[0], parts[1]);
  }
  if (parts.size() == 1) parts.push_back("center");
  if (parts.size() == 2 && is_vertical(parts[0]) && parts[1] == "center") std::swap(parts[0], parts[1]);
  const auto component = [&](std::string_view value, double extent,
                             bool horizontal) -> std::optional<double> {
    if (value == "center") return extent / 2.0;
    if (horizontal ? value == "left" : value == "top") return 0.0;
    if (horizontal ? value == "right" : value == "bottom") return extent;
    if (is_vertical(value) || is_horizontal(value)) return std::nullopt;  // on the wrong axis
    return resolve_length("transform-origin", value, LengthAxis{extent, horizontal ? dpi.x : dpi.y},
                          font_size, diagnostics);
  };
  const std::optional<double> x = component(parts[0], width, true);
  const std::optional<double> y = component(parts[1], height, false);
  if (!x || !y) return std::nullopt;
  return Point{*x, *y};
}

Affine paint_server_transform(const pugi::xml_node& node, const Affine& transform,
                              const ResolveContext& context, Diagnostics& diagnostics) {
  const std::optional<std::string> text = cascaded_value(node, "transform-origin", context.style_sheets);
  if (!text) return transform;
  const std::optional<Point> origin =
      transform_origin_point(*text, context.viewport_width, context.viewport_height,
                             ComputedStyle{}.font_size, context.dpi, diagnostics);
  if (!origin) {
    diagnostics.warnings.push_back("<" + std::string(node.name()) + "> ignoring transform-origin \"" + *text +
                                   "\"");
    return transform;
  }
  return about_origin(transform, *origin);
}

Affine about_origin(const Affine& transform, const Point& origin) noexcept {
  return Affine::translate(origin.x, origin.y) * transform * Affine::translate(-origin.x, -origin.y);
}

}  // namespace curvescan::svg::detail
