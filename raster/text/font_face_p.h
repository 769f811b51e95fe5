// Font::Impl: the FreeType library and face, and the HarfBuzz face and font over the same bytes.
//
// Each Font owns its own FT_Library, so two Fonts can be used from two threads (FreeType's rule is one
// FT_Library per thread, FreeType docs "Multi-threading"). HarfBuzz reads the same in-memory bytes as
// FreeType through a read-only blob (hb_blob_create with HB_MEMORY_MODE_READONLY), so the file is read
// once and both libraries see the same font. The HarfBuzz font keeps its default scale of units_per_em,
// so shaped advances and offsets come out in font units, unhinted, like FreeType's FT_LOAD_NO_SCALE.
#pragma once

#include <ft2build.h>
#include FT_FREETYPE_H
#include <hb.h>

#include <string>
#include <unordered_map>
#include <vector>

#include "curvescan/text/font.h"
#include "font_file_cache_p.h"
#include "shaping_p.h"

namespace curvescan {

struct Font::Impl {
  detail::FontFileBytes bytes;  // the font file, shared by the Fonts of one file; FreeType and HarfBuzz point into it
  std::string source_name;
  std::string family_name;
  std::string style_name;
  OutlineFormat format = OutlineFormat::kOther;
  // Colour bitmap strikes ("CBDT"/"CBLC" or "sbix" read by FreeType): the face has fixed sizes and
  // FreeType marks it as colour. Such a face may have no outlines at all (FT_IS_SCALABLE false; FreeType
  // also reports an sbix face with outlines as not scalable, FreeType docs FT_HAS_SBIX).
  bool color_strikes = false;
  // The em and vertical metrics in font units: FreeType's, or for a bitmap-only face (where FreeType
  // leaves them 0) the "head" and "hhea" tables'.
  double units_per_em = 0.0, ascender = 0.0, descender = 0.0, line_height = 0.0;
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  hb_blob_t* blob = nullptr;
  hb_face_t* hb_face = nullptr;
  hb_font_t* hb_font = nullptr;
  // Shaped runs of this face (shaping_p.h), and the glyphs of the last run shaped. Mutable: a memo, not
  // part of the face's value; a Font is used from one thread (font.h).
  mutable detail::ShapeCache shape_cache;
  mutable std::vector<detail::ShapedGlyph> shaped;
  mutable std::unordered_map<std::uint32_t, bool> gsub_features;  // detail::has_gsub_feature's answers

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl();
};

}  // namespace curvescan
