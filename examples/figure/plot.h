// Plot: a rectangle of the figure that shows a rectangle of data space, y up (as the notes draw their
// graphs and curves), and the axes, grids and titles drawn around it.
//
// Geometry is mapped into device pixels before it is stroked (Path::transformed, exact by affine
// invariance, Ince "Affine invariance property"), so line widths are in pixels whatever the scale.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/curves/point.h"
#include "curvescan/curves/rect.h"
#include "figure/figure.h"

namespace curvescan::figure {

struct Plot {
  Rect pixels;  ///< device rectangle: (x0, y0) top left, (x1, y1) bottom right
  Rect data;    ///< data rectangle shown: x0..x1 left to right, y0..y1 bottom to top

  /// The largest data rectangle of `data`'s aspect ratio centred in `pixels`: equal scales on both axes,
  /// for curves in the plane (a circle stays round).
  [[nodiscard]] static Plot fit(Rect pixels, Rect data) noexcept;
  /// data -> device pixels.
  [[nodiscard]] Affine to_pixels() const noexcept;
  [[nodiscard]] Point map(Point data_point) const noexcept { return to_pixels().apply(data_point); }
  /// Device pixels per data unit along x.
  [[nodiscard]] double scale_x() const noexcept { return pixels.width() / data.width(); }
};

/// The rectangle [x, x + width] × [y, y + height] in device pixels.
[[nodiscard]] constexpr Rect pixel_box(double x, double y, double width, double height) noexcept {
  return {x, y, x + width, y + height};
}

struct Axes {
  std::vector<double> x_ticks;  ///< grid lines and labels along x
  std::vector<double> y_ticks;
  int x_decimals = 0;  ///< digits after the point in the tick labels
  int y_decimals = 0;
  std::string x_label;  ///< right of the bottom right corner
  std::string y_label;  ///< left of the top of the y axis
  bool grid = true;
};

/// Ticks from `first` to `last` (inclusive, within rounding) every `step`.
[[nodiscard]] std::vector<double> ticks(double first, double last, double step);

/// The grid, the x axis at y = 0 (or at the bottom when 0 is outside; its tick labels always under the
/// plot), the y axis at the left edge, tick labels and axis labels (x's right of the plot's bottom end).
void draw_axes(Figure& figure, const Plot& plot, const Axes& axes);

/// A title centred above the plot.
void draw_title(Figure& figure, const Plot& plot, std::string_view title);

/// A light panel behind a plot (the plot's rectangle grown by `margin` pixels).
void draw_panel(Figure& figure, const Plot& plot, double margin);

/// `value` with `decimals` digits after the point ("0.25"), minus sign as U+2212.
[[nodiscard]] std::string format_number(double value, int decimals);

}  // namespace curvescan::figure
