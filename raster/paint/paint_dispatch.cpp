// Painting spans with any Paint into the canvas or a layer, through a mask (paint_dispatch.h).
#include "paint_dispatch.h"

#include "curvescan/raster/gradient.h"
#include "curvescan/raster/image_pattern.h"
#include "gradient_span_compositor.h"
#include "image_span_compositor.h"
#include "masked_span_sink.h"
#include "offset_span_sink.h"
#include "solid_span_compositor.h"

namespace curvescan::detail {
namespace {

void rasterize_through_mask(Rasterizer& rasterizer, FillRule rule, Antialias antialias, SpanSink& painter,
                            const ClipMask* mask) {
  if (mask == nullptr) {
    rasterizer.rasterize(rule, antialias, painter);
    return;
  }
  MaskedSpanSink masked(painter, *mask);
  rasterizer.rasterize(rule, antialias, masked);
}

}  // namespace

void rasterize_with_paint(Rasterizer& rasterizer, FillRule rule, Antialias antialias, const Paint& paint,
                          const Affine& user_to_device, Image& target, int origin_x, int origin_y,
                          const ClipMask* mask, std::shared_ptr<GradientTableSlot> gradient_table) {
  if (paint.gradient != nullptr) {
    const std::optional<Affine> device_to_gradient =
        (user_to_device * paint.gradient->gradient_to_user()).inverse();
    if (!device_to_gradient) return;
    GradientSpanCompositor compositor(target, origin_x, origin_y, *paint.gradient, *device_to_gradient,
                                      std::move(gradient_table));
    rasterize_through_mask(rasterizer, rule, antialias, compositor, mask);
    return;
  }
  if (paint.pattern != nullptr) {
    const std::optional<Affine> device_to_image = (user_to_device * paint.pattern->image_to_user).inverse();
    if (!device_to_image) return;
    ImageSpanCompositor compositor(target, origin_x, origin_y, *paint.pattern, *device_to_image);
    rasterize_through_mask(rasterizer, rule, antialias, compositor, mask);
    return;
  }
  if (paint.color.a == 0) return;  // "none" or a transparent colour changes nothing
  SolidSpanCompositor compositor(target, paint.color);
  if (origin_x == 0 && origin_y == 0) {
    rasterize_through_mask(rasterizer, rule, antialias, compositor, mask);
    return;
  }
  // The mask is in canvas coordinates, so it sees the spans before they are shifted into the layer.
  OffsetSpanSink shifted(compositor, origin_x, origin_y);
  rasterize_through_mask(rasterizer, rule, antialias, shifted, mask);
}

}  // namespace curvescan::detail
