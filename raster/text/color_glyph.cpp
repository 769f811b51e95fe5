// Colour glyphs (color_glyph.h) through FreeType's COLR/CPAL API (FreeType docs, "Glyph Color
// Management": FT_Get_Color_Glyph_Layer walks a COLR version 0 glyph's layers, FT_Palette_Select gives a
// CPAL palette), HarfBuzz's SVG-table lookup (hb_ot_color_glyph_reference_svg) and the COLR version 1
// glyph list read from the table (has_paint_graph).
#include "curvescan/text/color_glyph.h"

#include <algorithm>
#include <cstdint>

#include "curvescan/raster/path_builder.h"
#include "font_face_p.h"  // ft2build.h first: FreeType's header macros below need it
#include FT_COLOR_H
#include <hb-ot.h>

namespace curvescan {
namespace {

constexpr FT_UInt kForegroundIndex = 0xFFFF;  // COLR: "the text foreground color"

bool has_layers(FT_Face face, GlyphId glyph) noexcept {
  FT_LayerIterator iterator{};
  iterator.p = nullptr;
  FT_UInt layer_glyph = 0, color_index = 0;
  return FT_Get_Color_Glyph_Layer(face, glyph, &layer_glyph, &color_index, &iterator) != 0;
}

std::uint32_t read_be(const unsigned char* bytes, int count) noexcept {
  std::uint32_t value = 0;
  for (int i = 0; i < count; ++i) value = value << 8 | bytes[i];
  return value;
}

// Whether the COLR table has a version 1 record (a BaseGlyphPaintRecord) for `glyph`. Read from the table
// itself (OpenType spec, COLR: the version 1 header adds baseGlyphListOffset at byte 14; the BaseGlyphList
// is a uint32 count and 6-byte records {uint16 glyphID, Offset32 paint} sorted by glyph ID): Debian 12's
// FreeType 2.12.1 answers FT_Get_Color_Glyph_Paint with "no paint" for such records (its COLR version 1
// API is marked experimental), which would turn the warning off. A table cut short has no records.
bool has_paint_graph(hb_face_t* face, GlyphId glyph) noexcept {
  hb_blob_t* table = hb_face_reference_table(face, HB_TAG('C', 'O', 'L', 'R'));
  unsigned length = 0;
  const auto* bytes = reinterpret_cast<const unsigned char*>(hb_blob_get_data(table, &length));
  bool found = false;
  if (bytes != nullptr && length >= 18 && read_be(bytes, 2) >= 1) {
    const std::uint64_t list = read_be(bytes + 14, 4);
    if (list != 0 && list + 4 <= length) {
      const std::uint64_t records = read_be(bytes + list, 4);
      const std::uint64_t usable = std::min<std::uint64_t>(records, (length - list - 4) / 6);
      std::uint64_t low = 0, high = usable;  // binary search in [low, high)
      while (low < high && !found) {
        const std::uint64_t mid = low + (high - low) / 2;
        const std::uint32_t id = read_be(bytes + list + 4 + 6 * mid, 2);
        if (id == glyph) {
          found = true;
        } else if (id < glyph) {
          low = mid + 1;
        } else {
          high = mid;
        }
      }
    }
  }
  hb_blob_destroy(table);
  return found;
}

bool has_svg_document(hb_face_t* face, GlyphId glyph) noexcept {
  hb_blob_t* document = hb_ot_color_glyph_reference_svg(face, glyph);
  const bool found = hb_blob_get_length(document) > 0;
  hb_blob_destroy(document);
  return found;
}

}  // namespace

ColorGlyphKind color_glyph_kind(const Font& font, GlyphId glyph) noexcept {
  const Font::Impl& impl = font.impl();
  if (glyph >= static_cast<GlyphId>(impl.face->num_glyphs)) return ColorGlyphKind::kOutline;
  if (has_paint_graph(impl.hb_face, glyph)) {
    if (has_color_bitmap(font, glyph)) return ColorGlyphKind::kBitmap;
    return has_svg_document(impl.hb_face, glyph) ? ColorGlyphKind::kSvg : ColorGlyphKind::kPaintGraph;
  }
  if (has_layers(impl.face, glyph)) return ColorGlyphKind::kLayers;
  if (has_color_bitmap(font, glyph)) return ColorGlyphKind::kBitmap;
  if (has_svg_document(impl.hb_face, glyph)) return ColorGlyphKind::kSvg;
  return ColorGlyphKind::kOutline;
}

std::vector<ColorGlyphLayer> color_glyph_layers(const Font& font, GlyphId glyph) {
  std::vector<ColorGlyphLayer> layers;
  if (color_glyph_kind(font, glyph) != ColorGlyphKind::kLayers) return layers;
  const FT_Face face = font.impl().face;
  FT_Palette_Data palettes{};
  FT_Color* palette = nullptr;
  // Without a CPAL table (or with an empty one) only the foreground index 0xFFFF is in range.
  if (FT_Palette_Data_Get(face, &palettes) != 0 || palettes.num_palettes == 0 ||
      FT_Palette_Select(face, 0, &palette) != 0) {
    palette = nullptr;
    palettes.num_palette_entries = 0;
  }
  FT_LayerIterator iterator{};
  iterator.p = nullptr;
  FT_UInt layer_glyph = 0, color_index = 0;
  while (FT_Get_Color_Glyph_Layer(face, glyph, &layer_glyph, &color_index, &iterator) != 0) {
    // A layer naming a glyph the face does not have (a corrupt table) is left out.
    if (layer_glyph >= static_cast<FT_UInt>(face->num_glyphs)) continue;
    ColorGlyphLayer layer;
    layer.glyph = layer_glyph;
    // FreeType ends the layer list at an index past the palette's end; the test stays as a guard.
    layer.foreground =
        color_index == kForegroundIndex || palette == nullptr || color_index >= palettes.num_palette_entries;
    if (!layer.foreground) {
      const FT_Color& c = palette[color_index];  // CPAL stores BGRA, 8 bits each, straight alpha
      layer.color = Color::from_rgba8(c.red, c.green, c.blue, c.alpha);
    }
    layers.push_back(layer);
  }
  return layers;
}

Result<std::vector<ColorLayerOutline>> color_glyph_layer_outlines(const Font& font, GlyphId glyph,
                                                                  const Affine& place) {
  std::vector<ColorLayerOutline> outlines;
  for (const ColorGlyphLayer& layer : color_glyph_layers(font, glyph)) {
    PathBuilder builder;
    CURVESCAN_PROPAGATE(font.append_glyph(layer.glyph, place, builder));
    Result<Path> path = builder.build();
    if (!path) return path.error();
    if (!path->empty()) outlines.push_back({std::move(path).value(), layer.foreground, layer.color});
  }
  return outlines;
}

std::string_view color_glyph_svg_document(const Font& font, GlyphId glyph) {
  if (glyph >= static_cast<GlyphId>(font.impl().face->num_glyphs)) return {};
  // A sub-blob of the "SVG " table's blob, which the face's table accelerator holds until the face is
  // destroyed: the bytes outlive this reference.
  hb_blob_t* document = hb_ot_color_glyph_reference_svg(font.impl().hb_face, glyph);
  unsigned length = 0;
  const char* data = hb_blob_get_data(document, &length);
  const std::string_view bytes = data != nullptr ? std::string_view(data, length) : std::string_view();
  hb_blob_destroy(document);
  return bytes;
}

Result<SvgGlyphArea> svg_glyph_area(const Font& font, GlyphId glyph, const Affine& place) {
  PathBuilder outline;
  CURVESCAN_PROPAGATE(font.append_glyph(glyph, place, outline));
  Result<Path> path = outline.build();
  if (!path) return path.error();
  if (!path->empty()) return SvgGlyphArea{std::move(path).value(), true};
  const FontMetrics metrics = font.metrics();
  const double advance = font.advance(glyph);
  PathBuilder cell;
  cell.move_to(place.apply(Point{0.0, metrics.descender}));
  cell.line_to(place.apply(Point{advance, metrics.descender}));
  cell.line_to(place.apply(Point{advance, metrics.ascender}));
  cell.line_to(place.apply(Point{0.0, metrics.ascender}));
  cell.close();
  Result<Path> cell_path = cell.build();
  if (!cell_path) return cell_path.error();
  return SvgGlyphArea{std::move(cell_path).value(), false};
}

std::string outline_only_warning(const Font& font, ColorGlyphKind kind) {
  const std::string name = font.family_name().empty() ? font.source_name() : font.family_name();
  switch (kind) {
    case ColorGlyphKind::kPaintGraph:
      return "COLR v1 colour glyphs in font '" + name + "' are drawn as plain outlines";
    case ColorGlyphKind::kSvg:
      return "SVG colour glyphs in font '" + name + "' are drawn as plain outlines";
    default:
      return {};
  }
}

}  // namespace curvescan
