// Bitmap colour glyphs (color_glyph.h: has_color_bitmap, color_glyph_bitmap) against the fonts of
// tests/fonts/make_bitmap_test_fonts.py: an sbix font with outlines and a CBDT font without. The oracle
// for the pixels is FreeType itself, called directly by freetype_colour_bitmap.h (FT_Select_Size,
// FT_Load_Glyph with FT_LOAD_COLOR): the image curvescan returns must be FreeType's BGRA bitmap, byte for
// byte, in RGBA order (both premultiplied, so no rounding is involved and the comparison is exact).

#include <catch2/catch.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "curvescan/raster/file_io.h"
#include "curvescan/raster/limits.h"
#include "curvescan/text/color_glyph.h"
#include "freetype_colour_bitmap.h"

using namespace curvescan;

namespace {

std::string font_file(const char* name) {
  return std::string(CURVESCAN_SOURCE_DIR) + "/tests/fonts/" + name;
}

Font open_font(const char* name) {
  Result<Font> font = Font::open(font_file(name));
  REQUIRE(font.is_ok());
  return std::move(font).value();
}

bool same_pixels(const Image& a, const Image& b) {
  if (a.width() != b.width() || a.height() != b.height()) return false;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x)
      if (!(a.at(x, y) == b.at(x, y))) return false;
  return true;
}

ColorGlyphBitmap bitmap_of(const Font& font, char32_t c, double pixels_per_em) {
  Result<std::optional<ColorGlyphBitmap>> bitmap =
      color_glyph_bitmap(font, font.glyph_for(c), pixels_per_em, kMaxImagePixels);
  REQUIRE(bitmap.is_ok());
  REQUIRE(bitmap->has_value());
  return std::move(**bitmap);
}

}  // namespace

TEST_CASE("bitmap colour glyphs: an sbix glyph is a bitmap, its pixels FreeType's") {
  const Font font = open_font("CurvescanSbixTest.ttf");
  const GlyphId a = font.glyph_for(U'A');
  CHECK(color_glyph_kind(font, a) == ColorGlyphKind::kBitmap);
  CHECK(font.metrics().units_per_em == 1000);
  CHECK(font.advance(a) == 700);
  const ColorGlyphBitmap small = bitmap_of(font, U'A', 20);
  CHECK(small.strike_pixels_per_em == 20);
  CHECK(same_pixels(small.image, curvescan::test::freetype_colour_bitmap("CurvescanSbixTest.ttf", U'A', 0)));
  // The quadrants the generator draws: opaque red top left, white at alpha 128 (premultiplied) bottom right.
  CHECK(small.image.at(3, 3) == Rgba8{255, 0, 0, 255});
  CHECK(small.image.at(8, 8) == Rgba8{128, 128, 128, 128});
  CHECK(small.image.at(0, 0) == Rgba8{0, 0, 0, 0});
  // The 12-pixel image at 20 ppem is the box (0,0)-(600,600) in font units, y up.
  const Point top_left = small.image_to_font.apply(Point{0.0, 0.0});
  const Point bottom_right = small.image_to_font.apply(Point{12.0, 12.0});
  CHECK(top_left.x == Approx(0.0).margin(1e-9));
  CHECK(top_left.y == Approx(600.0));
  CHECK(bottom_right.x == Approx(600.0));
  CHECK(bottom_right.y == Approx(0.0).margin(1e-9));
  // The outline is there too (sbix fonts usually keep their glyf or CFF outlines).
  CHECK(font.glyph_path(a).is_ok());
}

TEST_CASE(
    "bitmap colour glyphs: the strike is the smallest at least as large as the size, else the largest") {
  const Font font = open_font("CurvescanSbixTest.ttf");
  CHECK(bitmap_of(font, U'A', 10).strike_pixels_per_em == 20);
  CHECK(bitmap_of(font, U'A', 20).strike_pixels_per_em == 20);
  CHECK(bitmap_of(font, U'A', 20.5).strike_pixels_per_em == 50);
  CHECK(bitmap_of(font, U'A', 400).strike_pixels_per_em == 50);
  const ColorGlyphBitmap large = bitmap_of(font, U'A', 400);
  CHECK(same_pixels(large.image, curvescan::test::freetype_colour_bitmap("CurvescanSbixTest.ttf", U'A', 1)));
}

TEST_CASE("bitmap colour glyphs: sbix origin offsets move the image") {
  const Font font = open_font("CurvescanSbixTest.ttf");
  // originOffsetX 5, originOffsetY -5 strike pixels at 20 ppem: 250 font units right and 250 down.
  const ColorGlyphBitmap b = bitmap_of(font, U'B', 20);
  const Point bottom_left = b.image_to_font.apply(Point{0.0, 12.0});
  CHECK(bottom_left.x == Approx(250.0));
  CHECK(bottom_left.y == Approx(-250.0));
}

TEST_CASE("bitmap colour glyphs: a CBDT font without outlines opens, with its metrics from head and hhea") {
  const Font font = open_font("CurvescanCbdtTest.ttf");
  const GlyphId a = font.glyph_for(U'A');
  CHECK(font.metrics().units_per_em == 1000);
  CHECK(font.metrics().ascender == 800);
  CHECK(font.metrics().descender == -200);
  CHECK(font.advance(a) == 700);
  CHECK(color_glyph_kind(font, a) == ColorGlyphKind::kBitmap);
  // "B" has no image in the strike (and no outline): not a bitmap glyph.
  CHECK(color_glyph_kind(font, font.glyph_for(U'B')) == ColorGlyphKind::kOutline);
  const ColorGlyphBitmap bitmap = bitmap_of(font, U'A', 64);
  CHECK(bitmap.strike_pixels_per_em == 50);
  CHECK(same_pixels(bitmap.image, curvescan::test::freetype_colour_bitmap("CurvescanCbdtTest.ttf", U'A', 0)));
  // No outline: FreeType loads an empty one (the face has no glyph outlines at all).
  const Result<Path> outline = font.glyph_path(a);
  REQUIRE(outline.is_ok());
  CHECK(outline->empty());
}

TEST_CASE("bitmap colour glyphs: an image beyond the pixel limit is refused") {
  const Font font = open_font("CurvescanSbixTest.ttf");
  const Result<std::optional<ColorGlyphBitmap>> refused =
      color_glyph_bitmap(font, font.glyph_for(U'A'), 20, 12 * 12 - 1);
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  // Fonts without colour strikes have no bitmap glyphs.
  const Font outlines = open_font("CurvescanColourTest.ttf");
  CHECK_FALSE(has_color_bitmap(outlines, outlines.glyph_for(U'D')));
  const Result<std::optional<ColorGlyphBitmap>> none =
      color_glyph_bitmap(outlines, outlines.glyph_for(U'D'), 20, kMaxImagePixels);
  REQUIRE(none.is_ok());
  CHECK_FALSE(none->has_value());
}

TEST_CASE("bitmap colour glyphs: a corrupt PNG in the strike is no bitmap, not a crash") {
  Result<std::vector<std::uint8_t>> bytes = read_file_bounded(
      font_file("CurvescanSbixTest.ttf"), ReadBound{1 << 20, "a test bound", FileKinds::kRegularOnly});
  REQUIRE(bytes.is_ok());
  // Overwrite every IDAT payload's first bytes: the PNGs keep their headers (so FreeType still finds the
  // metrics) but no longer inflate.
  std::vector<unsigned char> damaged(bytes->begin(), bytes->end());
  int damaged_chunks = 0;
  for (std::size_t i = 0; i + 12 < damaged.size(); ++i) {
    if (damaged[i] == 'I' && damaged[i + 1] == 'D' && damaged[i + 2] == 'A' && damaged[i + 3] == 'T') {
      for (std::size_t j = i + 4; j < i + 12; ++j) damaged[j] = 0xFF;
      ++damaged_chunks;
    }
  }
  REQUIRE(damaged_chunks == 4);  // two glyphs in two strikes
  Result<Font> font = Font::from_bytes(std::move(damaged), 0, "damaged sbix");
  REQUIRE(font.is_ok());
  const Result<std::optional<ColorGlyphBitmap>> bitmap =
      color_glyph_bitmap(*font, font->glyph_for(U'A'), 20, kMaxImagePixels);
  REQUIRE(bitmap.is_ok());
  CHECK_FALSE(bitmap->has_value());
}
