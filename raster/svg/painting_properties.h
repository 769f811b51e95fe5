// The properties of masking, markers, paint order and overflow (CSS Masking 1, SVG 1.1 chapters 11 and 14,
// SVG 2 13.10) kept
// beside the cascade of computed_style.h: what <mask>, <marker>, <pattern> and clipping need to know about
// an element, and the unsupported properties that must be reported rather than dropped.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "filter/filter_property.h"

#include "curvescan/raster/layer.h"

namespace curvescan::svg::detail {

struct Diagnostics;  // computed_style.h

/// The three things a shape paints, in the order paint-order gives (SVG 2 13.10).
enum class PaintLayer : std::uint8_t { kFill, kStroke, kMarkers };
using PaintOrder = std::array<PaintLayer, 3>;
inline constexpr PaintOrder kNormalPaintOrder{PaintLayer::kFill, PaintLayer::kStroke, PaintLayer::kMarkers};

/// paint-order: `normal`, or one to three distinct keywords of fill, stroke and markers, the ones left
/// out following in their normal order ("stroke" is stroke, fill, markers). nullopt for anything else.
[[nodiscard]] std::optional<PaintOrder> parse_paint_order(std::string_view value);

/// A <blend-mode> keyword (CSS Compositing 1, 3.2: normal, multiply, ..., luminosity); nullopt otherwise.
[[nodiscard]] std::optional<BlendMode> parse_blend_mode(std::string_view value);

/// mask-type (CSS Masking 1, 7.3): how a <mask>'s content becomes coverage.
enum class MaskType { kLuminance, kAlpha };

struct PaintingProperties {
  // Not inherited.
  std::string mask_id;  ///< mask="url(#id)", empty = none
  MaskType mask_type = MaskType::kLuminance;
  /// overflow: visible and auto show content outside a viewport; hidden, scroll and clip clip it. The
  /// initial value is visible; the user agent's style sheet makes it hidden on the elements that
  /// establish a viewport (user_agent_overflow), so `inherit` reads the parent's computed value.
  enum class Overflow { kVisible, kHidden } overflow = Overflow::kVisible;
  /// filter (Filter Effects 1, section 11): url(#id) references and CSS filter functions, applied in order;
  /// empty = none.
  std::vector<filter::FilterFunction> filters;
  BlendMode blend_mode = BlendMode::kNormal;  ///< mix-blend-mode (CSS Compositing 1, 3.2)
  bool isolate = false;                       ///< isolation: isolate (CSS Compositing 1, 3.3)
  /// vector-effect: non-scaling-stroke (SVG 2, "Vector effects"): the stroke is built in device space, so
  /// its width and dashes are device pixels whatever the element's transforms and the output's scale.
  bool non_scaling_stroke = false;
  // Inherited.
  std::string marker_start;  ///< marker-start="url(#id)", empty = none (SVG 1.1 11.6.2)
  std::string marker_mid;
  std::string marker_end;
  PaintOrder paint_order = kNormalPaintOrder;  ///< paint-order (SVG 2 13.10)
};

/// Resets the properties that are not inherited to their initial values.
void reset_non_inherited(PaintingProperties& properties) noexcept;

/// The overflow the user agent's style sheet gives an element (SVG 2 appendix A:
/// `svg:not(:root), symbol, image, marker, pattern, foreignObject { overflow: hidden }`), the value the
/// cascade starts from: hidden for those, visible (the initial value) for every other element.
[[nodiscard]] PaintingProperties::Overflow user_agent_overflow(std::string_view local_name,
                                                               bool is_root) noexcept;

/// True for the properties handled here that have no presentation attribute: `marker`, `mix-blend-mode`
/// and `isolation` may only be declared in CSS (a style sheet or the style attribute).
[[nodiscard]] bool is_css_only_property(std::string_view name) noexcept;

/// The appliers of the properties handled here, one per property, each a row of the cascade's property
/// table (computed_style.cpp): `value` is trimmed, `inherit` says it is "inherit" (`parent` serves it).
/// Each returns false when the value is invalid (the caller warns and ignores it). color-interpolation is
/// validated and otherwise has no effect: gradients interpolate in sRGB, and masks compute luminance from
/// sRGB (mask.h). Values this reader does not implement are accepted and reported once through
/// `diagnostics` when they would change the rendering.
namespace painting {
using Applier = bool (*)(PaintingProperties& style, const PaintingProperties& parent, std::string_view value,
                         bool inherit, Diagnostics& diagnostics);
bool mask(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool mask_type(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool vector_effect(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool overflow(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool marker_start(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool marker_mid(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool marker_end(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool marker(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool paint_order(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool color_interpolation(PaintingProperties&, const PaintingProperties&, std::string_view, bool,
                         Diagnostics&);
bool filter(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool mix_blend_mode(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
bool isolation(PaintingProperties&, const PaintingProperties&, std::string_view, bool, Diagnostics&);
}  // namespace painting

}  // namespace curvescan::svg::detail
