// <mask> region and coverage (mask.h).
#include "mask.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "curvescan/svg/length.h"

namespace curvescan::svg::detail {
namespace {

// One of x, y, width, height of the mask region. In objectBoundingBox units a number is a fraction of
// the box and a percentage is hundredths of it (SVG 1.1 7.11); in user space a percentage refers to the
// viewport (`reference`).
double region_value(const pugi::xml_node& mask, const char* name, double fallback_fraction, bool bounding_box,
                    LengthAxis axis, Diagnostics& diagnostics) {
  const double reference = axis.percent_reference;
  const pugi::xml_attribute attribute = mask.attribute(name);
  if (!attribute) return bounding_box ? fallback_fraction : fallback_fraction * reference;
  const Result<Length> length = parse_length(attribute.value());
  if (!length) {
    diagnostics.warnings.push_back("<mask> " + std::string(name) + ": " + length.error().message);
    return bounding_box ? fallback_fraction : fallback_fraction * reference;
  }
  if (bounding_box) return length->unit == LengthUnit::kPercent ? length->value / 100.0 : length->value;
  return length_to_pixels(*length, LengthContext{axis.dpi, 16.0, reference});
}

}  // namespace

ResolvedMask resolve_mask(const pugi::xml_node& mask, ComputedStyle style, const ResolveContext& context,
                          Diagnostics& diagnostics) {
  ResolvedMask resolved;
  resolved.element = mask;
  resolved.style = std::move(style);
  resolved.region_in_box = std::string_view(mask.attribute("maskUnits").value()) != "userSpaceOnUse";
  resolved.content_in_box =
      std::string_view(mask.attribute("maskContentUnits").value()) == "objectBoundingBox";
  // Defaults: -10 %, -10 %, 120 %, 120 % (SVG 1.1 14.4), of the box or of the viewport.
  const bool in_box = resolved.region_in_box;
  resolved.x = region_value(mask, "x", -0.1, in_box, context.horizontal(), diagnostics);
  resolved.y = region_value(mask, "y", -0.1, in_box, context.vertical(), diagnostics);
  resolved.width = region_value(mask, "width", 1.2, in_box, context.horizontal(), diagnostics);
  resolved.height = region_value(mask, "height", 1.2, in_box, context.vertical(), diagnostics);
  return resolved;
}

std::optional<MaskSetup> place_mask(const ResolvedMask& mask, const std::optional<Rect>& bbox) {
  const bool has_box = bbox && bbox->width() > 0.0 && bbox->height() > 0.0;
  if ((mask.region_in_box || mask.content_in_box) && !has_box) return std::nullopt;
  const double x = mask.x, y = mask.y, w = mask.width, h = mask.height;
  if (!(w > 0.0) || !(h > 0.0) || !std::isfinite(x + y + w + h)) return std::nullopt;
  const Affine box =
      has_box ? Affine::translate(bbox->x0, bbox->y0) * Affine::scale(bbox->width(), bbox->height())
              : Affine::identity();
  MaskSetup setup;
  if (mask.region_in_box) {
    setup.region = Rect{bbox->x0 + x * bbox->width(), bbox->y0 + y * bbox->height(),
                        bbox->x0 + (x + w) * bbox->width(), bbox->y0 + (y + h) * bbox->height()};
  } else {
    setup.region = Rect{x, y, x + w, y + h};
  }
  setup.content_transform = mask.content_in_box ? box : Affine::identity();
  setup.type = mask.style.painting.mask_type;
  return setup;
}

ClipMask mask_coverage(const Image& content, MaskType type) {
  std::vector<std::uint8_t> values(content.pixels().size());
  for (std::size_t i = 0; i < values.size(); ++i) {
    const Rgba8 p = content.pixels()[i];
    if (type == MaskType::kAlpha) {
      values[i] = p.a;
    } else {
      const double luminance = 0.2125 * p.r + 0.7154 * p.g + 0.0721 * p.b;
      values[i] = static_cast<std::uint8_t>(std::min(255.0, std::floor(luminance + 0.5)));
    }
  }
  return ClipMask::from_values(content.width(), content.height(), std::move(values));
}

std::optional<PixelBox> device_box(const Rect& region, const Affine& ctm, int width, int height) {
  std::optional<Rect> mapped;
  for (const Point corner : {Point{region.x0, region.y0}, Point{region.x1, region.y0},
                             Point{region.x0, region.y1}, Point{region.x1, region.y1}}) {
    const Point p = ctm.apply(corner);
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return std::nullopt;
    if (!mapped) mapped = Rect::from_point(p);
    mapped->include(p);
  }
  // Whole pixels around it (a pixel the region's edge crosses is partly covered), within the output.
  const double x0 = std::max(0.0, std::floor(mapped->x0)), y0 = std::max(0.0, std::floor(mapped->y0));
  const double x1 = std::min(static_cast<double>(width), std::ceil(mapped->x1));
  const double y1 = std::min(static_cast<double>(height), std::ceil(mapped->y1));
  if (!(x1 > x0) || !(y1 > y0)) return std::nullopt;
  return PixelBox{static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1), static_cast<int>(y1)};
}

ClipMask mask_coverage(const Image& content, MaskType type, int width, int height, int x0, int y0) {
  const ClipMask part = mask_coverage(content, type);
  std::vector<std::uint8_t> values(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
  for (int y = 0; y < part.height(); ++y) {
    const std::uint8_t* row = part.row(y);
    std::copy(row, row + part.width(),
              values.begin() + static_cast<std::ptrdiff_t>(y0 + y) * width + static_cast<std::ptrdiff_t>(x0));
  }
  return ClipMask::from_values(width, height, std::move(values));
}

}  // namespace curvescan::svg::detail
