// FreeType's own colour bitmap of a character (FT_LOAD_COLOR from one strike of a CBDT or sbix font in
// tests/fonts/), as premultiplied RGBA8: the oracle the bitmap colour-glyph tests compare curvescan's
// decoding and drawing with. FreeType gives premultiplied BGRA.
#pragma once

#include <ft2build.h>
#include FT_FREETYPE_H

#include <catch2/catch.hpp>
#include <string>

#include "curvescan/raster/image.h"

namespace curvescan::test {

inline Image freetype_colour_bitmap(const std::string& font_name, char32_t character, int strike) {
  FT_Library library = nullptr;
  REQUIRE(FT_Init_FreeType(&library) == 0);
  FT_Face face = nullptr;
  const std::string file = std::string(CURVESCAN_SOURCE_DIR) + "/tests/fonts/" + font_name;
  REQUIRE(FT_New_Face(library, file.c_str(), 0, &face) == 0);
  REQUIRE(FT_Select_Size(face, strike) == 0);
  REQUIRE(FT_Load_Glyph(face, FT_Get_Char_Index(face, character), FT_LOAD_COLOR) == 0);
  const FT_Bitmap& bitmap = face->glyph->bitmap;
  REQUIRE(bitmap.pixel_mode == FT_PIXEL_MODE_BGRA);
  Image image(static_cast<int>(bitmap.width), static_cast<int>(bitmap.rows));
  for (unsigned y = 0; y < bitmap.rows; ++y) {
    for (unsigned x = 0; x < bitmap.width; ++x) {
      const unsigned char* p = bitmap.buffer + y * bitmap.pitch + 4 * x;
      image.at(static_cast<int>(x), static_cast<int>(y)) = Rgba8{p[2], p[1], p[0], p[3]};
    }
  }
  FT_Done_Face(face);
  FT_Done_FreeType(library);
  return image;
}

}  // namespace curvescan::test
