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
/// Only the part of the layer that lies inside the target is touched.
void composite_layer(Image& target, int target_origin_x, int target_origin_y, const Layer& layer,
                     std::uint8_t alpha, const ClipMask* mask) noexcept;

}  // namespace curvescan
