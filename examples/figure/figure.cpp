#include "figure/figure.h"

#include <utility>

#include "curvescan/raster/paint.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/utf8.h"
#include "figure/palette.h"

namespace curvescan::figure {

Result<Figure> Figure::create(int width, int height) {
  Result<Canvas> canvas = Canvas::create(width, height);
  if (!canvas) return canvas.error();
  canvas->clear(Paint::solid(kPaper));
  Result<Font> font = load_font(FontQuery{std::string(kLabelFamily), 400, false}, /*allow_fallback=*/false);
  if (!font) return font.error();
  return Figure(std::move(*canvas), std::move(*font));
}

void Figure::record(const Status& status) {
  if (!status && !error_) error_ = status.error();
}

void Figure::fill(const Result<Path>& path, Color color, FillRule rule) {
  fill_paint(path, Paint::solid(color), rule);
}

void Figure::fill_paint(const Result<Path>& path, const Paint& paint, FillRule rule) {
  if (!ok()) return;
  if (!path) return record(path.status());
  record(canvas_.fill(*path, paint, rule));
}

void Figure::stroke(const Result<Path>& path, Color color, const StrokeStyle& style) {
  if (!ok()) return;
  if (!path) return record(path.status());
  record(canvas_.stroke(*path, Paint::solid(color), style));
}

double Figure::text(std::string_view utf8, Point origin, double size, Color color, TextAnchor anchor) {
  if (!ok()) return 0.0;
  Result<std::u32string> decoded = decode_utf8(utf8);
  if (!decoded) {
    record(decoded.status());
    return 0.0;
  }
  TextStyle style;
  style.size = size;
  style.anchor = anchor;
  Result<TextLayout> layout = layout_text(font_, *decoded, origin, style);
  if (!layout) {
    record(layout.status());
    return 0.0;
  }
  PathBuilder builder;
  record(append_text_outlines(font_, *layout, builder));
  fill(builder.build(), color);
  return layout->lines.empty() ? 0.0 : layout->lines.front().advance;
}

double Figure::text_width(std::string_view utf8, double size) {
  Result<std::u32string> decoded = decode_utf8(utf8);
  if (!decoded) return 0.0;
  TextStyle style;
  style.size = size;
  Result<TextLayout> layout = layout_text(font_, *decoded, {0.0, 0.0}, style);
  if (!layout || layout->lines.empty()) return 0.0;
  return layout->lines.front().advance;
}

Result<Image> Figure::finish() && {
  if (error_) return *error_;
  return std::move(canvas_).take_image();
}

}  // namespace curvescan::figure
