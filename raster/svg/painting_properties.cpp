// Masking, marker and overflow properties (painting_properties.h).
#include "painting_properties.h"

#include <algorithm>
#include <array>
#include <utility>
#include <optional>

#include "computed_style.h"

namespace curvescan::svg::detail {
namespace {

constexpr std::array<std::string_view, 13> kPaintingProperties{
    "mask",       "mask-type",   "overflow",     "marker-start",        "marker-mid",
    "marker-end", "marker",      "filter",       "color-interpolation", "mix-blend-mode",
    "isolation",  "paint-order", "vector-effect"};

// "none" -> "", url(#id) -> "id"; nullopt when neither.
std::optional<std::string> reference_or_none(std::string_view value) {
  if (value == "none") return std::string();
  return parse_url_reference(value);
}

}  // namespace

std::optional<BlendMode> parse_blend_mode(std::string_view value) {
  static constexpr std::array<std::pair<std::string_view, BlendMode>, 16> kModes{{
      {"normal", BlendMode::kNormal},         {"multiply", BlendMode::kMultiply},
      {"screen", BlendMode::kScreen},         {"overlay", BlendMode::kOverlay},
      {"darken", BlendMode::kDarken},         {"lighten", BlendMode::kLighten},
      {"color-dodge", BlendMode::kColorDodge}, {"color-burn", BlendMode::kColorBurn},
      {"hard-light", BlendMode::kHardLight},   {"soft-light", BlendMode::kSoftLight},
      {"difference", BlendMode::kDifference}, {"exclusion", BlendMode::kExclusion},
      {"hue", BlendMode::kHue},               {"saturation", BlendMode::kSaturation},
      {"color", BlendMode::kColor},           {"luminosity", BlendMode::kLuminosity},
  }};
  for (const auto& [name, mode] : kModes) {
    if (name == value) return mode;
  }
  return std::nullopt;
}

std::optional<PaintOrder> parse_paint_order(std::string_view value) {
  if (value == "normal") return kNormalPaintOrder;
  PaintOrder order{};
  std::size_t count = 0;
  bool seen[3] = {false, false, false};
  std::size_t at = 0;
  while (at < value.size()) {
    while (at < value.size() && (value[at] == ' ' || value[at] == '\t' || value[at] == '\n' || value[at] == '\r')) ++at;
    if (at == value.size()) break;
    std::size_t end = at;
    while (end < value.size() && value[end] != ' ' && value[end] != '\t' && value[end] != '\n' && value[end] != '\r') ++end;
    const std::string_view word = value.substr(at, end - at);
    at = end;
    PaintLayer layer;
    if (word == "fill") {
      layer = PaintLayer::kFill;
    } else if (word == "stroke") {
      layer = PaintLayer::kStroke;
    } else if (word == "markers") {
      layer = PaintLayer::kMarkers;
    } else {
      return std::nullopt;
    }
    const auto index = static_cast<std::size_t>(layer);
    if (seen[index]) return std::nullopt;  // a keyword given twice
    seen[index] = true;
    order[count++] = layer;
  }
  if (count == 0) return std::nullopt;
  for (const PaintLayer layer : kNormalPaintOrder) {
    if (!seen[static_cast<std::size_t>(layer)]) order[count++] = layer;
  }
  return order;
}

void reset_non_inherited(PaintingProperties& properties) noexcept {
  properties.mask_id.clear();
  properties.blend_mode = BlendMode::kNormal;
  properties.isolate = false;
  properties.mask_type = MaskType::kLuminance;
  properties.overflow = PaintingProperties::Overflow::kVisible;
  properties.filters.clear();
  properties.non_scaling_stroke = false;
}

PaintingProperties::Overflow user_agent_overflow(std::string_view local_name, bool is_root) noexcept {
  static constexpr std::array<std::string_view, 5> kViewportElements{"symbol", "image", "marker", "pattern",
                                                                     "foreignObject"};
  const bool hidden =
      (local_name == "svg" && !is_root) ||
      std::find(kViewportElements.begin(), kViewportElements.end(), local_name) != kViewportElements.end();
  return hidden ? PaintingProperties::Overflow::kHidden : PaintingProperties::Overflow::kVisible;
}

bool is_css_only_property(std::string_view name) noexcept {
  // `marker` is a shorthand of CSS only (SVG 1.1 11.6.2). mix-blend-mode and isolation come from CSS
  // Compositing 1, after SVG 2 6.6 stopped giving new properties presentation attributes; browsers
  // ignore them as attributes too.
  return name == "marker" || name == "mix-blend-mode" || name == "isolation";
}

bool is_painting_property(std::string_view name) noexcept {
  return !is_css_only_property(name) &&
         std::find(kPaintingProperties.begin(), kPaintingProperties.end(), name) != kPaintingProperties.end();
}

bool is_painting_declaration(std::string_view name) noexcept {
  return is_css_only_property(name) || is_painting_property(name);
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
  } else if (name == "vector-effect") {
    // SVG 2, "Coordinate Systems, Transformations and Units", section "Vector effects": none and
    // non-scaling-stroke; the other values of SVG 2's list (non-scaling-size, non-rotation,
    // fixed-position) are at risk in the specification and not drawn.
    if (inherit) {
      style.non_scaling_stroke = parent.non_scaling_stroke;
    } else if (value == "none" || value == "non-scaling-stroke") {
      style.non_scaling_stroke = value == "non-scaling-stroke";
    } else if (value == "non-scaling-size" || value == "non-rotation" || value == "fixed-position") {
      diagnostics.unsupported("vector-effect: " + std::string(value));
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
  } else if (name == "paint-order") {
    const std::optional<PaintOrder> order = inherit ? parent.paint_order : parse_paint_order(value);
    if (!order) return false;
    style.paint_order = *order;
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
    if (inherit) {
      style.blend_mode = parent.blend_mode;
      return true;
    }
    const std::optional<BlendMode> mode = parse_blend_mode(value);
    if (mode) {
      style.blend_mode = *mode;
    } else if (value == "plus-darker" || value == "plus-lighter") {
      diagnostics.unsupported("mix-blend-mode: " + std::string(value));  // Compositing 2 drafts
    } else {
      return false;
    }
  } else if (name == "isolation") {
    if (inherit) {
      style.isolate = parent.isolate;
    } else if (value == "auto" || value == "isolate") {
      style.isolate = value == "isolate";
    } else {
      return false;
    }
  }
  return true;
}

}  // namespace curvescan::svg::detail
