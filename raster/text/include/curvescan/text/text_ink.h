// The ink of laid-out text as pieces to fill one after the other: runs of plain glyph outlines in the
// text's own colour, and the layers of colour glyphs (color_glyph.h) in their palette colours, in the
// order of the glyphs and, within a colour glyph, of its layers (COLR: layers composite source-over,
// bottom first). Filling the pieces in order with the non-zero rule draws the text; for text without
// colour glyphs there is one piece, the Path append_text_outlines makes.
//
// A palette colour is modulated by the alpha of the text's colour, as browsers draw colour glyphs in a
// translucent text colour (the layers fade with the text): the caller multiplies, text_ink gives the
// palette colour as the font has it.
#pragma once

#include <string>
#include <vector>

#include "curvescan/raster/paint.h"
#include "curvescan/raster/path.h"
#include "curvescan/status.h"
#include "curvescan/text/text_layout.h"

namespace curvescan {

struct TextInkPiece {
  Path path;               ///< user units, to fill with FillRule::kNonZero
  bool foreground = true;  ///< filled with the text's colour; else with `color`
  Color color;             ///< a colour glyph layer's palette colour (straight alpha)
};

struct TextInk {
  std::vector<TextInkPiece> pieces;  ///< in painting order
  /// One warning per face and kind of colour glyph drawn as plain outlines (color_glyph.h,
  /// outline_only_warning), in order of first appearance.
  std::vector<std::string> warnings;
};

/// The pieces of `layout`'s glyphs, each glyph from its own face (PositionedGlyph::font, or `font` where
/// that is null) scaled to its size, as append_text_outlines places them. Its errors.
[[nodiscard]] Result<TextInk> text_ink(const Font& font, const TextLayout& layout);

}  // namespace curvescan
