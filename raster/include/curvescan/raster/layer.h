// Layer: the transparent offscreen image a group is drawn into for group opacity (SVG 1.1 section 14.5,
// "Object and group opacity": the group is rendered as a whole into an offscreen image, which is then
// composited onto the background with the group's opacity).
//
// Canvas::push_layer / pop_layer (canvas.h) manage a stack of these; a layer covers only the canvas
// rectangle that could be drawn at the time it was pushed (the clip rectangle, the enclosing layer and
// the clip masks' bounds), so nested groups cost memory in proportion to what they can touch.
#pragma once

#include <cstdint>

#include "curvescan/raster/image.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/rasterizer.h"

namespace curvescan {

/// How a group's layer combines with what lies under it (CSS Compositing and Blending 1, section 5.3:
/// mix-blend-mode). kNormal is plain source-over; the others blend the colours by the mode's function B
/// before source-over: co = cs·(1 − αb) + cb·(1 − αs) + αs·αb·B(Cb, Cs) (section 5.1).
enum class BlendMode : std::uint8_t {
  kNormal, kMultiply, kScreen, kOverlay, kDarken, kLighten, kColorDodge, kColorBurn, kHardLight, kSoftLight,
  kDifference, kExclusion, kHue, kSaturation, kColor, kLuminosity
};

/// B(Cb, Cs) of `mode` for one pixel: `backdrop` and `source` unpremultiplied RGB in [0, 1]; `result` gets
/// the blended colour (section 5.3 for the separable modes, 5.7's SetLum / SetSat / ClipColor for hue,
/// saturation, color and luminosity).
void blend_colors(BlendMode mode, const float backdrop[3], const float source[3], float result[3]) noexcept;

/// One pixel: `source` (premultiplied) seen through `coverage` (0-255), blended with `mode` and composited
/// source-over onto `backdrop` (premultiplied), in real arithmetic and rounded to nearest. kNormal gives
/// the same result as composite_source_over up to one step of rounding.
[[nodiscard]] Rgba8 blend_source_over(Rgba8 backdrop, Rgba8 source, std::uint8_t coverage, BlendMode mode) noexcept;

struct Layer {
  /// The layer's pixels: bounds.width() x bounds.height(), premultiplied, initially transparent.
  Image pixels;
  /// Where the layer lies on the canvas (device pixels); pixel (x, y) of the canvas is
  /// pixels.at(x - bounds.x0, y - bounds.y0). May be empty, when the group can draw nothing.
  IntRect bounds;
};

/// Opacity in [0, 1] (clamped; NaN -> 0) to the 8-bit alpha Cairo uses for cairo_paint_with_alpha:
/// ⌊opacity·65535 + 0.5⌋ >> 8 (cairo-color.c, then pixman's high byte), so group opacity matches Cairo.
[[nodiscard]] std::uint8_t layer_alpha(double opacity) noexcept;

/// Composites `layer` source-over onto `target` (whose pixel (0, 0) is canvas pixel (target_origin_x,
/// target_origin_y)) with `alpha` as the coverage of every pixel (composite_source_over, pixman's
/// rounding: what cairo_paint_with_alpha does), multiplied by `mask` (MUL_UN8) where a mask is given.
/// Only the part of the layer that lies inside the target is touched. A `mode` other than kNormal blends
/// each pixel with blend_source_over.
void composite_layer(Image& target, int target_origin_x, int target_origin_y, const Layer& layer,
                     std::uint8_t alpha, const ClipMask* mask, BlendMode mode = BlendMode::kNormal) noexcept;

}  // namespace curvescan
