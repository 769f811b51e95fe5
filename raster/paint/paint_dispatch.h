// Painting the spans of a rasterized shape with any Paint, into the canvas image or a layer, through a
// clip mask: picks the compositor for the paint (solid or gradient) and wraps it for the layer's origin
// (offset_span_sink.h) and the mask (masked_span_sink.h). Canvas::fill's plain case (solid, no layer, no
// mask) does not come here: it keeps its direct SolidSpanCompositor.
#pragma once

#include <memory>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/rasterizer.h"
#include "gradient_table_cache.h"

namespace curvescan::detail {

/// Resolves the rasterizer's edges under `rule` and composites them with `paint` into `target`, whose
/// pixel (0, 0) is canvas pixel (origin_x, origin_y); `user_to_device` is the fill's transform (gradients
/// are evaluated through its inverse); `mask`, when given, multiplies the coverage. A gradient whose
/// composed transform is singular paints nothing (the shape then has no area either).
/// `gradient_table`: where a large pad-gradient fill keeps its colour table (gradient_table_cache.h),
/// shared with the other bands of the fill; null when the render's memory budget has no room for one.
void rasterize_with_paint(Rasterizer& rasterizer, FillRule rule, Antialias antialias, const Paint& paint,
                          const Affine& user_to_device, Image& target, int origin_x, int origin_y,
                          const ClipMask* mask, std::shared_ptr<GradientTableSlot> gradient_table);

}  // namespace curvescan::detail
