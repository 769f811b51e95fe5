// Masking, marker and overflow properties (painting_properties.h).
#include "painting_properties.h"

#include <algorithm>
#include <array>
#include <optional>

#include "computed_style.h"

namespace curvescan::svg::detail {
namespace {

constexpr std::array<std::string_view, 11> kPaintingProperties{
    "mask",   "mask-type",           "overflow",       "marker-start", "marker-mid", "marker-end", "marker",
    "filter", "color-interpolation", "mix-blend-mode", "isolation"};

// "none" -> "", url(#id) -> "id"; nullopt when neither.
std::optional<std::string> reference_or_none(std::string_view value) {
  if (value == "none") return std::string();
  return parse_url_reference(value);
}

}  // namespace

void reset_non_inherited(PaintingProperties& properties) noexcept {
  properties.mask_id.clear();
  properties.mask_type = MaskType::kLuminance;
  properties.overflow = PaintingProperties::Overflow::kUnset;
  properties.filters.clear();
}

bool is_painting_property(std::string_view name) noexcept {
  // `marker` is a shorthand of CSS only, not a presentation attribute (SVG 1.1 11.6.2).
  return name != "marker" &&
         std::find(kPaintingProperties.begin(), kPaintingProperties.end(), name) != kPaintingProperties.end();
}

bool is_painting_declaration(std::string_view name) noexcept {
  return name == "marker" || is_painting_property(name);
}

bool apply_painting_property(PaintingProperties& style, const PaintingProperties& parent,
                             std::string_view name, std::string_view value, Diagnostics& diagnostics) {
  const bool inherit = value == "inherit";
  if (name == "mask") {
    const std::optional<std::string> id = inherit ? parent.mask_id : reference_or_none(value);
    if (!id) return false;
    style.mask_id = *id;
  } else if (name == "mask-type") {
    if (inherit) {
      style.mask_type = parent.mask_type;
    } else if (value == "luminance" || value == "alpha") {
      style.mask_type = value == "alpha" ? MaskType::kAlpha : MaskType::kLuminance;
    } else {
      return false;
    }
  } else if (name == "overflow") {
    using Overflow = PaintingProperties::Overflow;
    if (inherit) {
      style.overflow = parent.overflow;
    } else if (value == "visible" || value == "auto") {
      style.overflow = Overflow::kVisible;
    } else if (value == "hidden" || value == "scroll" || value == "clip") {
      style.overflow = Overflow::kHidden;
    } else {
      return false;
    }
  } else if (name == "marker-start" || name == "marker-mid" || name == "marker-end" || name == "marker") {
    // SVG 1.1 11.6.2; `marker` sets all three.
    const auto set = [&](std::string& target, const std::string& inherited) -> bool {
      const std::optional<std::string> id = inherit ? inherited : reference_or_none(value);
      if (!id) return false;
      target = *id;
      return true;
    };
    if (name == "marker") {
      return set(style.marker_start, parent.marker_start) && set(style.marker_mid, parent.marker_mid) &&
             set(style.marker_end, parent.marker_end);
    }
    if (name == "marker-start") return set(style.marker_start, parent.marker_start);
    if (name == "marker-mid") return set(style.marker_mid, parent.marker_mid);
    return set(style.marker_end, parent.marker_end);
  } else if (name == "color-interpolation") {
    return inherit || value == "linearRGB" || value == "sRGB" || value == "auto";
  } else if (name == "filter") {
    if (inherit) {
      style.filters = parent.filters;
    } else {
      std::optional<std::vector<filter::FilterFunction>> filters = filter::parse_filter_property(value);
      if (!filters) return false;
      style.filters = std::move(*filters);
    }
  } else if (name == "mix-blend-mode") {
    if (value != "normal") diagnostics.unsupported("mix-blend-mode");
  } else if (name == "isolation") {
    if (value != "auto") diagnostics.unsupported("isolation");
  }
  return true;
}

}  // namespace curvescan::svg::detail
