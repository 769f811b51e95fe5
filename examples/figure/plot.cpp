#include "figure/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "curvescan/raster/path_builder.h"
#include "figure/palette.h"

namespace curvescan::figure {

Plot Plot::fit(Rect pixels, Rect data) noexcept {
  const double scale = std::min(pixels.width() / data.width(), pixels.height() / data.height());
  const double width = data.width() * scale;
  const double height = data.height() * scale;
  const double x0 = pixels.x0 + 0.5 * (pixels.width() - width);
  const double y0 = pixels.y0 + 0.5 * (pixels.height() - height);
  return {{x0, y0, x0 + width, y0 + height}, data};
}

Affine Plot::to_pixels() const noexcept {
  const double sx = pixels.width() / data.width();
  const double sy = pixels.height() / data.height();
  // x' = x0 + (x - dx0)·sx, y' = y1 - (y - dy0)·sy: y up in data, down on the canvas.
  return {sx, 0.0, 0.0, -sy, pixels.x0 - data.x0 * sx, pixels.y1 + data.y0 * sy};
}

std::vector<double> ticks(double first, double last, double step) {
  std::vector<double> values;
  if (!(step > 0.0) || !std::isfinite(first) || !std::isfinite(last)) return values;
  // Counted, not accumulated, so that 0.1-steps do not drift; the half step absorbs the rounding of
  // (last - first) / step.
  const auto count = static_cast<long>(std::floor((last - first) / step + 0.5));
  for (long i = 0; i <= count && i <= 1000; ++i) values.push_back(first + static_cast<double>(i) * step);
  return values;
}

std::string format_number(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, std::abs(value));
  std::string text(buffer);
  // A value that rounds to zero is printed without a sign.
  const bool negative = value < 0.0 && text.find_first_not_of("0.") != std::string::npos;
  return negative ? "\u2212" + text : text;
}

namespace {

void line(Figure& figure, Point a, Point b, Color color, double width) {
  StrokeStyle style;
  style.width = width;
  figure.stroke(PathBuilder().move_to(a).line_to(b).build(), color, style);
}

}  // namespace

void draw_panel(Figure& figure, const Plot& plot, double margin) {
  const Rect& r = plot.pixels;
  figure.fill(PathBuilder()
                  .move_to({r.x0 - margin, r.y0 - margin})
                  .line_to({r.x1 + margin, r.y0 - margin})
                  .line_to({r.x1 + margin, r.y1 + margin})
                  .line_to({r.x0 - margin, r.y1 + margin})
                  .close()
                  .build(),
              kPanel);
}

void draw_axes(Figure& figure, const Plot& plot, const Axes& axes) {
  constexpr double kTickFont = 11.0;
  const Rect& box = plot.pixels;
  const double axis_y = (plot.data.y0 <= 0.0 && 0.0 <= plot.data.y1) ? plot.map({0.0, 0.0}).y : box.y1;
  if (axes.grid) {
    for (double x : axes.x_ticks) {
      const double px = plot.map({x, 0.0}).x;
      line(figure, {px, box.y0}, {px, box.y1}, kGrid, 1.0);
    }
    for (double y : axes.y_ticks) {
      const double py = plot.map({0.0, y}).y;
      line(figure, {box.x0, py}, {box.x1, py}, kGrid, 1.0);
    }
  }
  // The u axis is drawn at 0; its tick labels sit under the plot, where no graph runs over them.
  line(figure, {box.x0, axis_y}, {box.x1, axis_y}, kInk, 1.25);
  if (axis_y != box.y1) line(figure, {box.x0, box.y1}, {box.x1, box.y1}, kMutedInk, 1.0);
  line(figure, {box.x0, box.y0}, {box.x0, box.y1}, kInk, 1.25);
  for (double x : axes.x_ticks) {
    const double px = plot.map({x, 0.0}).x;
    line(figure, {px, box.y1}, {px, box.y1 + 4.0}, kInk, 1.0);
    figure.text(format_number(x, axes.x_decimals), {px, box.y1 + 16.0}, kTickFont, kMutedInk,
                TextAnchor::kMiddle);
  }
  for (double y : axes.y_ticks) {
    const double py = plot.map({0.0, y}).y;
    line(figure, {box.x0 - 4.0, py}, {box.x0, py}, kInk, 1.0);
    figure.text(format_number(y, axes.y_decimals), {box.x0 - 7.0, py + 4.0}, kTickFont, kMutedInk,
                TextAnchor::kEnd);
  }
  if (!axes.x_label.empty()) {
    figure.text(axes.x_label, {box.x1 + 8.0, box.y1 + 4.0}, 12.0, kInk, TextAnchor::kStart);
  }
  if (!axes.y_label.empty()) {
    figure.text(axes.y_label, {box.x0 + 6.0, box.y0 + 12.0}, 12.0, kInk, TextAnchor::kStart);
  }
}

void draw_title(Figure& figure, const Plot& plot, std::string_view title) {
  figure.text(title, {0.5 * (plot.pixels.x0 + plot.pixels.x1), plot.pixels.y0 - 12.0}, 14.0, kInk,
              TextAnchor::kMiddle);
}

}  // namespace curvescan::figure
