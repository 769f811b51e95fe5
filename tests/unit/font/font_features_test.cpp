// Font features in layout (text_layout.h): explicit OpenType features (CSS font-feature-settings), and
// small capitals — the font's own 'smcp' where it has one (Noto Sans Mono), synthesized where it has not
// (DejaVu Sans): lowercase letters drawn as the uppercase glyph at kSyntheticSmallCapsScale of the size.
#include <ft2build.h>
#include FT_FREETYPE_H

#include <catch2/catch.hpp>
#include <string>

#include "curvescan/text/text_layout.h"
#include "font_files.h"
#include "text/shaping_p.h"

using namespace curvescan;

namespace {

// Noto Sans Mono (Debian fonts-noto-mono) has small capitals (smcp, c2sc); DejaVu has none.
constexpr const char* kNotoSansMonoFile = "/usr/share/fonts/truetype/noto/NotoSansMono-Regular.ttf";

Font open_font(const char* file) {
  Result<Font> font = Font::open(file);
  REQUIRE(font.is_ok());
  return std::move(font).value();
}

TextLayout lay_out(const Font& font, std::u32string_view text, const TextStyle& style) {
  Result<TextLayout> layout = layout_text(font, text, {0.0, 0.0}, style);
  REQUIRE(layout.is_ok());
  return std::move(layout).value();
}

// The glyph's PostScript name from FreeType (an independent reading of the font's post table).
std::string glyph_name(const char* file, GlyphId glyph) {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  REQUIRE(FT_Init_FreeType(&library) == 0);
  REQUIRE(FT_New_Face(library, file, 0, &face) == 0);
  char name[64] = {};
  const bool ok = FT_Get_Glyph_Name(face, glyph, name, sizeof name) == 0;
  FT_Done_Face(face);
  FT_Done_FreeType(library);
  REQUIRE(ok);
  return name;
}

}  // namespace

TEST_CASE("features: font-feature-settings switch features on and off", "[font][layout][features]") {
  const Font font = open_font(kDejaVuSansFile);
  TextStyle style;
  style.size = 20.0;
  // DejaVu Sans has an "fi" ligature ('liga'): one glyph, two without the feature.
  CHECK(lay_out(font, U"fi", style).glyphs.size() == 1);
  style.features = {{font_feature_tag("liga"), 0}};
  CHECK(lay_out(font, U"fi", style).glyphs.size() == 2);
  // 'kern' off by feature equals kerning = false: "AV" is a kerned pair.
  TextStyle unkerned;
  unkerned.size = 20.0;
  unkerned.kerning = false;
  TextStyle feature_off;
  feature_off.size = 20.0;
  feature_off.features = {{font_feature_tag("kern"), 0}};
  const double kerned = lay_out(font, U"AV", TextStyle{}).glyphs[1].origin.x;
  CHECK(lay_out(font, U"AV", feature_off).glyphs[1].origin.x ==
        lay_out(font, U"AV", unkerned).glyphs[1].origin.x);
  CHECK(lay_out(font, U"AV", TextStyle{}).glyphs[1].origin.x == kerned);
  CHECK(lay_out(font, U"AV", unkerned).glyphs[1].origin.x * (16.0 / 20.0) > kerned);  // kerning pulls V left
  CHECK(font_feature_tag("smcp") ==
        ((std::uint32_t{'s'} << 24) | (std::uint32_t{'m'} << 16) | ('c' << 8) | 'p'));
}

TEST_CASE("features: small caps from the font's smcp feature", "[font][layout][features]") {
  const Font serif = open_font(kNotoSansMonoFile);
  REQUIRE(detail::has_gsub_feature(serif, font_feature_tag("smcp")));
  TextStyle style;
  style.size = 20.0;
  style.caps = CapsVariant::kSmallCaps;
  const TextLayout layout = lay_out(serif, U"Ab", style);
  REQUIRE(layout.glyphs.size() == 2);
  // The capital stays; the lowercase letter becomes the font's small-capital glyph, at the full size.
  CHECK(layout.glyphs[0].glyph == serif.glyph_for(U'A'));
  CHECK(layout.glyphs[1].glyph != serif.glyph_for(U'b'));
  CHECK(layout.glyphs[1].glyph != serif.glyph_for(U'B'));
  CHECK(glyph_name(kNotoSansMonoFile, layout.glyphs[1].glyph).find(".sc") != std::string::npos);
  CHECK(layout.glyphs[1].size == 20.0);
}

TEST_CASE("features: small caps synthesized where the font has none", "[font][layout][features]") {
  const Font sans = open_font(kDejaVuSansFile);
  REQUIRE_FALSE(detail::has_gsub_feature(sans, font_feature_tag("smcp")));
  TextStyle style;
  style.size = 20.0;
  style.caps = CapsVariant::kSmallCaps;
  style.kerning = false;  // so that the advances are the glyphs' own
  const TextLayout layout = lay_out(sans, U"A\u00e9b1", style);
  REQUIRE(layout.glyphs.size() == 4);
  const double scale = 20.0 / sans.metrics().units_per_em;
  // "A" and "1" are unchanged; "é" and "b" are drawn as "É" and "B" at 0.7 of the size.
  CHECK(layout.glyphs[0].glyph == sans.glyph_for(U'A'));
  CHECK(layout.glyphs[0].size == 20.0);
  CHECK(layout.glyphs[1].glyph == sans.glyph_for(U'\u00c9'));
  CHECK(layout.glyphs[1].size == Approx(20.0 * kSyntheticSmallCapsScale));
  CHECK(layout.glyphs[2].glyph == sans.glyph_for(U'B'));
  CHECK(layout.glyphs[3].glyph == sans.glyph_for(U'1'));
  CHECK(layout.glyphs[3].size == 20.0);
  // Advances: the uppercase glyph's at the reduced size (equal up to rounding: 1e-12 of a unit).
  CHECK(layout.glyphs[2].advance == Approx(sans.advance(sans.glyph_for(U'B')) * scale * 0.7).epsilon(1e-12));
  CHECK(layout.glyphs[3].origin.x ==
        Approx(layout.glyphs[2].origin.x + layout.glyphs[2].advance).epsilon(1e-12));
  // The characters are still the text's: "é" is character 1.
  CHECK(layout.glyphs[1].character_index == 1);
  // all-small-caps makes the capitals small too.
  style.caps = CapsVariant::kAllSmallCaps;
  const TextLayout all = lay_out(sans, U"Ab", style);
  CHECK(all.glyphs[0].glyph == sans.glyph_for(U'A'));
  CHECK(all.glyphs[0].size == Approx(20.0 * kSyntheticSmallCapsScale));
  CHECK(all.glyphs[1].size == Approx(20.0 * kSyntheticSmallCapsScale));
  // The outlines follow the glyph's size: "b" as a "B" at 14 units.
  PathBuilder drawn, expected;
  REQUIRE(append_text_outlines(sans, all, drawn).is_ok());
  const double s = 14.0 / sans.metrics().units_per_em;
  REQUIRE(sans.append_glyph(sans.glyph_for(U'A'), Affine{s, 0, 0, -s, 0, 0}, expected).is_ok());
  REQUIRE(sans.append_glyph(sans.glyph_for(U'B'), Affine{s, 0, 0, -s, all.glyphs[1].origin.x, 0}, expected)
              .is_ok());
  const Path a = drawn.build().value(), b = expected.build().value();
  REQUIRE(a.points().size() == b.points().size());
  for (std::size_t i = 0; i < a.points().size(); ++i) {
    CHECK(a.points()[i].x == Approx(b.points()[i].x).margin(1e-9));
    CHECK(a.points()[i].y == Approx(b.points()[i].y).margin(1e-9));
  }
}
