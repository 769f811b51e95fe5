// Figure: one picture of the gallery — a white canvas, the DejaVu Sans face for its labels, and drawing
// calls in device pixels that remember the first failure instead of returning a Status each, so that a
// figure reads as a list of drawing steps and still reports what went wrong (PathBuilder keeps its first
// error the same way). finish() hands back the image, or that first error.
//
// Labels go through curvescan's own text pipeline (font_lookup.h -> text_layout.h -> Canvas::fill), so
// the gallery also shows the text rendering. The face is looked up without fallback: the golden images
// are drawn with DejaVu Sans (Debian's fonts-dejavu-core), and another face would change every label.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/raster/canvas.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/pixel_format.h"
#include "curvescan/raster/stroke.h"
#include "curvescan/status.h"
#include "curvescan/text/font.h"
#include "curvescan/text/text_layout.h"

namespace curvescan::figure {

/// The family every label is set in.
inline constexpr std::string_view kLabelFamily = "DejaVu Sans";

class Figure {
 public:
  /// A width x height figure on a white background, with DejaVu Sans loaded (kInvalidArgument naming the
  /// fallback when it is not installed; Canvas::create's errors for a bad size).
  [[nodiscard]] static Result<Figure> create(int width, int height);

  [[nodiscard]] int width() const noexcept { return canvas_.width(); }
  [[nodiscard]] int height() const noexcept { return canvas_.height(); }
  [[nodiscard]] Canvas& canvas() noexcept { return canvas_; }
  [[nodiscard]] const Font& font() const noexcept { return font_; }

  /// Keeps `status` if it is the first failure; later drawing calls become no-ops.
  void record(const Status& status);
  [[nodiscard]] bool ok() const noexcept { return !error_.has_value(); }

  /// Fills `path` (device pixels) with a solid colour.
  void fill(const Result<Path>& path, Color color, FillRule rule = FillRule::kNonZero);
  /// Strokes `path` (device pixels).
  void stroke(const Result<Path>& path, Color color, const StrokeStyle& style);
  /// Fills `path` with any paint (gradients).
  void fill_paint(const Result<Path>& path, const Paint& paint, FillRule rule = FillRule::kNonZero);

  /// Draws `utf8` in DejaVu Sans at `size` pixels per em with its baseline starting at `origin` (aligned
  /// by `anchor`), and returns its advance width in pixels (0 after a failure).
  double text(std::string_view utf8, Point origin, double size, Color color,
              TextAnchor anchor = TextAnchor::kStart);
  /// The advance width `text` would draw, without drawing.
  [[nodiscard]] double text_width(std::string_view utf8, double size);

  /// The image, or the first failure recorded.
  [[nodiscard]] Result<Image> finish() &&;

 private:
  Figure(Canvas canvas, Font font) : canvas_(std::move(canvas)), font_(std::move(font)) {}

  Canvas canvas_;
  Font font_;
  std::optional<Error> error_;
};

}  // namespace curvescan::figure
