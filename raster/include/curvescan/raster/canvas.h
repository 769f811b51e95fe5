// Canvas: an Image plus a clip rectangle, and fill(), the whole pipeline of STYLE.md in one call:
// path -> transform -> flatten -> Rasterizer -> spans -> source-over compositing -> pixels.
#pragma once

#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/curves/point.h"
#include "curvescan/raster/fill_rule.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/rasterizer.h"
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

 private:
  Image image_;
  IntRect clip_;
  Rasterizer rasterizer_;
  std::vector<Point> polyline_;  // flattener output, reused between segments and fills
};

}  // namespace curvescan
