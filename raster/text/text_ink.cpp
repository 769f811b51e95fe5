// Text ink (text_ink.h): the glyphs of a layout cut into pieces of one paint.
#include "curvescan/text/text_ink.h"

#include <cmath>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "curvescan/text/color_glyph.h"

namespace curvescan {
namespace {

// A piece filled with the text's colour (foreground) or with `color`, no image or document.
TextInkPiece fill_piece(Path path, bool foreground = true, Color color = Color{}) {
  TextInkPiece piece;
  piece.path = std::move(path);
  piece.foreground = foreground;
  piece.color = color;
  return piece;
}

}  // namespace

Result<TextInk> text_ink(const Font& font, const TextLayout& layout, std::int64_t max_image_pixels) {
  TextInk ink;
  std::set<std::pair<const Font*, ColorGlyphKind>> warned;
  std::map<std::pair<const Font*, const char*>, std::shared_ptr<const std::string>> svg_documents;
  std::optional<PathBuilder> plain;  // the run of plain outlines being gathered
  const auto flush_plain = [&]() -> Status {
    if (!plain) return Status::ok();
    Result<Path> path = plain->build();
    plain.reset();
    if (!path) return path.error();
    if (!path->empty()) ink.pieces.push_back(fill_piece(std::move(path).value()));
    return Status::ok();
  };
  for (const PositionedGlyph& glyph : layout.glyphs) {
    const Font& face = glyph.font != nullptr ? *glyph.font : font;
    const Affine place = glyph_to_user(face, layout, glyph);
    const ColorGlyphKind kind = color_glyph_kind(face, glyph.glyph);
    if (kind == ColorGlyphKind::kLayers) {
      CURVESCAN_PROPAGATE(flush_plain());
      Result<std::vector<ColorLayerOutline>> layers = color_glyph_layer_outlines(face, glyph.glyph, place);
      if (!layers) return layers.error();
      for (ColorLayerOutline& layer : *layers)
        ink.pieces.push_back(fill_piece(std::move(layer.path), layer.foreground, layer.color));
      continue;
    }
    if (kind == ColorGlyphKind::kBitmap) {
      CURVESCAN_PROPAGATE(flush_plain());
      // The em in user units (the layout's pixels): the strike is chosen for it.
      const double pixels_per_em = std::hypot(place.c, place.d) * face.metrics().units_per_em;
      Result<std::optional<ColorGlyphBitmap>> bitmap =
          color_glyph_bitmap(face, glyph.glyph, pixels_per_em, max_image_pixels);
      if (!bitmap) return bitmap.error();
      if (!*bitmap) {
        // An image FreeType cannot decode (a corrupt or cut PNG): the outline, where the face has one.
        ink.warnings.push_back("the colour bitmap of glyph " + std::to_string(glyph.glyph) + " of font '" +
                               face.source_name() +
                               "' cannot be decoded; its outline is drawn where it has one");
        PathBuilder outline;
        if (face.append_glyph(glyph.glyph, place, outline)) {
          Result<Path> path = outline.build();
          if (path && !path->empty()) ink.pieces.push_back(fill_piece(std::move(path).value()));
        }
        continue;
      }
      const Affine image_to_user = place * (*bitmap)->image_to_font;
      Result<Path> path = color_glyph_bitmap_rectangle(**bitmap, image_to_user);
      if (!path) return path.error();
      TextInkPiece piece = fill_piece(std::move(path).value());
      piece.bitmap = std::make_shared<const ColorGlyphBitmap>(std::move(**bitmap));
      piece.image_to_user = image_to_user;
      ink.pieces.push_back(std::move(piece));
      continue;
    }
    if (kind == ColorGlyphKind::kSvg) {
      CURVESCAN_PROPAGATE(flush_plain());
      // One copy per document, not per glyph: the glyphs of one document share its bytes (color_glyph.h).
      const std::string_view bytes = color_glyph_svg_document(face, glyph.glyph);
      std::shared_ptr<const std::string>& document = svg_documents[{&face, bytes.data()}];
      if (!document) document = std::make_shared<const std::string>(bytes);
      Result<SvgGlyphArea> area = svg_glyph_area(face, glyph.glyph, place);
      if (!area) return area.error();
      TextInkPiece piece = fill_piece(std::move(area->path));
      piece.svg_document = document;
      piece.svg_glyph = glyph.glyph;
      piece.units_per_em = face.metrics().units_per_em;
      piece.svg_to_user = place * Affine::scale(1.0, -1.0);  // the outline's y-up placement, flipped
      piece.path_is_outline = area->is_outline;
      ink.pieces.push_back(std::move(piece));
      continue;
    }
    if (kind == ColorGlyphKind::kPaintGraph && warned.emplace(&face, kind).second) {
      ink.warnings.push_back(outline_only_warning(face, kind));
    }
    if (!plain) plain.emplace();
    CURVESCAN_PROPAGATE(face.append_glyph(glyph.glyph, place, *plain));
  }
  CURVESCAN_PROPAGATE(flush_plain());
  return ink;
}

}  // namespace curvescan
