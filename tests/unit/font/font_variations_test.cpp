// Variable fonts (Font::set_variations; OpenType "fvar", CSS Fonts 4 7.13 font-variation-settings).
// Oracles: the font's own named instances, opened by FreeType with the instance in the face index
// (FreeType docs, FT_Open_Face: bits 16-30 of face_index select a named instance), and FreeType's
// advance (HVAR) against HarfBuzz's shaped advance at the same coordinates.
#include <ft2build.h>
#include FT_FREETYPE_H

#include <catch2/catch.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "curvescan/text/text_layout.h"
#include "font_files.h"

using namespace curvescan;

namespace {

Font open_font(const char* file, int face_index = 0) {
  Result<Font> font = Font::open(file, face_index);
  REQUIRE(font.is_ok());
  return std::move(font).value();
}

// The face index of the named instance called `style` (FreeType numbers instances from 1).
int named_instance(const char* file, const std::string& style) {
  for (int instance = 1; instance < 64; ++instance) {
    const Result<Font> font = Font::open(file, instance << 16);
    if (!font) break;
    if (font->style_name() == style) return instance << 16;
  }
  FAIL("no named instance " << style);
  return 0;
}

// The coordinates of a path's points, for an exact comparison of two outlines.
std::vector<double> points_of(const Path& path) {
  std::vector<double> coordinates;
  for (const Point& p : path.points()) {
    coordinates.push_back(p.x);
    coordinates.push_back(p.y);
  }
  return coordinates;
}

double shaped_advance(const Font& font, std::u32string_view text) {
  TextStyle style;
  style.size = font.metrics().units_per_em;  // one user unit per font unit
  const Result<TextLayout> layout = layout_text(font, text, {0.0, 0.0}, style);
  REQUIRE(layout.is_ok());
  REQUIRE(layout->glyphs.size() == 1);
  return layout->glyphs.front().advance;
}

}  // namespace

TEST_CASE("variations: a variable font at wght 700 draws its Bold named instance", "[font][variations]") {
  Font font = open_font(kInterVariableFile);
  REQUIRE(font.is_variable());
  CHECK(font.has_variation_axis(font_feature_tag("wght")));
  CHECK_FALSE(font.has_variation_axis(font_feature_tag("XTRA")));
  const Font bold = open_font(kInterVariableFile, named_instance(kInterVariableFile, "Bold"));
  const GlyphId o = font.glyph_for(U'o');
  const Result<Path> regular_o = font.glyph_path(o);
  REQUIRE(regular_o.is_ok());
  const FontVariation wght700[] = {{font_feature_tag("wght"), 700.0}};
  REQUIRE(font.set_variations(wght700).is_ok());
  const Result<Path> varied_o = font.glyph_path(o), bold_o = bold.glyph_path(o);
  REQUIRE(varied_o.is_ok());
  REQUIRE(bold_o.is_ok());
  // Both are FreeType's outline at the same design coordinates: the same points exactly.
  CHECK(points_of(*varied_o) == points_of(*bold_o));
  CHECK(points_of(*varied_o) != points_of(*regular_o));
  CHECK(font.advance(o) == bold.advance(o));
  CHECK(font.advance(o) > open_font(kInterVariableFile).advance(o));
}

TEST_CASE("variations: shaping follows the coordinates as the outlines do", "[font][variations]") {
  Font font = open_font(kInterVariableFile);
  // The shaped run is cached per face: after set_variations the run must be shaped again.
  const double regular = shaped_advance(font, U"o");
  CHECK(regular == font.advance(font.glyph_for(U'o')));
  const FontVariation heavy[] = {{font_feature_tag("wght"), 900.0}};
  REQUIRE(font.set_variations(heavy).is_ok());
  const double bold = shaped_advance(font, U"o");
  // HarfBuzz (hb_font_set_var_coords_design) and FreeType (HVAR through FT_Get_Advance) agree to the
  // font unit: HarfBuzz rounds the varied advance to an integer, FreeType keeps 16.16 and rounds too.
  CHECK(bold == Approx(font.advance(font.glyph_for(U'o'))).margin(1.0));
  CHECK(bold > regular);
}

TEST_CASE("variations: out-of-range values are clamped, unknown axes and NaN ignored", "[font][variations]") {
  Font clamped = open_font(kInterVariableFile);
  Font at_max = open_font(kInterVariableFile);
  const FontVariation beyond[] = {{font_feature_tag("wght"), 5000.0},
                                  {font_feature_tag("ZZZZ"), 3.0},
                                  {font_feature_tag("opsz"), std::nan("")}};
  const FontVariation max[] = {{font_feature_tag("wght"), 900.0}};
  REQUIRE(clamped.set_variations(beyond).is_ok());
  REQUIRE(at_max.set_variations(max).is_ok());
  const GlyphId a = clamped.glyph_for(U'a');
  CHECK(points_of(*clamped.glyph_path(a)) == points_of(*at_max.glyph_path(a)));
  // A face without axes: nothing to do, nothing fails.
  Font dejavu = open_font(kDejaVuSansFile);
  CHECK_FALSE(dejavu.is_variable());
  CHECK(dejavu.set_variations(max).is_ok());
}
