// Vertical layout (TextStyle::vertical, HarfBuzz's HB_DIRECTION_TTB) against FreeType's own reading of
// the vertical metrics, with IPA Gothic (Debian fonts-ipafont-gothic), a Japanese face with vhea, vmtx
// and a 'vert' feature. It is opened by file: the tests' fontconfig configuration leaves it out, so that
// other tests keep finding CJK characters missing.
#include <ft2build.h>
#include FT_FREETYPE_H

#include <catch2/catch.hpp>
#include <string>

#include "curvescan/text/text_layout.h"

using namespace curvescan;

namespace {

constexpr const char* kIpaGothicFile = "/usr/share/fonts/opentype/ipafont-gothic/ipag.ttf";

// FreeType's unscaled vertical metrics of a glyph: advance (vmtx), top side bearing, and the top of its
// bounding box (FT_LOAD_VERTICAL_LAYOUT reads vmtx; FreeType docs, FT_Glyph_Metrics).
struct VerticalMetrics {
  double advance = 0.0, top_bearing = 0.0, y_max = 0.0, horizontal_advance = 0.0;
  double width = 0.0, height = 0.0;  // of the outline's bounding box
};
VerticalMetrics freetype_vertical(FT_UInt glyph) {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  REQUIRE(FT_Init_FreeType(&library) == 0);
  REQUIRE(FT_New_Face(library, kIpaGothicFile, 0, &face) == 0);
  REQUIRE(FT_HAS_VERTICAL(face));
  REQUIRE(FT_Load_Glyph(face, glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_VERTICAL_LAYOUT) == 0);
  VerticalMetrics m{static_cast<double>(face->glyph->metrics.vertAdvance),
                    static_cast<double>(face->glyph->metrics.vertBearingY), 0.0,
                    static_cast<double>(face->glyph->metrics.horiAdvance)};
  REQUIRE(FT_Load_Glyph(face, glyph, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
  m.y_max = static_cast<double>(face->glyph->metrics.horiBearingY);
  m.width = static_cast<double>(face->glyph->metrics.width);
  m.height = static_cast<double>(face->glyph->metrics.height);
  FT_Done_Face(face);
  FT_Done_FreeType(library);
  return m;
}

}  // namespace

TEST_CASE("vertical layout: vmtx advances, vertical origins and 'vert' alternates",
          "[font][layout][vertical]") {
  Result<Font> font = Font::open(kIpaGothicFile);
  REQUIRE(font.is_ok());
  TextStyle style;
  style.size = 32.0;
  style.vertical = true;
  // 中 (an ideograph) then 「 (a corner bracket, which vertical text turns: the font's 'vert' alternate).
  const Result<TextLayout> layout = layout_text(*font, U"\u4E2D\u300C", {100.0, 10.0}, style);
  REQUIRE(layout.is_ok());
  REQUIRE(layout->glyphs.size() == 2);
  const double scale = 32.0 / font->metrics().units_per_em;
  const GlyphId ideograph = font->glyph_for(U'\u4E2D');
  CHECK(layout->glyphs[0].glyph == ideograph);
  CHECK(layout->glyphs[1].glyph != font->glyph_for(U'\u300C'));  // substituted by 'vert'
  CHECK(layout->glyphs[1].glyph != kNotdefGlyph);
  // Horizontal layout keeps the bracket as the cmap has it.
  const Result<TextLayout> horizontal = layout_text(*font, U"\u300C", {0.0, 0.0}, {});
  REQUIRE(horizontal.is_ok());
  CHECK(horizontal->glyphs[0].glyph == font->glyph_for(U'\u300C'));

  const VerticalMetrics m = freetype_vertical(ideograph);
  // The advance is vmtx's, down the line; the next glyph starts there.
  CHECK(layout->glyphs[0].advance == Approx(m.advance * scale).epsilon(1e-12));
  // HarfBuzz's vertical origin (no VORG table): x at half the horizontal advance, y at the top side
  // bearing above the glyph's top; the glyph's own (horizontal) origin is that far left of and below
  // the pen.
  CHECK(layout->glyphs[0].origin.x == Approx(100.0 - 0.5 * m.horizontal_advance * scale).epsilon(1e-12));
  CHECK(layout->glyphs[0].origin.y == Approx(10.0 + (m.top_bearing + m.y_max) * scale).epsilon(1e-12));
  const VerticalMetrics bracket = freetype_vertical(layout->glyphs[1].glyph);
  // The alternate is the bracket turned for vertical text: the tall, narrow corner becomes wide and low.
  const VerticalMetrics upright_bracket = freetype_vertical(font->glyph_for(U'\u300C'));
  CHECK(upright_bracket.height > 2.0 * upright_bracket.width);
  CHECK(bracket.width > 2.0 * bracket.height);
  CHECK(layout->glyphs[1].origin.y ==
        Approx(10.0 + m.advance * scale + (bracket.top_bearing + bracket.y_max) * scale).epsilon(1e-12));
  CHECK(layout->lines.front().advance == Approx((m.advance + bracket.advance) * scale).epsilon(1e-12));

  // text-anchor acts along the line: middle centres the column on y = 10.
  style.anchor = TextAnchor::kMiddle;
  const Result<TextLayout> middle = layout_text(*font, U"\u4E2D\u300C", {100.0, 10.0}, style);
  REQUIRE(middle.is_ok());
  CHECK(middle->glyphs[0].origin.y ==
        Approx(layout->glyphs[0].origin.y - 0.5 * layout->lines.front().advance));
  CHECK(middle->glyphs[0].origin.x == layout->glyphs[0].origin.x);
  // A second line stands one line height to the left.
  style.anchor = TextAnchor::kStart;
  const Result<TextLayout> two = layout_text(*font, U"\u4E2D\n\u4E2D", {100.0, 10.0}, style);
  REQUIRE(two.is_ok());
  REQUIRE(two->glyphs.size() == 2);
  CHECK(two->glyphs[1].origin.x == Approx(two->glyphs[0].origin.x - two->line_height));
  CHECK(two->glyphs[1].origin.y == two->glyphs[0].origin.y);
  const Rect box = two->line_box();
  CHECK(box.x1 == Approx(100.0 + 0.5 * two->line_height));
  CHECK(box.y0 == Approx(10.0));
  CHECK(box.y1 == Approx(10.0 + m.advance * scale));
}
