// Text ink (text_ink.h): the glyphs of a layout cut into pieces of one paint.
#include "curvescan/text/text_ink.h"

#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <utility>

#include "curvescan/text/color_glyph.h"

namespace curvescan {

Result<TextInk> text_ink(const Font& font, const TextLayout& layout, std::int64_t max_image_pixels) {
  TextInk ink;
  std::set<std::pair<const Font*, ColorGlyphKind>> warned;
  std::optional<PathBuilder> plain;  // the run of plain outlines being gathered
  const auto flush_plain = [&]() -> Status {
    if (!plain) return Status::ok();
    Result<Path> path = plain->build();
    plain.reset();
    if (!path) return path.error();
    if (!path->empty()) ink.pieces.push_back({std::move(path).value(), true, Color{}, nullptr, Affine{}});
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
        ink.pieces.push_back({std::move(layer.path), layer.foreground, layer.color, nullptr, Affine{}});
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
          if (path && !path->empty())
            ink.pieces.push_back({std::move(path).value(), true, Color{}, nullptr, Affine{}});
        }
        continue;
      }
      const Affine image_to_user = place * (*bitmap)->image_to_font;
      Result<Path> path = color_glyph_bitmap_rectangle(**bitmap, image_to_user);
      if (!path) return path.error();
      ink.pieces.push_back({std::move(path).value(), true, Color{},
                            std::make_shared<const ColorGlyphBitmap>(std::move(**bitmap)), image_to_user});
      continue;
    }
    if ((kind == ColorGlyphKind::kPaintGraph || kind == ColorGlyphKind::kSvg) &&
        warned.emplace(&face, kind).second) {
      ink.warnings.push_back(outline_only_warning(face, kind));
    }
    if (!plain) plain.emplace();
    CURVESCAN_PROPAGATE(face.append_glyph(glyph.glyph, place, *plain));
  }
  CURVESCAN_PROPAGATE(flush_plain());
  return ink;
}

}  // namespace curvescan
