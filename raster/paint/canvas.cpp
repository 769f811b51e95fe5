// Canvas: clip bookkeeping and fill(), after plutovg's ten-line canvas_fill: transform, build edges,
// rasterize into a span sink that composites (solid_span_compositor.h).
#include "curvescan/raster/canvas.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <utility>

#include "band_queue.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/stroke.h"
#include "gradient_color_table.h"
#include "gradient_table_cache.h"
#include "paint_dispatch.h"
#include "path_edges.h"
#include "pixel_fill.h"
#include "segment_in_box.h"
#include "solid_span_compositor.h"
#include "stroke_reach.h"

namespace curvescan {
namespace {

constexpr std::int64_t kMiB = std::int64_t{1} << 20;

std::string mib_text(std::int64_t bytes) {
  return std::to_string((bytes + kMiB - 1) / kMiB) + " MiB";
}

Error memory_limit_error(const std::string& what, std::int64_t needed, std::int64_t limit) {
  return Error{ErrorKind::kLimitExceeded, what + " needs " + mib_text(needed) +
                                              ", beyond the memory limit of " + mib_text(limit) +
                                              " per render (raise --max-memory)"};
}

}  // namespace

struct Canvas::DrawQueue : detail::BandQueue {};

Result<Canvas> Canvas::create(int width, int height, const RenderLimits& limits) {
  if (width >= 1 && height >= 1 && image_size_within_limits(width, height)) {
    const std::int64_t bytes = image_memory_bytes(width, height);
    if (bytes > limits.max_memory_bytes) {
      return memory_limit_error("a " + std::to_string(width) + " x " + std::to_string(height) + " canvas",
                                bytes, limits.max_memory_bytes);
    }
  }
  Result<Canvas> canvas = create(width, height);
  if (canvas) canvas->set_limits(limits);
  return canvas;
}

Result<Canvas> Canvas::create(int width, int height) {
  if (width < 1 || height < 1) {
    return Error{ErrorKind::kInvalidArgument, "a canvas needs a positive width and height, not " +
                                                  std::to_string(width) + " x " + std::to_string(height)};
  }
  if (!image_size_within_limits(width, height)) {
    return Error{ErrorKind::kLimitExceeded, "a " + std::to_string(width) + " x " + std::to_string(height) +
                                                " canvas exceeds the image size limit (" +
                                                std::to_string(kMaxImageDimension) + " pixels per side, " +
                                                std::to_string(kMaxImagePixels) + " in all)"};
  }
  return Canvas(Image(width, height));
}

struct Canvas::GradientTables : detail::GradientTableCache {};

Canvas::Canvas(Image image) : image_(std::move(image)), clip_{0, 0, image_.width(), image_.height()} {}

void Canvas::clear(const Paint& paint) {
  finish_queued();
  detail::fill_pixels(image_.pixels().data(), image_.pixels().size(), paint.color);
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
  // The identity maps every (finite) point to itself and the bounds to themselves: the path is already in
  // device space, so no copy (a copy and a pass over the points were 6 % of a small circle's fill).
  if (transform == Affine::identity()) return fill_device_path(path, paint, rule, transform, options);
  const Result<Path> device = path.transformed(transform);
  if (!device) return device.error();
  return fill_device_path(*device, paint, rule, transform, options);
}

Status Canvas::fill_device_path(const Path& device_path, const Paint& paint, FillRule rule,
                                const Affine& paint_transform, const FillOptions& options) {
  const IntRect area = drawing_area();  // clip_ when no layer or mask is in use
  if (area.empty() || device_path.empty()) return Status::ok();
  // Queued fills keep their edges until drawn: at most half of what the budget leaves (or
  // kMaxQueuedEdgeBytes), so the fill built now still has the rest, as much as without threads.
  const std::int64_t memory_left = std::max<std::int64_t>(0, limits_.max_memory_bytes - memory_bytes());
  const auto max_queued_edges =
      static_cast<std::size_t>(std::min(kMaxQueuedEdgeBytes, memory_left / 2) / kRenderBytesPerEdge);
  if (threads_ > 1 && !queue_.queue) queue_.queue = new DrawQueue;
  rasterizer_.reset(area);
  CURVESCAN_PROPAGATE(add_edges_within_budget(device_path, options.tolerance));
  const auto [first_row, last_row] = rasterizer_.edge_rows();
  const std::size_t bands = cut_into_bands(first_row, last_row);
  const IntRect origin = layers_.empty() ? IntRect{} : layers_.back().bounds;
  Image* const target = layers_.empty() ? &image_ : &layers_.back().pixels;
  const ClipMask* const mask = current_mask();
  // The bands share one pad-gradient colour table, kept for the later fills of the same gradient.
  std::shared_ptr<detail::GradientTableSlot> gradient_table;
  if (paint.gradient != nullptr) {
    if (gradient_tables_ == nullptr) gradient_tables_ = std::make_shared<GradientTables>();
    gradient_table = gradient_tables_->slot_for(
        paint.gradient, memory_bytes() + detail::PadColorTable::kBytes <= limits_.max_memory_bytes);
  }
  const auto band = [&](std::size_t i) -> Rasterizer& { return i == 0 ? rasterizer_ : band_rasterizers_[i - 1]; };
  if (threads_ <= 1) {
    // One thread: each band drawn now, in order, into rows the next band does not touch (nothing is
    // shared with a queue, so nothing is allocated: a fill's fixed cost matters for many small shapes).
    finish_queued();  // fills queued before set_threads(1)
    for (std::size_t i = 0; i < bands; ++i) {
      detail::rasterize_with_paint(band(i), rule, options.antialias, paint, paint_transform, *target,
                                   origin.x0, origin.y0, mask, gradient_table);
    }
    return Status::ok();
  }
  auto shared = std::make_shared<detail::BandPaint>();
  shared->rule = rule;
  shared->antialias = options.antialias;
  shared->paint = paint;
  shared->transform = paint_transform;
  shared->target = target;
  shared->origin_x = origin.x0;
  shared->origin_y = origin.y0;
  shared->mask = mask;
  shared->gradient_table = std::move(gradient_table);
  // Queued: each band's edges move to a job (swapped with a spare rasterizer, whose buffers the next
  // fill reuses).
  const std::vector<int>& cuts = band_cuts_;
  std::vector<detail::BandJob> jobs(bands);
  for (std::size_t i = 0; i < bands; ++i) {
    jobs[i].row0 = i == 0 ? first_row : cuts[i - 1];
    jobs[i].row1 = i + 1 < bands ? cuts[i] : last_row;
    jobs[i].rasterizer = queue_.queue->take_spare();
    std::swap(jobs[i].rasterizer, band(i));
    jobs[i].paint = shared;
  }
  queue_.queue->submit(jobs, threads_, max_queued_edges);
  return Status::ok();
}

std::size_t Canvas::cut_into_bands(int first, int last) {
  band_cuts_.clear();
  for (int y = (first / kBandRows + 1) * kBandRows; y < last; y += kBandRows) band_cuts_.push_back(y);
  if (band_cuts_.empty()) return 1;
  if (band_rasterizers_.size() < band_cuts_.size()) band_rasterizers_.resize(band_cuts_.size());
  rasterizer_.split_at_rows(band_cuts_, std::span<Rasterizer>(band_rasterizers_).first(band_cuts_.size()));
  return band_cuts_.size() + 1;
}

Canvas::QueueOwner::QueueOwner(QueueOwner&& other) noexcept : queue(std::exchange(other.queue, nullptr)) {
  if (queue) queue->finish_quietly();
}

Canvas::QueueOwner& Canvas::QueueOwner::operator=(QueueOwner&& other) noexcept {
  if (this != &other) {
    delete queue;  // finishes its bands
    queue = std::exchange(other.queue, nullptr);
    if (queue) queue->finish_quietly();
  }
  return *this;
}

Canvas::QueueOwner::~QueueOwner() {
  delete queue;
}

Canvas::~Canvas() {
  // Before the images the queued bands draw into are destroyed.
  if (queue_.queue) queue_.queue->finish_quietly();
}

void Canvas::finish_queued() const {
  if (queue_.queue) queue_.queue->finish();
}

void Canvas::finish() {
  finish_queued();
}

const Image& Canvas::image() const {
  finish_queued();
  return image_;
}

Image Canvas::take_image() && {
  finish_queued();
  return std::move(image_);
}

Status Canvas::stroke(const Path& path, const Paint& paint, const StrokeStyle& style, const Affine& transform,
                      const FillOptions& options) {
  if (!transform.is_finite()) return Status::invalid("the stroke transform is not finite");
  const double user_tolerance = stroke_user_tolerance(transform, options.tolerance);
  if (std::isinf(user_tolerance) && options.tolerance > 0.0) return Status::ok();  // maps to one point
  const Result<Path> outline =
      stroke_outline_within_budget(path, style, user_tolerance, drawing_area_in(transform));
  if (!outline) return outline.error();
  return fill(*outline, paint, FillRule::kNonZero, transform, options);
}

Status Canvas::stroke_in_device_space(const Path& path, const Paint& paint, const StrokeStyle& style,
                                      const Affine& transform, const FillOptions& options) {
  if (!transform.is_finite()) return Status::invalid("the stroke transform is not finite");
  if (!(std::isfinite(options.tolerance) && options.tolerance > 0.0)) {
    return Status::invalid("the flattening tolerance must be a finite positive number of pixels");
  }
  const Result<Path> device = path.transformed(transform);
  if (!device) return device.error();
  const Result<Path> outline =
      stroke_outline_within_budget(*device, style, options.tolerance, drawing_area_in(Affine::identity()));
  if (!outline) return outline.error();
  return fill_device_path(*outline, paint, FillRule::kNonZero, transform, options);
}

Result<Path> Canvas::stroke_outline_within_budget(const Path& path, const StrokeStyle& style,
                                                  double tolerance, const Rect& visible) {
  CURVESCAN_PROPAGATE(check_dash_count(path, style, tolerance, visible));
  // The outline's points become this render's segments when it is filled, so the stroker may not make more
  // than the segment budget has left: a stroke far too fine for its transform stops early, in the stroker,
  // instead of building millions of points that fill() would refuse anyway.
  const std::int64_t segments_left = std::max<std::int64_t>(0, limits_.max_segments - segments_used_);
  const bool render_budget_binds = segments_left < kMaxStrokeOutlinePoints;
  Result<Path> outline =
      stroke_path(path, style, tolerance, std::min(segments_left, kMaxStrokeOutlinePoints), visible);
  if (!outline && outline.error().kind == ErrorKind::kLimitExceeded && render_budget_binds) {
    return Error{ErrorKind::kLimitExceeded,
                 "the stroke outline needs more than the " + std::to_string(segments_left) +
                     " line segments left of the segment limit per render (" +
                     std::to_string(limits_.max_segments) + "; raise --max-segments)"};
  }
  return outline;
}

std::int64_t Canvas::memory_bytes() const noexcept {
  const auto image_bytes = [](const Image& image) {
    return image_memory_bytes(image.width(), image.height());
  };
  std::int64_t bytes = image_bytes(image_) + held_memory_bytes_;
  for (const Layer& layer : layers_) bytes += image_bytes(layer.pixels);
  for (const ClipEntry& clip : clips_) bytes += std::int64_t{clip.mask.width()} * clip.mask.height();
  if (gradient_tables_ != nullptr) bytes += gradient_tables_->memory_bytes();
  return bytes;
}

Status Canvas::add_edges_within_budget(const Path& device, double tolerance) {
  // The edges of this fill may use what the pixels leave of the memory budget (kRenderBytesPerEdge each,
  // limits.h) and what earlier drawing left of the segment budget, whichever is smaller.
  const std::int64_t segments_left = std::max<std::int64_t>(0, limits_.max_segments - segments_used_);
  const std::int64_t memory_left = std::max<std::int64_t>(0, limits_.max_memory_bytes - memory_bytes());
  const std::int64_t edges_in_memory = memory_left / kRenderBytesPerEdge;
  const std::int64_t max_edges = std::min(segments_left, edges_in_memory);
  const std::size_t added =
      detail::add_path_edges(device, tolerance, rasterizer_, polyline_, static_cast<std::size_t>(max_edges));
  if (added <= static_cast<std::size_t>(max_edges)) {
    segments_used_ += static_cast<std::int64_t>(added);
    return Status::ok();
  }
  rasterizer_.reset({});  // drop the partial edges: nothing of this fill is drawn
  if (segments_left <= edges_in_memory) {
    return Error{ErrorKind::kLimitExceeded,
                 "the drawing flattens to more than " + std::to_string(limits_.max_segments) +
                     " line segments, the segment limit per render (raise --max-segments)"};
  }
  return memory_limit_error("a fill of more than " + std::to_string(max_edges) + " edges",
                            memory_bytes() + (max_edges + 1) * kRenderBytesPerEdge, limits_.max_memory_bytes);
}

Status Canvas::reserve_layer() const {
  // push_layer() allocates an RGBA8 image of the drawing area (layer_stack.cpp).
  const IntRect area = drawing_area();
  const std::int64_t layer = area.empty() ? 0 : image_memory_bytes(area.x1 - area.x0, area.y1 - area.y0);
  if (memory_bytes() + layer > limits_.max_memory_bytes) {
    return memory_limit_error("an opacity layer", memory_bytes() + layer, limits_.max_memory_bytes);
  }
  return Status::ok();
}

Status Canvas::reserve_clip(const Path& path, const Affine& transform, const FillOptions& options) {
  // push_clip() allocates a one-byte mask of the whole canvas (layer_stack.cpp) and rasterizes the path.
  const std::int64_t mask = std::int64_t{width()} * height();
  if (memory_bytes() + mask > limits_.max_memory_bytes) {
    return memory_limit_error("a clip mask", memory_bytes() + mask, limits_.max_memory_bytes);
  }
  if (!(std::isfinite(options.tolerance) && options.tolerance > 0.0))
    return Status::ok();  // push_clip refuses
  const Result<Path> device = path.transformed(transform);
  if (!device || device->empty()) return Status::ok();
  rasterizer_.reset({0, 0, width(), height()});
  const Status counted = add_edges_within_budget(*device, options.tolerance);
  rasterizer_.reset({});
  return counted;
}

Rect Canvas::drawing_area_in(const Affine& transform) const noexcept {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  const IntRect area = drawing_area();
  const std::optional<Affine> inverse = transform.inverse();
  if (!inverse) return {-kInfinity, -kInfinity, kInfinity, kInfinity};
  Rect box =
      Rect::from_point(inverse->apply(Point{static_cast<double>(area.x0), static_cast<double>(area.y0)}));
  box.include(inverse->apply(Point{static_cast<double>(area.x1), static_cast<double>(area.y0)}));
  box.include(inverse->apply(Point{static_cast<double>(area.x0), static_cast<double>(area.y1)}));
  box.include(inverse->apply(Point{static_cast<double>(area.x1), static_cast<double>(area.y1)}));
  return box;
}

Status Canvas::check_dash_count(const Path& path, const StrokeStyle& style, double user_tolerance,
                                const Rect& visible) {
  if (!dash_is_active(style.dash_array) || !validate_dash(style.dash_array, style.dash_offset)) {
    return Status::ok();  // solid, or stroke_path() reports the invalid pattern
  }
  if (!(std::isfinite(user_tolerance) && user_tolerance > 0.0)) return Status::ok();
  // As the dasher counts (dasher.cpp): an odd array is repeated; each period makes entries / 2 dashes,
  // plus one per contour; lengths along the polyline flattened within the stroke's tolerance.
  double period = 0.0;
  for (const double length : style.dash_array) period += length;
  double dashes_per_period = static_cast<double>(style.dash_array.size()) / 2.0;
  if (style.dash_array.size() % 2 == 1) {
    period *= 2.0;
    dashes_per_period = static_cast<double>(style.dash_array.size());
  }
  // Only the length where dashes can reach the drawing area counts (stroke_reach.h); a box that is not
  // finite counts everything, as the stroker then culls nothing.
  std::optional<Rect> cull;
  if (visible.is_finite()) cull = detail::dash_cull_box(visible, style, user_tolerance);
  if (cull && !cull->is_finite()) cull.reset();
  const auto counted_length = [&cull](Point a, Point b) {
    if (!cull) return a.distance(b);
    const std::optional<detail::SegmentSpan> inside = detail::segment_in_box(a, b, *cull);
    return inside ? (inside->t1 - inside->t0) * a.distance(b) : 0.0;
  };
  double expected = 0.0, contour_length = 0.0;
  bool in_contour = false;
  const auto end_contour = [&] {
    if (in_contour) expected += std::floor(contour_length / period) * dashes_per_period + 1.0;
    contour_length = 0.0;
  };
  for (const PathElement& element : path) {
    if (element.verb == PathVerb::kMove) {
      end_contour();
      in_contour = true;
      continue;
    }
    if (element.verb == PathVerb::kLine || element.verb == PathVerb::kClose) {
      contour_length += counted_length(element.start, element.end);
      continue;
    }
    // An estimate only (the dasher's own counter enforces the limit exactly), so the curve is flattened to
    // 1/1000 of its control polygon's length at most: a handful of segments whatever the stroke tolerance,
    // where the full tolerance could cost millions on a huge curve (fuzz regression
    // raster_stroke/dash_count_estimate_flattened_finely_timeout). The polyline's length is then within
    // about 1e-3 relative of the curve's. Wang's bound (flatten.cpp: every second difference is at most the
    // polygon's length) puts a polynomial curve of degree n within that tolerance in sqrt(n(n-1)/8 / 1e-3)
    // < 11.2·n equal steps, 717 for the largest degree (64), and the adaptive walk needs no more than
    // about that; the cap of 2^12 bounds the rest (rational curves whose weights crowd the parameter):
    // past it the polyline ends with a chord, which only shortens the estimate.
    constexpr std::size_t kMaxEstimateSegments = std::size_t{1} << 12;
    double polygon_length = 0.0;
    for (std::size_t i = 1; i < element.points.size(); ++i) {
      polygon_length += element.points[i - 1].distance(element.points[i]);
    }
    const double estimate_tolerance = std::max(user_tolerance, 1e-3 * polygon_length);
    if (!std::isfinite(estimate_tolerance)) continue;
    polyline_.clear();
    const FlattenOutcome outcome =
        element.is_rational()
            ? flatten_rational(element.points, element.weights, estimate_tolerance, polyline_,
                               kMaxEstimateSegments)
            : flatten_bezier(element.points, estimate_tolerance, polyline_, kMaxEstimateSegments);
    if (outcome != FlattenOutcome::kOk && outcome != FlattenOutcome::kSegmentLimit) continue;
    Point previous = element.start;
    for (const Point p : polyline_) {
      contour_length += counted_length(previous, p);
      previous = p;
    }
  }
  end_contour();
  if (!(expected <= static_cast<double>(limits_.max_dashes))) {
    return Error{ErrorKind::kLimitExceeded, "the dash pattern would cut the path into more than " +
                                                std::to_string(limits_.max_dashes) +
                                                " dashes, the dash limit per stroke (raise --max-dashes)"};
  }
  return Status::ok();
}

}  // namespace curvescan
