// SVG-in-OpenType glyphs in `curvescan text` (docs/text.md, "Colour fonts"): each glyph's document drawn
// by the SVG renderer as SVG text draws it (svg::Document::draw_glyph), faded by the text colour's alpha
// as a group. A document that cannot be read (a broken gzip stream, not well formed, not SVG) is named in
// a warning and the glyph's plain outline is filled in the text's colour instead.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "curvescan/raster/canvas.h"
#include "curvescan/status.h"
#include "curvescan/svg/document.h"
#include "curvescan/text/text_ink.h"

namespace curvescan::cli {

class SvgGlyphPainter {
 public:
  /// `max_memory_bytes` bounds each document's inflated text and parsed tree; `quiet` drops warnings.
  SvgGlyphPainter(std::int64_t max_memory_bytes, bool quiet)
      : max_memory_bytes_(max_memory_bytes), quiet_(quiet) {}

  /// Draws `piece` (one with an svg_document) into `canvas`, `user_to_device` mapping the text's user units
  /// to the canvas; `alpha` fades it, `ink` fills the outline where the document cannot be drawn. Errors
  /// are limits exceeded (memory, layers).
  [[nodiscard]] Status draw(Canvas& canvas, const TextInkPiece& piece, const Affine& user_to_device,
                            double alpha, const Paint& ink, const FillOptions& fill);

  /// The box in the text's user units of what draw() paints for `piece` (one with an svg_document): its
  /// document's ink (svg::Document::glyph_ink_box), which may reach beyond the glyph's outline; the
  /// outline's box where the document cannot be read and the outline is drawn instead; nullopt where
  /// nothing is drawn. Errors are limits exceeded while the document is read.
  [[nodiscard]] Result<std::optional<Rect>> ink_box(const TextInkPiece& piece);

 private:
  // The parsed document of each distinct document text (text_ink shares one per glyph), nullopt for one
  // that cannot be read.
  const std::optional<svg::Document>* parsed(const std::shared_ptr<const std::string>& document,
                                             Status& error);
  void warn(const std::string& message);

  std::int64_t max_memory_bytes_;
  bool quiet_;
  std::map<const std::string*, std::optional<svg::Document>> documents_;
  std::set<std::string> warned_;
};

}  // namespace curvescan::cli
