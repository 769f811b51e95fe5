// Bitmap colour glyphs (color_glyph.h, color_glyph_bitmap): the PNG strikes of "CBDT"/"CBLC" (Google's
// colour bitmaps, OpenType spec "CBDT") and "sbix" (Apple's), which FreeType decodes when a glyph is
// loaded with FT_LOAD_COLOR from a selected strike (FreeType docs, FT_LOAD_COLOR: "load embedded color
// bitmap images ... the resulting color bitmaps ... have the FT_PIXEL_MODE_BGRA format", premultiplied
// alpha). FreeType also applies an sbix glyph's originOffsetX/Y: bitmap_left and bitmap_top place the
// image's top-left corner relative to the glyph origin, in the strike's pixels.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "curvescan/raster/limits.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/text/color_glyph.h"
#include "font_face_p.h"  // ft2build.h first

namespace curvescan {
namespace {

// The strike to draw at `pixels_per_em`: the smallest at least that large (a bitmap is scaled down
// rather than up, which keeps it sharp), else the largest. -1 when the face has none.
int strike_for(FT_Face face, double pixels_per_em) noexcept {
  int best = -1;
  double best_ppem = 0.0;
  for (int i = 0; i < face->num_fixed_sizes; ++i) {
    const double ppem = static_cast<double>(face->available_sizes[i].y_ppem) / 64.0;
    if (!(ppem > 0.0)) continue;
    const bool big_enough = ppem >= pixels_per_em, best_big_enough = best >= 0 && best_ppem >= pixels_per_em;
    const bool better = best < 0 || (big_enough && (!best_big_enough || ppem < best_ppem)) ||
                        (!big_enough && !best_big_enough && ppem > best_ppem);
    if (better) {
      best = i;
      best_ppem = ppem;
    }
  }
  return best;
}

// Loads `glyph` from strike `strike` with FT_LOAD_COLOR (`flags` adds to it); true when it is a colour
// bitmap there.
bool load_from_strike(FT_Face face, GlyphId glyph, int strike, FT_Int32 flags) noexcept {
  if (strike < 0 || FT_Select_Size(face, strike) != 0) return false;
  if (FT_Load_Glyph(face, glyph, FT_LOAD_COLOR | flags) != 0) return false;
  const FT_GlyphSlot slot = face->glyph;
  return slot->format == FT_GLYPH_FORMAT_BITMAP && slot->bitmap.pixel_mode == FT_PIXEL_MODE_BGRA;
}

}  // namespace

bool has_color_bitmap(const Font& font, GlyphId glyph) noexcept {
  const Font::Impl& impl = font.impl();
  if (!impl.color_strikes || glyph >= static_cast<GlyphId>(impl.face->num_glyphs)) return false;
  // The metrics say whether the strike has an image for the glyph without decoding its PNG.
  if (!load_from_strike(impl.face, glyph, 0, FT_LOAD_BITMAP_METRICS_ONLY)) return false;
  return impl.face->glyph->bitmap.width > 0 && impl.face->glyph->bitmap.rows > 0;
}

Result<std::optional<ColorGlyphBitmap>> color_glyph_bitmap(const Font& font, GlyphId glyph,
                                                           double pixels_per_em, std::int64_t max_pixels) {
  const Font::Impl& impl = font.impl();
  if (!impl.color_strikes || glyph >= static_cast<GlyphId>(impl.face->num_glyphs))
    return std::optional<ColorGlyphBitmap>();
  const int strike = strike_for(impl.face, std::isfinite(pixels_per_em) ? pixels_per_em : 0.0);
  // The size first, from the metrics alone (a PNG header), so that a hostile image of 32767 x 32767
  // pixels (FreeType's own bound) is refused before FreeType decodes it.
  if (!load_from_strike(impl.face, glyph, strike, FT_LOAD_BITMAP_METRICS_ONLY))
    return std::optional<ColorGlyphBitmap>();
  const std::int64_t claimed = std::int64_t{impl.face->glyph->bitmap.width} * impl.face->glyph->bitmap.rows;
  if (claimed > max_pixels) {
    return Error{ErrorKind::kLimitExceeded, "the " + std::to_string(impl.face->glyph->bitmap.width) + " x " +
                                                std::to_string(impl.face->glyph->bitmap.rows) +
                                                " colour bitmap of glyph " + std::to_string(glyph) + " of " +
                                                impl.source_name + " is beyond the pixel limit"};
  }
  if (!load_from_strike(impl.face, glyph, strike, 0)) return std::optional<ColorGlyphBitmap>();
  const FT_GlyphSlot slot = impl.face->glyph;
  const FT_Bitmap& bitmap = slot->bitmap;
  const std::int64_t width = bitmap.width, height = bitmap.rows;
  if (width == 0 || height == 0) return std::optional<ColorGlyphBitmap>();
  if (!image_size_within_limits(width, height) || width * height > max_pixels) {
    return Error{ErrorKind::kLimitExceeded, "the " + std::to_string(width) + " x " + std::to_string(height) +
                                                " colour bitmap of glyph " + std::to_string(glyph) + " of " +
                                                impl.source_name + " is beyond the pixel limit"};
  }
  if (bitmap.buffer == nullptr || std::abs(bitmap.pitch) < 4 * width) {
    return Error{ErrorKind::kCorruptInput, "the colour bitmap of glyph " + std::to_string(glyph) + " of " +
                                               impl.source_name + " is malformed"};
  }
  ColorGlyphBitmap result;
  result.image = Image(static_cast<int>(width), static_cast<int>(height));
  for (int y = 0; y < height; ++y) {
    // A negative pitch means the rows are stored bottom-up (FreeType docs, FT_Bitmap).
    const unsigned char* source = bitmap.pitch >= 0
                                      ? bitmap.buffer + static_cast<std::ptrdiff_t>(y) * bitmap.pitch
                                      : bitmap.buffer + (height - 1 - y) * -bitmap.pitch;
    Rgba8* row = result.image.row(y);
    for (int x = 0; x < width; ++x, source += 4) {
      // BGRA, premultiplied: Image's encoding in another order. A channel above alpha (invalid) is clamped.
      const std::uint8_t a = source[3];
      row[x] = Rgba8{std::min(source[2], a), std::min(source[1], a), std::min(source[0], a), a};
    }
  }
  const FT_Bitmap_Size& size = impl.face->available_sizes[strike];
  const double y_ppem = static_cast<double>(size.y_ppem) / 64.0;
  const double x_ppem = size.x_ppem > 0 ? static_cast<double>(size.x_ppem) / 64.0 : y_ppem;
  result.strike_pixels_per_em = y_ppem;
  const double sx = impl.units_per_em / x_ppem, sy = impl.units_per_em / y_ppem;
  // Image pixel (i, j), j down, covers font units x = (left + i)·sx, y = (top − j)·sy (y up).
  result.image_to_font = Affine{sx, 0.0, 0.0, -sy, slot->bitmap_left * sx, slot->bitmap_top * sy};
  return std::optional<ColorGlyphBitmap>(std::move(result));
}

Result<Path> color_glyph_bitmap_rectangle(const ColorGlyphBitmap& bitmap, const Affine& image_to_user) {
  const double w = bitmap.image.width(), h = bitmap.image.height();
  PathBuilder rectangle;
  rectangle.move_to(image_to_user.apply(Point{0.0, 0.0}));
  rectangle.line_to(image_to_user.apply(Point{w, 0.0}));
  rectangle.line_to(image_to_user.apply(Point{w, h}));
  rectangle.line_to(image_to_user.apply(Point{0.0, h}));
  rectangle.close();
  return rectangle.build();
}

}  // namespace curvescan
