// The ink of laid-out text as pieces to fill one after the other: runs of plain glyph outlines in the
// text's own colour, and the layers of colour glyphs (color_glyph.h) in their palette colours, in the
// order of the glyphs and, within a colour glyph, of its layers (COLR: layers composite source-over,
// bottom first). Filling the pieces in order with the non-zero rule draws the text; for text without
// colour glyphs there is one piece, the Path append_text_outlines makes.
//
// A palette colour is modulated by the alpha of the text's colour, as browsers draw colour glyphs in a
// translucent text colour (the layers fade with the text): the caller multiplies, text_ink gives the
// palette colour as the font has it.
//
// A bitmap colour glyph (CBDT, sbix) is a piece of its own carrying its image (the strike nearest the
// text size): its path is the image's rectangle, to be filled with the image placed by image_to_user
// (image_pattern.h), faded by the text colour's alpha as a palette layer is.
//
// An SVG-in-OpenType glyph is a piece of its own carrying its document (as the font stores it, possibly
// gzip-compressed): its path is the glyph's outline (its cell where it has none), to measure it and to
// fill where the document cannot be drawn; the document's element "glyphN" is drawn mapped by
// svg_to_user (svg::Document::draw_glyph), faded by the text colour's alpha as a group.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "curvescan/raster/limits.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/path.h"
#include "curvescan/status.h"
#include "curvescan/text/color_glyph.h"
#include "curvescan/text/text_layout.h"

namespace curvescan {

struct TextInkPiece {
  Path path;               ///< user units, to fill with FillRule::kNonZero
  bool foreground = true;  ///< filled with the text's colour; else with `color`
  Color color;             ///< a colour glyph layer's palette colour (straight alpha)
  /// A bitmap colour glyph's image (`path` is then its rectangle), or null.
  std::shared_ptr<const ColorGlyphBitmap> bitmap;
  Affine image_to_user;  ///< where the bitmap lies: image pixels -> user units
  /// An SVG-in-OpenType glyph's document (shared by the pieces of one glyph drawn again), or null.
  std::shared_ptr<const std::string> svg_document;
  GlyphId svg_glyph = kNotdefGlyph;  ///< the glyph whose element "glyphN" the document draws
  double units_per_em = 1000.0;      ///< what the document's percentages are of
  Affine svg_to_user;                ///< the document's user space (font units, y down) -> user units
  bool path_is_outline = false;      ///< `path` is the glyph's outline, not its cell
};

struct TextInk {
  std::vector<TextInkPiece> pieces;  ///< in painting order
  /// One warning per face for COLR version 1 glyphs drawn as plain outlines (color_glyph.h,
  /// outline_only_warning), in order of first appearance.
  std::vector<std::string> warnings;
};

/// The pieces of `layout`'s glyphs, each glyph from its own face (PositionedGlyph::font, or `font` where
/// that is null) scaled to its size, as append_text_outlines places them. A bitmap colour glyph of more
/// than `max_image_pixels` pixels fails with kLimitExceeded. Its errors.
[[nodiscard]] Result<TextInk> text_ink(const Font& font, const TextLayout& layout,
                                       std::int64_t max_image_pixels = kMaxImagePixels);

}  // namespace curvescan
