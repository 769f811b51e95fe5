// Canvas: an Image plus a clip rectangle, and fill(), the whole pipeline of curvescan in one call:
// path -> transform -> flatten -> Rasterizer -> spans -> source-over compositing -> pixels.
#pragma once

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

  [[nodiscard]] int width() const noexcept { return image_.width(); }
  [[nodiscard]] int height() const noexcept { return image_.height(); }
  [[nodiscard]] const Image& image() const noexcept { return image_; }
  /// Gives the image away; the canvas is left empty.
  [[nodiscard]] Image take_image() && noexcept { return std::move(image_); }

  /// Sets every pixel of the image (ignoring the clip) to the paint's premultiplied colour.
  void clear(const Paint& paint) noexcept;

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

  /// How many threads a fill may use (default 1). A fill reaching kBandRows rows or more is always cut
  /// into bands of about that many rows (the cut depends on the fill, not on this number, so the pixels
  /// are the same whatever the thread count); with more than one thread the bands are rasterized and
  /// composited in parallel, each into its own rows.
  void set_threads(int threads) noexcept { threads_ = threads < 1 ? 1 : threads; }
  [[nodiscard]] int threads() const noexcept { return threads_; }
  static constexpr int kBandRows = 256;

  [[nodiscard]] const RenderLimits& limits() const noexcept { return limits_; }
  void set_limits(const RenderLimits& limits) noexcept { limits_ = limits; }
  /// Flattened segments drawn so far (fills, stroke outlines, and clip paths charged by reserve_clip()).
  [[nodiscard]] std::int64_t segments_used() const noexcept { return segments_used_; }
  /// Bytes held now: the image, every open layer and every clip mask, and the caller's held bytes.
  [[nodiscard]] std::int64_t memory_bytes() const noexcept;
  /// Memory the caller holds for this render outside the canvas, counted in memory_bytes() against
  /// limits().max_memory_bytes (the text command's glyph outlines, which fill() copies once more).
  void set_held_memory_bytes(std::int64_t bytes) noexcept { held_memory_bytes_ = bytes; }
  /// Whether push_layer() now stays within limits().max_memory_bytes; kLimitExceeded otherwise.
  [[nodiscard]] Status reserve_layer() const;
  /// Whether push_clip(path, ...) now stays within the budgets: charges the clip path's flattened
  /// segments (counted by flattening it once) and checks the mask's memory; kLimitExceeded otherwise.
  [[nodiscard]] Status reserve_clip(const Path& path, const Affine& transform = Affine::identity(),
                                    const FillOptions& options = {});

 private:
  /// Adds the edges of `device` to rasterizer_ within the budgets, charging segments_used_.
  [[nodiscard]] Status add_edges_within_budget(const Path& device, double tolerance);
  /// kLimitExceeded when a stroke of `path` with `style` (user space) makes more than max_dashes dashes.
  [[nodiscard]] Status check_dash_count(const Path& path, const StrokeStyle& style, double user_tolerance);

  Image image_;
  IntRect clip_;
  Rasterizer rasterizer_;
  std::vector<Rasterizer> band_rasterizers_;  // the bands below the first of a fill cut into bands
  int threads_ = 1;
  std::vector<Point> polyline_;  // flattener output, reused between segments and fills
  /// Cuts the fill in rasterizer_ into bands (set_threads): returns how many, the first staying in
  /// rasterizer_, the others in band_rasterizers_.
  std::size_t cut_into_bands();

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
};

}  // namespace curvescan
