// The filter region (filter_region.h).
#include "filter_region.h"

#include <cmath>
#include <string>

#include "curvescan/svg/length.h"
#include "href_chain.h"

namespace curvescan::svg::detail::filter {

double region_attribute(const pugi::xml_attribute& attribute, double fallback, bool bounding_box,
                        LengthAxis axis, std::string_view element, Diagnostics& diagnostics) {
  if (!attribute) return fallback;
  const Result<Length> length = parse_length(attribute.value());
  if (!length) {
    diagnostics.warnings.push_back("<" + std::string(element) + "> " + attribute.name() + ": " +
                                   length.error().message);
    return fallback;
  }
  if (bounding_box) return length->unit == LengthUnit::kPercent ? length->value / 100.0 : length->value;
  return length_to_pixels(*length, LengthContext{axis.dpi, 16.0, axis.percent_reference});
}

std::optional<FilterDefinition> resolve_filter_element(const pugi::xml_node& filter, const IdIndex& ids,
                                                       const std::optional<Rect>& bbox,
                                                       const ResolveContext& context,
                                                       Diagnostics& diagnostics) {
  constexpr int kMaxChain = 16;
  const std::vector<pugi::xml_node> chain =
      href_chain(filter, ids, {"filter"}, kMaxChain, "filter", diagnostics);
  FilterDefinition definition;
  definition.primitives = filter;
  for (const pugi::xml_node& link : chain) {
    if (link.find_child([](const pugi::xml_node& child) { return child.type() == pugi::node_element; })) {
      definition.primitives = link;
      break;
    }
  }
  const bool region_in_box =
      std::string_view(chain_attribute(chain, "filterUnits").value()) != "userSpaceOnUse";
  definition.bounding_box_primitives =
      std::string_view(chain_attribute(chain, "primitiveUnits").value()) == "objectBoundingBox";
  const bool has_box = bbox && bbox->width() > 0.0 && bbox->height() > 0.0;
  if ((region_in_box || definition.bounding_box_primitives) && !has_box) return std::nullopt;
  const auto value = [&](const char* name, double fraction, LengthAxis axis) {
    return region_attribute(chain_attribute(chain, name),
                            region_in_box ? fraction : fraction * axis.percent_reference, region_in_box, axis,
                            "filter", diagnostics);
  };
  const double x = value("x", -0.1, context.horizontal()), y = value("y", -0.1, context.vertical());
  const double w = value("width", 1.2, context.horizontal()), h = value("height", 1.2, context.vertical());
  if (!(w > 0.0) || !(h > 0.0) || !std::isfinite(x + y + w + h)) return std::nullopt;
  if (region_in_box) {
    definition.region = Rect{bbox->x0 + x * bbox->width(), bbox->y0 + y * bbox->height(),
                             bbox->x0 + (x + w) * bbox->width(), bbox->y0 + (y + h) * bbox->height()};
  } else {
    definition.region = Rect{x, y, x + w, y + h};
  }
  if (!std::isfinite(definition.region.x1 + definition.region.y1)) return std::nullopt;
  return definition;
}

}  // namespace curvescan::svg::detail::filter
