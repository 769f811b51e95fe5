// Canvas: clip bookkeeping and fill(), after plutovg's ten-line canvas_fill: transform, build edges,
// rasterize into a span sink that composites (solid_span_compositor.h).
#include "curvescan/raster/canvas.h"

#include <algorithm>
#include <cmath>

#include "curvescan/raster/limits.h"
#include "curvescan/raster/stroke.h"
#include "paint_dispatch.h"
#include "path_edges.h"
#include "solid_span_compositor.h"

namespace curvescan {

Result<Canvas> Canvas::create(int width, int height) {
  if (width < 1 || height < 1) {
    return Error{ErrorKind::kInvalidArgument, "a canvas needs a positive width and height, not " +
                                                  std::to_string(width) + " x " + std::to_string(height)};
  }
  if (!image_size_within_limits(width, height)) {
    return Error{ErrorKind::kLimitExceeded, "a " + std::to_string(width) + " x " + std::to_string(height) +
                                                " canvas exceeds the image size limit (limits.h)"};
  }
  return Canvas(Image(width, height));
}

Canvas::Canvas(Image image) : image_(std::move(image)), clip_{0, 0, image_.width(), image_.height()} {}

void Canvas::clear(const Paint& paint) noexcept {
  std::fill(image_.pixels().begin(), image_.pixels().end(), paint.color);
}

void Canvas::set_clip(IntRect rect) noexcept {
  clip_ = {std::max(rect.x0, 0), std::max(rect.y0, 0), std::min(rect.x1, width()),
           std::min(rect.y1, height())};
  if (clip_.empty()) clip_ = {};
}

Status Canvas::fill(const Path& path, const Paint& paint, FillRule rule, const Affine& transform,
                    const FillOptions& options) {
  if (!(std::isfinite(options.tolerance) && options.tolerance > 0.0)) {
    return Status::invalid("the flattening tolerance must be a finite positive number of pixels");
  }
  const Result<Path> device = path.transformed(transform);
  if (!device) return device.error();
  const IntRect area = drawing_area();  // clip_ when no layer or mask is in use
  if (area.empty() || device->empty()) return Status::ok();
  rasterizer_.reset(area);
  detail::add_path_edges(*device, options.tolerance, rasterizer_, polyline_);
  const ClipMask* mask = current_mask();
  if (layers_.empty() && mask == nullptr && paint.gradient == nullptr) {
    detail::SolidSpanCompositor compositor(image_, paint.color);
    rasterizer_.rasterize(rule, options.antialias, compositor);
    return Status::ok();
  }
  // Gradients, layers (layer_stack.cpp) and clip masks: paint_dispatch.h.
  Image& target = layers_.empty() ? image_ : layers_.back().pixels;
  const IntRect origin = layers_.empty() ? IntRect{} : layers_.back().bounds;
  detail::rasterize_with_paint(rasterizer_, rule, options.antialias, paint, transform, target, origin.x0, origin.y0,
                               mask);
  return Status::ok();
}

Status Canvas::stroke(const Path& path, const Paint& paint, const StrokeStyle& style, const Affine& transform,
                      const FillOptions& options) {
  if (!transform.is_finite()) return Status::invalid("the stroke transform is not finite");
  const double user_tolerance = stroke_user_tolerance(transform, options.tolerance);
  if (std::isinf(user_tolerance) && options.tolerance > 0.0) return Status::ok();  // maps to one point
  const Result<Path> outline = stroke_path(path, style, user_tolerance);
  if (!outline) return outline.error();
  return fill(*outline, paint, FillRule::kNonZero, transform, options);
}

}  // namespace curvescan
