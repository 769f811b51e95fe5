// Canvas: an Image plus a clip rectangle, and fill(), the whole pipeline of STYLE.md in one call:
// path -> transform -> flatten -> Rasterizer -> spans -> source-over compositing -> pixels.
#pragma once

#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/curves/point.h"
#include "curvescan/raster/fill_rule.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/layer.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/rasterizer.h"
#include "curvescan/raster/stroke_style.h"
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
  [[nodiscard]] static Result<Canvas> create(int width, int height);
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
  /// masks of the enclosing level. Fails when no layer is open or clips pushed inside it are still open.
  [[nodiscard]] Status pop_layer(double opacity);
  [[nodiscard]] int layer_depth() const noexcept { return static_cast<int>(layers_.size()); }

  /// Intersects the clip with `path` (user space, mapped by `transform`, filled with `rule` and
  /// antialiased as fill() does): an SVG clipPath with its clip-rule. The clip applies to drawing in the
  /// current layer, and to the layers pushed inside it when they are composited (so it applies once).
  /// Fails as fill() does, or with kLimitExceeded beyond kMaxClipDepth (limits.h).
  [[nodiscard]] Status push_clip(const Path& path, FillRule rule, const Affine& transform = Affine::identity(),
                                 const FillOptions& options = {});
  /// Removes the innermost clip mask. Fails when there is none at the current layer level.
  [[nodiscard]] Status pop_clip();
  [[nodiscard]] int clip_depth() const noexcept { return static_cast<int>(clips_.size()); }

 private:
  Image image_;
  IntRect clip_;
  Rasterizer rasterizer_;
  std::vector<Point> polyline_;  // flattener output, reused between segments and fills

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
};

}  // namespace curvescan
