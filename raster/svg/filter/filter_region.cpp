// The filter region (filter_region.h).
#include "filter_region.h"

#include <cmath>
#include <string>

#include "curvescan/svg/length.h"

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

std::optional<FilterDefinition> place_filter(const ResolvedFilter& filter, const std::optional<Rect>& bbox) {
  FilterDefinition definition;
  definition.filter = &filter;
  definition.bounding_box_primitives = filter.bounding_box_primitives;
  const bool has_box = bbox && bbox->width() > 0.0 && bbox->height() > 0.0;
  if ((filter.region_in_box || filter.bounding_box_primitives) && !has_box) return std::nullopt;
  const double x = filter.x, y = filter.y, w = filter.width, h = filter.height;
  if (!(w > 0.0) || !(h > 0.0) || !std::isfinite(x + y + w + h)) return std::nullopt;
  if (filter.region_in_box) {
    definition.region = Rect{bbox->x0 + x * bbox->width(), bbox->y0 + y * bbox->height(),
                             bbox->x0 + (x + w) * bbox->width(), bbox->y0 + (y + h) * bbox->height()};
  } else {
    definition.region = Rect{x, y, x + w, y + h};
  }
  if (!std::isfinite(definition.region.x1 + definition.region.y1)) return std::nullopt;
  return definition;
}

}  // namespace curvescan::svg::detail::filter
