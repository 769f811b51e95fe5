// Fuzz target font: a font file through FreeType and curvescan's outline conversion (font/font.h), then
// each glyph's outline through the exact-area rasterizer (font/coverage_mask.h) at 16 pixels per em,
// and a short text through HarfBuzz shaping (font/text_layout.h); the colour-glyph readers
// (text/color_glyph.h) on each glyph: COLR version 0 layers and their outlines, the colour bitmap of
// the strike for 16 pixels per em (CBDT/CBLC, sbix; FreeType decodes the PNG) and its rectangle, and
// the "SVG " table's document.
//
// At most kMaxGlyphs glyphs are drawn (a face may claim 65535 of them) and masks are clipped to a
// 64 x 64 box around the origin, so that one input stays fast; a glyph whose outline reaches out to the
// 16-bit font-unit range still goes through the rasterizer, clipped. A colour bitmap may claim up to
// kMaxBitmapPixels pixels (above: refused by color_glyph_bitmap's limit, which is then what is driven).
#include "curvescan/text/font.h"

#include <algorithm>
#include <vector>

#include "curvescan/text/color_glyph.h"
#include "curvescan/text/coverage_mask.h"
#include "curvescan/text/text_layout.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {
namespace {

constexpr std::size_t kMaxGlyphs = 64;
constexpr std::int64_t kMaxBitmapPixels = std::int64_t{1} << 16;
constexpr double kPixelsPerEm = 16.0;
constexpr IntRect kMaskClip = {-32, -32, 32, 32};

IntRect intersect(IntRect a, IntRect b) noexcept {
  const IntRect r = {std::max(a.x0, b.x0), std::max(a.y0, b.y0), std::min(a.x1, b.x1), std::min(a.y1, b.y1)};
  return r.x0 < r.x1 && r.y0 < r.y1 ? r : IntRect{0, 0, 0, 0};
}

// The colour representations of `glyph`, each layer outline and bitmap rectangle rasterized as above.
void drive_color_glyph(const Font& font, GlyphId glyph, const Affine& font_to_device, MaskRenderer& renderer,
                       CoverageMask& mask) {
  (void)color_glyph_kind(font, glyph);
  const Result<std::vector<ColorLayerOutline>> layers =
      color_glyph_layer_outlines(font, glyph, font_to_device);
  if (layers) {
    for (const ColorLayerOutline& layer : *layers) {
      const IntRect box = intersect(pixel_box(layer.path), kMaskClip);
      (void)renderer.render(layer.path, box, FillRule::kNonZero, kDefaultFlattenTolerance, mask);
    }
  }
  if (has_color_bitmap(font, glyph)) {
    const Result<std::optional<ColorGlyphBitmap>> bitmap =
        color_glyph_bitmap(font, glyph, kPixelsPerEm, kMaxBitmapPixels);
    if (bitmap && *bitmap) {
      const Result<Path> rectangle =
          color_glyph_bitmap_rectangle(**bitmap, font_to_device * (*bitmap)->image_to_font);
      if (rectangle) {
        const IntRect box = intersect(pixel_box(*rectangle), kMaskClip);
        (void)renderer.render(*rectangle, box, FillRule::kNonZero, kDefaultFlattenTolerance, mask);
      }
    }
  }
  (void)color_glyph_svg_document(font, glyph);
}

}  // namespace

int fuzz_font(const std::uint8_t* data, std::size_t size) {
  Result<Font> font = Font::from_bytes(std::vector<unsigned char>(data, data + size), 0, "fuzz input");
  if (!font) return 0;
  (void)font->family_name();
  (void)font->glyph_for(U'A');
  const FontMetrics metrics = font->metrics();
  // Font units (y up) -> device pixels (y down) at kPixelsPerEm; a bogus units_per_em gives a bogus (maybe
  // non-finite) scale, which glyph_path must refuse cleanly.
  const double scale = kPixelsPerEm / metrics.units_per_em;
  const Affine font_to_device = Affine::scale(scale, -scale);

  MaskRenderer renderer;
  CoverageMask mask;
  const std::size_t glyphs = std::min(font->glyph_count(), kMaxGlyphs);
  for (std::size_t index = 0; index < glyphs; ++index) {
    const auto glyph = static_cast<GlyphId>(index);
    (void)font->advance(glyph);
    (void)font->freetype_scaled_glyph_path(glyph, kPixelsPerEm);
    const Result<Path> path = font->glyph_path(glyph, font_to_device);
    if (!path) continue;
    const IntRect box = intersect(pixel_box(*path), kMaskClip);
    (void)renderer.render(*path, box, FillRule::kNonZero, kDefaultFlattenTolerance, mask);
    drive_color_glyph(*font, glyph, font_to_device, renderer, mask);
  }

  TextStyle style;
  style.size = kPixelsPerEm;
  (void)text_path(*font, "Hi, fuzz! ffi \xC3\xA9", Point{0.0, 16.0}, style);
  return 0;
}

}  // namespace curvescan::fuzz
