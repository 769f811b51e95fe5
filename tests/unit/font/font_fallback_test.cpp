// Per-character font fallback (font_fallback.h, text_layout.h): Cantarell (CFF) lacks the card suits,
// box drawing and geometric shapes (U+2500-U+25C9), which DejaVu Sans (TrueType) has (fc-query on both
// files), so "A♠─■" in Cantarell must be one Cantarell run and one DejaVu Sans run (fontconfig ranks
// DejaVu Sans first among the faces that have them), every glyph a real glyph, advances FreeType's.
#include <ft2build.h>
#include FT_FREETYPE_H

#include <catch2/catch.hpp>
#include <string>

#include "curvescan/text/font_fallback.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"
#include "font_files.h"

using namespace curvescan;

namespace {

Font cantarell() {
  Result<Font> font = Font::open(kCantarellFile);
  REQUIRE(font.is_ok());
  return std::move(font).value();
}

// FreeType's unhinted advance of `character` in font units, from a face of its own on `file`.
double freetype_advance(const std::string& file, char32_t character, double& units_per_em) {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  REQUIRE(FT_Init_FreeType(&library) == 0);
  REQUIRE(FT_New_Face(library, file.c_str(), 0, &face) == 0);
  REQUIRE(FT_Load_Char(face, character, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
  const double advance = static_cast<double>(face->glyph->advance.x);
  units_per_em = face->units_per_EM;
  FT_Done_Face(face);
  FT_Done_FreeType(library);
  return advance;
}

TextStyle unkerned(double size) {
  TextStyle style;
  style.size = size;
  style.kerning = false;  // advances alone, so each step between glyphs is one FreeType advance
  return style;
}

}  // namespace

TEST_CASE("fallback: characters Cantarell lacks are drawn from DejaVu Sans", "[font][fallback]") {
  const Font primary = cantarell();
  const std::u32string text = U"A\u2660\u2500\u25A0";  // A ♠ ─ ■
  for (char32_t c : text.substr(1)) REQUIRE(primary.glyph_for(c) == kNotdefGlyph);  // the premise

  FontFallback fonts(primary, FontQuery{"Cantarell", 400, false});
  const Result<TextLayout> layout = layout_text(fonts, text, {0.0, 0.0}, unkerned(40.0));
  REQUIRE(layout.is_ok());
  CHECK(layout->missing_characters.empty());
  REQUIRE(layout->runs.size() == 2);
  CHECK(layout->runs[0].font == &primary);
  CHECK(layout->runs[0].glyph_count == 1);
  REQUIRE(layout->runs[1].font != nullptr);
  CHECK(layout->runs[1].font->family_name() == "DejaVu Sans");
  CHECK(layout->runs[1].glyph_count == 3);
  REQUIRE(layout->glyphs.size() == 4);
  for (const PositionedGlyph& glyph : layout->glyphs) {
    CHECK(glyph.glyph != kNotdefGlyph);
    const char32_t character = text[glyph.character_index];
    CHECK(glyph.font->glyph_for(character) == glyph.glyph);  // the face's own glyph for it
  }
  CHECK(fonts.opened_face_count() == 1);  // one fallback face opened, once, for three characters

  // Each step is the previous glyph's FreeType advance in its own face, at the same em size. Tolerance
  // 1e-9 user units: the same products and sums of doubles ~100 in size, rounding errors ~1e-14.
  for (std::size_t i = 0; i + 1 < layout->glyphs.size(); ++i) {
    const PositionedGlyph& glyph = layout->glyphs[i];
    double units_per_em = 0.0;
    const double advance = freetype_advance(glyph.font->source_name(), text[glyph.character_index], units_per_em);
    CHECK(layout->glyphs[i + 1].origin.x - glyph.origin.x == Approx(advance * 40.0 / units_per_em).margin(1e-9));
  }
  double units_per_em = 0.0;
  const double last = freetype_advance(layout->glyphs.back().font->source_name(), text.back(), units_per_em);
  CHECK(layout->lines.front().advance ==
        Approx(layout->glyphs.back().origin.x + last * 40.0 / units_per_em).margin(1e-9));
}

TEST_CASE("fallback: the primary face keeps every character it has", "[font][fallback]") {
  const Font primary = cantarell();
  FontFallback fonts(primary, FontQuery{"Cantarell", 400, false});
  const Result<TextLayout> layout = layout_text(fonts, U"Hello, world", {0.0, 0.0}, unkerned(20.0));
  REQUIRE(layout.is_ok());
  REQUIRE(layout->runs.size() == 1);
  CHECK(layout->runs[0].font == &primary);
  CHECK(fonts.opened_face_count() == 0);  // nothing missing: fontconfig is never asked
  // Without fallback the same text lays out identically.
  const Result<TextLayout> plain = layout_text(primary, U"Hello, world", {0.0, 0.0}, unkerned(20.0));
  REQUIRE(plain.is_ok());
  REQUIRE(plain->glyphs.size() == layout->glyphs.size());
  for (std::size_t i = 0; i < plain->glyphs.size(); ++i) {
    CHECK(plain->glyphs[i].glyph == layout->glyphs[i].glyph);
    CHECK(plain->glyphs[i].origin == layout->glyphs[i].origin);
  }
}

TEST_CASE("fallback: only characters no installed face has are missing, each once", "[font][fallback]") {
  const Font primary = cantarell();
  FontFallback fonts(primary, FontQuery{"Cantarell", 400, false});
  // U+10FFFD is a plane-16 private-use character no installed font maps (fc-list ':charset=10fffd').
  const Result<TextLayout> layout = layout_text(fonts, U"a\U0010FFFD\u2660\U0010FFFD", {0.0, 0.0}, unkerned(20.0));
  REQUIRE(layout.is_ok());
  CHECK(layout->missing_characters == U"\U0010FFFD");
  REQUIRE(layout->glyphs.size() == 4);
  CHECK(layout->glyphs[1].glyph == kNotdefGlyph);  // the primary face's .notdef
  CHECK(layout->glyphs[1].font == &primary);
  CHECK(layout->glyphs[2].glyph != kNotdefGlyph);
  CHECK(layout->glyphs[2].font->family_name() == "DejaVu Sans");
  CHECK(fonts.face_for(U'\U0010FFFD') == nullptr);
  CHECK(fonts.face_for(U'a') == &primary);
}

TEST_CASE("fallback: a combining mark stays with its base's face", "[font][fallback]") {
  const Font primary = cantarell();
  FontFallback fonts(primary, FontQuery{"Cantarell", 400, false});
  // ♠ followed by U+0301 COMBINING ACUTE ACCENT: the base comes from DejaVu Sans, which has the accent,
  // so the accent is shaped with it (one run) even if Cantarell has U+0301 too.
  const Result<TextLayout> layout = layout_text(fonts, U"\u2660\u0301", {0.0, 0.0}, unkerned(20.0));
  REQUIRE(layout.is_ok());
  REQUIRE(layout->runs.size() == 1);
  CHECK(layout->runs[0].font->family_name() == "DejaVu Sans");
  CHECK(layout->missing_characters.empty());
}

TEST_CASE("fallback: text_path with fallback equals the outlines of its layout", "[font][fallback]") {
  const Font primary = cantarell();
  FontFallback fonts(primary, FontQuery{"Cantarell", 400, false});
  const Result<Path> path = text_path(fonts, "A\xE2\x99\xA0", {5.0, 30.0}, unkerned(24.0));
  REQUIRE(path.is_ok());
  const Result<TextLayout> layout = layout_text(fonts, U"A\u2660", {5.0, 30.0}, unkerned(24.0));
  REQUIRE(layout.is_ok());
  PathBuilder builder;
  REQUIRE(append_text_outlines(primary, *layout, builder).is_ok());
  const Result<Path> expected = builder.build();
  REQUIRE(expected.is_ok());
  CHECK(*path == *expected);
  // The ♠ is DejaVu's outline: the path reaches beyond the 'A' by the ♠'s extent.
  CHECK(path->tight_bounds().x1 > 5.0 + 24.0 * 0.6);
}
