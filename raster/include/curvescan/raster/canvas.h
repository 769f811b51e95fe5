// Canvas: an Image plus a clip rectangle, and fill(), the whole pipeline of curvescan in one call:
// path -> transform -> flatten -> Rasterizer -> spans -> source-over compositing -> pixels.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/curves/point.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/layer.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/rasterizer.h"
#include "curvescan/raster/stroke.h"
#include "curvescan/status.h"

namespace curvescan {

struct FillOptions {
  /// Flattening tolerance in device pixels: Hausdorff distance between curve and polyline (flatten.h).
  double tolerance = kDefaultFlattenTolerance;
  Antialias antialias = Antialias::kExact;
};

class Canvas {
 public:
  /// A transparent width x height canvas; kLimitExceeded beyond limits.h, kInvalidArgument if empty.
  /// Its render budgets are unlimited (RenderLimits::unlimited()).
  [[nodiscard]] static Result<Canvas> create(int width, int height);
  /// The same with the budgets of one render (limits.h): kLimitExceeded, before the image is allocated,
  /// when the image alone exceeds limits.max_memory_bytes.
  [[nodiscard]] static Result<Canvas> create(int width, int height, const RenderLimits& limits);
  /// Draws on an existing image (premultiplied RGBA8), taking ownership. The clip is the whole image.
  explicit Canvas(Image image);
  /// Moving or destroying a canvas first finishes the fills still being drawn (set_threads).
  Canvas(Canvas&&) noexcept = default;
  Canvas& operator=(Canvas&&) noexcept = default;
  ~Canvas();

  [[nodiscard]] int width() const noexcept { return image_.width(); }
  [[nodiscard]] int height() const noexcept { return image_.height(); }
  /// The image, once every fill so far is drawn (with threads, fills finish in the background).
  [[nodiscard]] const Image& image() const;
  /// Gives the image away, once every fill so far is drawn; the canvas is left empty.
  [[nodiscard]] Image take_image() &&;
  /// Waits until every fill so far is drawn. With more than one thread (set_threads) a fill may return
  /// before its pixels are written; an exception thrown while drawing it (std::bad_alloc) is rethrown here,
  /// or by the next call that draws. Every other call that reads or changes pixels, layers or clips
  /// finishes first.
  void finish();

  /// Sets every pixel of the image (ignoring the clip) to the paint's premultiplied colour.
  void clear(const Paint& paint);

  /// Restricts drawing to `rect` intersected with the image; an empty intersection draws nothing.
  void set_clip(IntRect rect) noexcept;
  void reset_clip() noexcept { clip_ = {0, 0, width(), height()}; }
  [[nodiscard]] IntRect clip() const noexcept { return clip_; }

  /// Fills `path` (user space) mapped by `transform` (user -> device pixels) with `paint`, source-over
  /// (paint.h). Open contours are closed implicitly, as SVG and Cairo fill them. Fails, drawing nothing,
  /// when the transform is not finite or overflows a point (Path::transformed) or the tolerance is not a
  /// finite positive number.
  [[nodiscard]] Status fill(const Path& path, const Paint& paint, FillRule rule,
                            const Affine& transform = Affine::identity(), const FillOptions& options = {});

  /// Strokes `path` with `style` in user space, then maps the outline by `transform` and fills it nonzero
  /// (SVG 2 and Cairo: a non-uniform scale makes an elliptical pen). The user-space tolerance is
  /// options.tolerance / σ_max(transform) so the device-space error stays within options.tolerance
  /// (stroke.h). Fails, drawing nothing, as fill() and stroke_path() do.
  [[nodiscard]] Status stroke(const Path& path, const Paint& paint, const StrokeStyle& style,
                              const Affine& transform = Affine::identity(), const FillOptions& options = {});

  /// Strokes `path` mapped by `transform` in device space: the width, dashes and joins are device pixels
  /// whatever the transform (SVG 2 vector-effect: non-scaling-stroke), while the paint is still mapped by
  /// `transform` as in stroke(). Fails, drawing nothing, as stroke() does.
  [[nodiscard]] Status stroke_in_device_space(const Path& path, const Paint& paint, const StrokeStyle& style,
                                              const Affine& transform, const FillOptions& options = {});

  // Layers and clip masks (docs/paint.md). fill() draws into the innermost layer, through the clip masks
  // pushed at that layer's level; clip() and clear() keep addressing the canvas image as above.

  /// Starts a group (SVG group opacity): later drawing goes into a transparent layer covering what can be
  /// drawn now (layer.h) until pop_layer(). kLimitExceeded beyond kMaxLayerDepth (limits.h).
  [[nodiscard]] Status push_layer();
  /// Ends the innermost group: composites its layer source-over onto what lies under it with `opacity`
  /// (clamped to [0, 1], NaN -> 0; converted as cairo_paint_with_alpha does, layer.h), through the clip
  /// masks of the enclosing level; a `mode` other than kNormal blends it (mix-blend-mode, layer.h).
  /// Fails when no layer is open or clips pushed inside it are still open.
  [[nodiscard]] Status pop_layer(double opacity, BlendMode mode = BlendMode::kNormal);
  [[nodiscard]] int layer_depth() const noexcept { return static_cast<int>(layers_.size()); }

  /// Intersects the clip with `path` (user space, mapped by `transform`, filled with `rule` and
  /// antialiased as fill() does): an SVG clipPath with its clip-rule. The clip applies to drawing in the
  /// current layer, and to the layers pushed inside it when they are composited (so it applies once).
  /// Fails as fill() does, or with kLimitExceeded beyond kMaxClipDepth (limits.h).
  [[nodiscard]] Status push_clip(const Path& path, FillRule rule, const Affine& transform = Affine::identity(),
                                 const FillOptions& options = {});
  /// Intersects the clip with a ready-made coverage mask of the canvas's size (an SVG <mask>'s luminance
  /// or alpha, ClipMask::from_values); it then acts exactly as a mask pushed by push_clip() and is
  /// removed by pop_clip(). Fails with kInvalidArgument when the sizes differ, kLimitExceeded beyond
  /// kMaxClipDepth.
  [[nodiscard]] Status push_clip_mask(ClipMask mask);
  /// Removes the innermost clip mask. Fails when there is none at the current layer level.
  [[nodiscard]] Status pop_clip();
  [[nodiscard]] int clip_depth() const noexcept { return static_cast<int>(clips_.size()); }

  // Render budgets (limits.h, docs/limits.md). fill() and stroke() refuse with kLimitExceeded, drawing
  // nothing, when the flattened segments of all drawing so far would pass limits().max_segments, the
  // edges of one fill would pass the memory left under limits().max_memory_bytes, or a stroke's dash
  // pattern would make more than limits().max_dashes dashes.

  /// How many threads drawing may use (default 1). Every fill is cut into bands at the canvas rows that
  /// are multiples of kBandRows (the cut depends on the fill alone, not on this number, so the pixels are
  /// the same whatever the thread count). With more than one thread, fill() returns once the path is
  /// flattened and its bands are queued: a pool of threads started once per canvas rasterizes and
  /// composites them, bands sharing rows in the order they were queued (band_queue.h), while the
  /// caller prepares the next path. When a fill is built, the fills still queued hold at most
  /// kMaxQueuedEdgeBytes of edges and at most half of what the memory budget leaves; these come on top
  /// of the budget, which each fill still has whole, as with one thread (so the same fills succeed).
  void set_threads(int threads) noexcept { threads_ = threads < 1 ? 1 : threads; }
  [[nodiscard]] int threads() const noexcept { return threads_; }
  static constexpr int kBandRows = 128;
  static constexpr std::int64_t kMaxQueuedEdgeBytes = std::int64_t{32} << 20;

  [[nodiscard]] const RenderLimits& limits() const noexcept { return limits_; }
  void set_limits(const RenderLimits& limits) noexcept { limits_ = limits; }
  /// Flattened segments drawn so far (fills, stroke outlines, and clip paths charged by reserve_clip()).
  [[nodiscard]] std::int64_t segments_used() const noexcept { return segments_used_; }
  /// Bytes held now: the image, every open layer and every clip mask, and the caller's held bytes.
  [[nodiscard]] std::int64_t memory_bytes() const noexcept;
  /// Memory the caller holds for this render outside the canvas, counted in memory_bytes() against
  /// limits().max_memory_bytes (the text command's glyph outlines, which fill() copies once more).
  void set_held_memory_bytes(std::int64_t bytes) noexcept { held_memory_bytes_ = bytes; }
  [[nodiscard]] std::int64_t held_memory_bytes() const noexcept { return held_memory_bytes_; }
  /// Whether push_layer() now stays within limits().max_memory_bytes; kLimitExceeded otherwise.
  [[nodiscard]] Status reserve_layer() const;
  /// Whether push_clip(path, ...) now stays within the budgets: charges the clip path's flattened
  /// segments (counted by flattening it once) and checks the mask's memory; kLimitExceeded otherwise.
  [[nodiscard]] Status reserve_clip(const Path& path, const Affine& transform = Affine::identity(),
                                    const FillOptions& options = {});

 private:
  /// Adds the edges of `device` to rasterizer_ within the budgets, charging segments_used_.
  [[nodiscard]] Status add_edges_within_budget(const Path& device, double tolerance);
  /// fill() of a path already in device space, its paint mapped by `paint_transform`.
  [[nodiscard]] Status fill_device_path(const Path& device_path, const Paint& paint, FillRule rule,
                                        const Affine& paint_transform, const FillOptions& options);
  /// stroke_path() of `path` within the segment budget left, with an error naming the budget when it binds.
  /// Dashes are made and counted only where they can reach `visible` (the drawing area in the path's
  /// coordinates; stroke.h).
  [[nodiscard]] Result<Path> stroke_outline_within_budget(const Path& path, const StrokeStyle& style,
                                                          double tolerance, const Rect& visible);
  /// kLimitExceeded when a stroke of `path` with `style` (user space) makes more than max_dashes dashes
  /// where they can reach `visible`.
  [[nodiscard]] Status check_dash_count(const Path& path, const StrokeStyle& style, double user_tolerance,
                                        const Rect& visible);
  /// The drawing area as a box in the coordinates `transform` maps to the device (the bounding box of its
  /// corners mapped back), or an infinite box when `transform` has no inverse.
  [[nodiscard]] Rect drawing_area_in(const Affine& transform) const noexcept;

  /// Owns the band queue (set_threads). Moving it first finishes the queued bands, which point into the
  /// images of this canvas; so it is the first member, moved before them.
  struct DrawQueue;  // the band queue of band_queue.h
  struct QueueOwner {
    QueueOwner() = default;
    QueueOwner(QueueOwner&& other) noexcept;
    QueueOwner& operator=(QueueOwner&& other) noexcept;
    ~QueueOwner();
    DrawQueue* queue = nullptr;
  };
  QueueOwner queue_;
  /// Finishes the queued bands (when any) before pixels, layers or clips are read or changed.
  void finish_queued() const;

  Image image_;
  IntRect clip_;
  Rasterizer rasterizer_;
  std::vector<Rasterizer> band_rasterizers_;  // the bands of a fill below its first, while it is cut
  std::vector<int> band_cuts_;                // the rows it is cut at
  int threads_ = 1;
  std::vector<Point> polyline_;  // flattener output, reused between segments and fills
  /// Cuts the fill in rasterizer_, reaching rows [first, last), at the multiples of kBandRows inside
  /// them (set_threads): returns how many bands, the first staying in rasterizer_, the others in
  /// band_rasterizers_.
  std::size_t cut_into_bands(int first, int last);

  struct ClipEntry {
    ClipMask mask;    // the product of every clip pushed at the same layer level, this one included
    int layer_level;  // layer_depth() when it was pushed
  };
  /// clip_ ∩ the innermost layer's bounds ∩ every clip mask's bounds: where drawing can change a pixel.
  [[nodiscard]] IntRect drawing_area() const noexcept;
  /// The clip mask fill() draws through at the current level, or null.
  [[nodiscard]] const ClipMask* current_mask() const noexcept;
  std::vector<Layer> layers_;
  std::vector<ClipEntry> clips_;
  RenderLimits limits_ = RenderLimits::unlimited();
  std::int64_t segments_used_ = 0;
  std::int64_t held_memory_bytes_ = 0;
  /// The pad-gradient colour tables kept between fills (gradient_table_cache.h); created by the first
  /// gradient fill.
  struct GradientTables;  // detail::GradientTableCache
  std::shared_ptr<GradientTables> gradient_tables_;
};

}  // namespace curvescan
