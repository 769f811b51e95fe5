// SvgGlyphPainter (text_svg_glyphs.h).
#include "text_svg_glyphs.h"

#include <string_view>
#include <utility>

#include "exit_codes.h"

namespace curvescan::cli {

void SvgGlyphPainter::warn(const std::string& message) {
  if (!quiet_ && warned_.insert(message).second) report_warning("text", message);
}

const std::optional<svg::Document>* SvgGlyphPainter::parsed(
    const std::shared_ptr<const std::string>& document, Status& error) {
  const auto known = documents_.find(document.get());
  if (known != documents_.end()) return &known->second;
  std::optional<svg::Document>& slot = documents_[document.get()];
  Result<svg::Document> read = svg::Document::parse_glyph_document(*document, max_memory_bytes_);
  if (!read) {
    if (read.error().kind == ErrorKind::kLimitExceeded) {
      error = read.error();
      return &slot;
    }
    warn("an SVG glyph document " + read.error().message + "; its glyphs are drawn as plain outlines");
    return &slot;
  }
  slot = std::move(read).value();
  return &slot;
}

Result<std::optional<Rect>> SvgGlyphPainter::ink_box(const TextInkPiece& piece) {
  Status error = Status::ok();
  const std::optional<svg::Document>* document = parsed(piece.svg_document, error);
  CURVESCAN_PROPAGATE(error);
  if (!*document) {
    if (!piece.path_is_outline) return std::optional<Rect>{};
    return std::optional<Rect>{piece.path.tight_bounds()};
  }
  const std::optional<Rect> box = (*document)->glyph_ink_box(piece.svg_glyph, piece.units_per_em, {});
  if (!box) return std::optional<Rect>{};
  // The box of the four mapped corners: svg_to_user may turn the glyph (it does not in the text command,
  // whose glyphs are upright, but the bound stays right if it did).
  std::optional<Rect> mapped;
  for (const Point corner :
       {Point{box->x0, box->y0}, Point{box->x1, box->y0}, Point{box->x0, box->y1}, Point{box->x1, box->y1}}) {
    const Point user = piece.svg_to_user.apply(corner);
    if (!mapped) mapped = Rect::from_point(user);
    mapped->include(user);
  }
  return mapped;
}

Status SvgGlyphPainter::draw(Canvas& canvas, const TextInkPiece& piece, const Affine& user_to_device,
                             double alpha, const Paint& ink, const FillOptions& fill) {
  Status error = Status::ok();
  const std::optional<svg::Document>* document = parsed(piece.svg_document, error);
  CURVESCAN_PROPAGATE(error);
  if (!*document) {
    if (!piece.path_is_outline) return Status::ok();
    return canvas.fill(piece.path, ink, FillRule::kNonZero, user_to_device, fill);
  }
  const bool faded = alpha < 1.0;
  if (faded) {
    CURVESCAN_PROPAGATE(canvas.reserve_layer());
    CURVESCAN_PROPAGATE(canvas.push_layer());
  }
  svg::RenderOptions options;
  options.tolerance = fill.tolerance;
  options.limits.render = canvas.limits();
  Result<svg::DocumentMessages> messages = (*document)->draw_glyph(
      canvas, piece.svg_glyph, user_to_device * piece.svg_to_user, piece.units_per_em, options);
  if (faded) CURVESCAN_PROPAGATE(canvas.pop_layer(alpha));
  if (!messages) return messages.error();
  for (const std::string& warning : messages->warnings) warn("SVG glyph document: " + warning);
  return Status::ok();
}

}  // namespace curvescan::cli
