// Masking, marker and overflow properties (painting_properties.h).
#include "painting_properties.h"

#include <algorithm>
#include <array>
#include <optional>
#include <utility>

#include "computed_style.h"
#include "css/syntax.h"
#include "curvescan/svg/number.h"

namespace curvescan::svg::detail {
namespace {

// "none" -> "", url(#id) -> "id"; nullopt when neither.
std::optional<std::string> reference_or_none(std::string_view value) {
  if (css::ascii_equal_ignoring_case(value, "none")) return std::string();
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
    if (css::ascii_equal_ignoring_case(name, value)) return mode;
  }
  return std::nullopt;
}

std::optional<PaintOrder> parse_paint_order(std::string_view value) {
  if (css::ascii_equal_ignoring_case(value, "normal")) return kNormalPaintOrder;
  PaintOrder order{};
  std::size_t count = 0;
  bool seen[3] = {false, false, false};
  std::size_t at = 0;
  while (at < value.size()) {
    while (at < value.size() && is_svg_whitespace(value[at])) ++at;
    if (at == value.size()) break;
    std::size_t end = at;
    while (end < value.size() && !is_svg_whitespace(value[end])) ++end;
    const std::string_view word = value.substr(at, end - at);
    at = end;
    PaintLayer layer;
    if (css::ascii_equal_ignoring_case(word, "fill")) {
      layer = PaintLayer::kFill;
    } else if (css::ascii_equal_ignoring_case(word, "stroke")) {
      layer = PaintLayer::kStroke;
    } else if (css::ascii_equal_ignoring_case(word, "markers")) {
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

namespace painting {

bool mask(PaintingProperties& style, const PaintingProperties& parent, std::string_view value, bool inherit,
          Diagnostics&) {
  const std::optional<std::string> id = inherit ? parent.mask_id : reference_or_none(value);
  if (!id) return false;
  style.mask_id = *id;
  return true;
}

bool mask_type(PaintingProperties& style, const PaintingProperties& parent, std::string_view value,
               bool inherit, Diagnostics&) {
  if (inherit) {
    style.mask_type = parent.mask_type;
  } else if (value == "luminance" || value == "alpha") {
    style.mask_type = value == "alpha" ? MaskType::kAlpha : MaskType::kLuminance;
  } else {
    return false;
  }
  return true;
}

bool vector_effect(PaintingProperties& style, const PaintingProperties& parent, std::string_view value,
                   bool inherit, Diagnostics& diagnostics) {
  // SVG 2, "Coordinate Systems, Transformations and Units", section "Vector effects": none and
  // non-scaling-stroke; the other values of SVG 2's list (non-scaling-size, non-rotation,
  // fixed-position) are at risk in the specification and not drawn.
  if (inherit) {
    style.non_scaling_stroke = parent.non_scaling_stroke;
  } else if (css::ascii_equal_ignoring_case(value, "none") ||
             css::ascii_equal_ignoring_case(value, "non-scaling-stroke")) {
    style.non_scaling_stroke = css::ascii_equal_ignoring_case(value, "non-scaling-stroke");
  } else if (value == "non-scaling-size" || value == "non-rotation" || value == "fixed-position") {
    diagnostics.unsupported("vector-effect: " + std::string(value));
  } else {
    return false;
  }
  return true;
}

bool overflow(PaintingProperties& style, const PaintingProperties& parent, std::string_view value,
              bool inherit, Diagnostics&) {
  using Overflow = PaintingProperties::Overflow;
  if (inherit) {
    style.overflow = parent.overflow;
  } else if (css::ascii_equal_ignoring_case(value, "visible") ||
             css::ascii_equal_ignoring_case(value, "auto")) {
    style.overflow = Overflow::kVisible;
  } else if (css::ascii_equal_ignoring_case(value, "hidden") ||
             css::ascii_equal_ignoring_case(value, "scroll") ||
             css::ascii_equal_ignoring_case(value, "clip")) {
    style.overflow = Overflow::kHidden;
  } else {
    return false;
  }
  return true;
}

namespace {

// One marker property (SVG 1.1 11.6.2): "none", url(#id), or the parent's on `inherit`.
bool set_marker(std::string& target, const std::string& inherited, std::string_view value, bool inherit) {
  const std::optional<std::string> id = inherit ? inherited : reference_or_none(value);
  if (!id) return false;
  target = *id;
  return true;
}

}  // namespace

bool marker_start(PaintingProperties& style, const PaintingProperties& parent, std::string_view value,
                  bool inherit, Diagnostics&) {
  return set_marker(style.marker_start, parent.marker_start, value, inherit);
}

bool marker_mid(PaintingProperties& style, const PaintingProperties& parent, std::string_view value,
                bool inherit, Diagnostics&) {
  return set_marker(style.marker_mid, parent.marker_mid, value, inherit);
}

bool marker_end(PaintingProperties& style, const PaintingProperties& parent, std::string_view value,
                bool inherit, Diagnostics&) {
  return set_marker(style.marker_end, parent.marker_end, value, inherit);
}

bool marker(PaintingProperties& style, const PaintingProperties& parent, std::string_view value, bool inherit,
            Diagnostics&) {
  // The shorthand sets all three (SVG 1.1 11.6.2).
  return set_marker(style.marker_start, parent.marker_start, value, inherit) &&
         set_marker(style.marker_mid, parent.marker_mid, value, inherit) &&
         set_marker(style.marker_end, parent.marker_end, value, inherit);
}

bool paint_order(PaintingProperties& style, const PaintingProperties& parent, std::string_view value,
                 bool inherit, Diagnostics&) {
  const std::optional<PaintOrder> order = inherit ? parent.paint_order : parse_paint_order(value);
  if (!order) return false;
  style.paint_order = *order;
  return true;
}

bool color_interpolation(PaintingProperties&, const PaintingProperties&, std::string_view value, bool inherit,
                         Diagnostics&) {
  return inherit || css::ascii_equal_ignoring_case(value, "linearRGB") ||
         css::ascii_equal_ignoring_case(value, "sRGB") || css::ascii_equal_ignoring_case(value, "auto");
}

bool filter(PaintingProperties& style, const PaintingProperties& parent, std::string_view value, bool inherit,
            Diagnostics&) {
  if (inherit) {
    style.filters = parent.filters;
    return true;
  }
  std::optional<std::vector<filter::FilterFunction>> filters = filter::parse_filter_property(value);
  if (!filters) return false;
  style.filters = std::move(*filters);
  return true;
}

bool mix_blend_mode(PaintingProperties& style, const PaintingProperties& parent, std::string_view value,
                    bool inherit, Diagnostics& diagnostics) {
  if (inherit) {
    style.blend_mode = parent.blend_mode;
    return true;
  }
  const std::optional<BlendMode> mode = parse_blend_mode(value);
  if (mode) {
    style.blend_mode = *mode;
  } else if (css::ascii_equal_ignoring_case(value, "plus-darker") ||
             css::ascii_equal_ignoring_case(value, "plus-lighter")) {
    diagnostics.unsupported("mix-blend-mode: " + std::string(value));  // Compositing 2 drafts
  } else {
    return false;
  }
  return true;
}

bool isolation(PaintingProperties& style, const PaintingProperties& parent, std::string_view value,
               bool inherit, Diagnostics&) {
  if (inherit) {
    style.isolate = parent.isolate;
  } else if (css::ascii_equal_ignoring_case(value, "auto") ||
             css::ascii_equal_ignoring_case(value, "isolate")) {
    style.isolate = css::ascii_equal_ignoring_case(value, "isolate");
  } else {
    return false;
  }
  return true;
}

}  // namespace painting

}  // namespace curvescan::svg::detail
