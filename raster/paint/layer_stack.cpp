// Canvas layers and clip masks: the stacks behind push_layer/pop_layer and push_clip/pop_clip (canvas.h).
//
// Every clip mask remembers the layer level it was pushed at. fill() draws through the innermost mask
// only when it belongs to the current level; masks of enclosing levels are applied when the layers
// inside them are composited (pop_layer). So a clip around a group is applied once, to the group's
// result, as SVG 1.1 section 14.3.5 describes (clipping the group as a whole); drawing the group's
// contents through it too would apply an antialiased edge twice (coverage squared), which is what
// cairo_clip + cairo_push_group does (docs/paint.md).
#include <algorithm>
#include <cmath>
#include <string>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/limits.h"
#include "masked_span_sink.h"
#include "path_edges.h"

namespace curvescan {
namespace {

IntRect intersection(IntRect a, IntRect b) noexcept {
  const IntRect both{std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
  return both.empty() ? IntRect{} : both;
}

}  // namespace

IntRect Canvas::drawing_area() const noexcept {
  IntRect area = clip_;
  if (!layers_.empty()) area = intersection(area, layers_.back().bounds);
  for (const ClipEntry& clip : clips_) area = intersection(area, clip.mask.bounds());
  return area;
}

const ClipMask* Canvas::current_mask() const noexcept {
  if (clips_.empty() || clips_.back().layer_level != layer_depth()) return nullptr;
  return &clips_.back().mask;
}

Status Canvas::push_layer() {
  finish_queued();  // queued bands point into the layers
  if (layer_depth() >= kMaxLayerDepth) {
    return Error{ErrorKind::kLimitExceeded,
                 "layers nest deeper than " + std::to_string(kMaxLayerDepth) + " levels"};
  }
  const IntRect bounds = drawing_area();
  Layer layer{bounds.empty() ? Image() : Image(bounds.x1 - bounds.x0, bounds.y1 - bounds.y0), bounds};
  layers_.push_back(std::move(layer));
  return Status::ok();
}

Status Canvas::pop_layer(double opacity, BlendMode mode) {
  finish_queued();  // queued bands point into the layers
  if (layers_.empty()) return Status::invalid("pop_layer() without a matching push_layer()");
  if (!clips_.empty() && clips_.back().layer_level == layer_depth()) {
    return Status::invalid(
        "pop_layer() while a clip pushed inside the layer is still open (pop_clip() first)");
  }
  const Layer layer = std::move(layers_.back());
  layers_.pop_back();
  Image& target = layers_.empty() ? image_ : layers_.back().pixels;
  const IntRect origin = layers_.empty() ? IntRect{} : layers_.back().bounds;
  composite_layer(target, origin.x0, origin.y0, layer, layer_alpha(opacity), current_mask(), mode);
  return Status::ok();
}

Status Canvas::push_clip(const Path& path, FillRule rule, const Affine& transform,
                         const FillOptions& options) {
  finish_queued();  // queued bands point into the clip masks
  if (!(std::isfinite(options.tolerance) && options.tolerance > 0.0)) {
    return Status::invalid("the flattening tolerance must be a finite positive number of pixels");
  }
  if (clip_depth() >= kMaxClipDepth) {
    return Error{ErrorKind::kLimitExceeded,
                 "clips nest deeper than " + std::to_string(kMaxClipDepth) + " levels"};
  }
  const Result<Path> device = path.transformed(transform);
  if (!device) return device.error();
  // The whole canvas (not the clip rectangle, which may later grow), limited to where anything can
  // still show through the layer and the masks already pushed.
  IntRect area{0, 0, width(), height()};
  if (!layers_.empty()) area = intersection(area, layers_.back().bounds);
  for (const ClipEntry& clip : clips_) area = intersection(area, clip.mask.bounds());
  ClipEntry entry{ClipMask(width(), height()), layer_depth()};
  if (!area.empty() && !device->empty()) {
    rasterizer_.reset(area);
    // Not charged here (reserve_clip() charges a clip against what is left of the budget), but bounded by
    // the whole segment budget: no render can draw a clip that flattens to more, and without a bound one
    // curve of the clip path was flattened to the 2^22-segment cap whatever the budget.
    const auto max_edges = static_cast<std::size_t>(std::max<std::int64_t>(0, limits_.max_segments));
    if (detail::add_path_edges(*device, options.tolerance, rasterizer_, polyline_, max_edges) > max_edges) {
      rasterizer_.reset({});
      return Error{ErrorKind::kLimitExceeded,
                   "the clip path flattens to more than " + std::to_string(limits_.max_segments) +
                       " line segments, the segment limit per render (raise --max-segments)"};
    }
    detail::ClipMaskWriter writer(entry.mask);
    rasterizer_.rasterize(rule, options.antialias, writer);
  }
  if (const ClipMask* enclosing = current_mask(); enclosing != nullptr) entry.mask.intersect(*enclosing);
  clips_.push_back(std::move(entry));
  return Status::ok();
}

Status Canvas::push_clip_mask(ClipMask mask) {
  finish_queued();  // queued bands point into the clip masks
  if (mask.width() != width() || mask.height() != height())
    return Status::invalid("push_clip_mask() needs a mask of the canvas's size");
  if (clip_depth() >= kMaxClipDepth) {
    return Error{ErrorKind::kLimitExceeded,
                 "clips nest deeper than " + std::to_string(kMaxClipDepth) + " levels"};
  }
  if (const ClipMask* enclosing = current_mask(); enclosing != nullptr) mask.intersect(*enclosing);
  clips_.push_back(ClipEntry{std::move(mask), layer_depth()});
  return Status::ok();
}

Status Canvas::pop_clip() {
  finish_queued();  // queued bands point into the clip masks
  if (clips_.empty() || clips_.back().layer_level != layer_depth()) {
    return Status::invalid("pop_clip() without a matching push_clip() in the current layer");
  }
  clips_.pop_back();
  return Status::ok();
}

}  // namespace curvescan
