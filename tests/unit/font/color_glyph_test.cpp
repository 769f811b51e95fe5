// color_glyph.h against tests/fonts/CurvescanColourTest.ttf, whose tables tests/fonts/
// make_colour_test_font.py states: the kind of each glyph, and the layers of the COLR version 0 glyph in
// order with their palette colours (CPAL stores 8-bit channels, so the colours compare exactly).
#include "curvescan/text/color_glyph.h"

#include <catch2/catch.hpp>
#include <string>

using namespace curvescan;

namespace {

Font colour_font() {
  Result<Font> font = Font::open(std::string(CURVESCAN_SOURCE_DIR) + "/tests/fonts/CurvescanColourTest.ttf");
  REQUIRE(font.is_ok());
  return std::move(font).value();
}

}  // namespace

TEST_CASE("colour glyph kinds: COLR v0 layers, COLR v1 paint, SVG document, plain outline") {
  const Font font = colour_font();
  CHECK(color_glyph_kind(font, font.glyph_for(U'A')) == ColorGlyphKind::kLayers);
  CHECK(color_glyph_kind(font, font.glyph_for(U'B')) == ColorGlyphKind::kPaintGraph);
  CHECK(color_glyph_kind(font, font.glyph_for(U'C')) == ColorGlyphKind::kSvg);
  CHECK(color_glyph_kind(font, font.glyph_for(U'D')) == ColorGlyphKind::kOutline);
  CHECK(color_glyph_kind(font, 100000) == ColorGlyphKind::kOutline);  // outside the face
  CHECK(color_glyph_layers(font, font.glyph_for(U'D')).empty());
  CHECK(color_glyph_layers(font, font.glyph_for(U'B')).empty());
  CHECK(outline_only_warning(font, ColorGlyphKind::kLayers).empty());
  CHECK(outline_only_warning(font, ColorGlyphKind::kSvg) ==
        "SVG colour glyphs in font 'Curvescan Colour Test' are drawn as plain outlines");
}

TEST_CASE("colour glyph layers: bottom first, palette colours, 0xFFFF the foreground") {
  const Font font = colour_font();
  const std::vector<ColorGlyphLayer> layers = color_glyph_layers(font, font.glyph_for(U'A'));
  REQUIRE(layers.size() == 3);
  // Glyph order of the script: .notdef A B C D layer.red layer.fg layer.blue.
  CHECK(layers[0].glyph == 5);
  CHECK_FALSE(layers[0].foreground);
  CHECK(layers[0].color == Color::from_rgba8(255, 0, 0, 255));
  CHECK(layers[1].glyph == 6);
  CHECK(layers[1].foreground);
  CHECK(layers[2].glyph == 7);
  CHECK_FALSE(layers[2].foreground);
  CHECK(layers[2].color == Color::from_rgba8(0, 0, 255, 128));
}

TEST_CASE("colour fonts without colour tables: every glyph is a plain outline") {
  Result<Font> font = Font::open("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
  REQUIRE(font.is_ok());
  CHECK(color_glyph_kind(*font, font->glyph_for(U'A')) == ColorGlyphKind::kOutline);
  CHECK(color_glyph_layers(*font, font->glyph_for(U'A')).empty());
}
