// The outlines of a font's glyphs in device orientation (y down), for tests that check every glyph, or
// every n-th, of a real font at a size.
#pragma once

#include <catch2/catch.hpp>
#include <cstddef>

#include "curvescan/raster/path.h"
#include "curvescan/text/font.h"

namespace curvescan::testing {

/// Calls visit(glyph, outline) for glyphs 0, stride, 2·stride… of the font in `file` scaled to
/// pixels_per_em, skipping those with no outline (spaces, marks without contours); returns how many it
/// visited, so that a test can assert the font really had glyphs to check.
template <class Visit>
int for_each_glyph_outline(const char* file, double pixels_per_em, int stride, Visit visit) {
  const Result<Font> font = Font::open(file);
  REQUIRE(font.is_ok());
  int visited = 0;
  for (GlyphId glyph = 0; glyph < font->glyph_count(); glyph += static_cast<GlyphId>(stride)) {
    const Result<Path> outline = font->freetype_scaled_glyph_path(glyph, pixels_per_em);
    if (!outline || outline->empty()) continue;
    const Result<Path> device = outline->transformed(Affine::scale(1.0, -1.0));
    REQUIRE(device.is_ok());
    visit(glyph, *device);
    ++visited;
  }
  return visited;
}

}  // namespace curvescan::testing
