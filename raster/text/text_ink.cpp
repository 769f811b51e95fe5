// Text ink (text_ink.h): the glyphs of a layout cut into pieces of one paint.
#include "curvescan/text/text_ink.h"

#include <optional>
#include <set>
#include <utility>

#include "curvescan/text/color_glyph.h"

namespace curvescan {

Result<TextInk> text_ink(const Font& font, const TextLayout& layout) {
  TextInk ink;
  std::set<std::pair<const Font*, ColorGlyphKind>> warned;
  std::optional<PathBuilder> plain;  // the run of plain outlines being gathered
  const auto flush_plain = [&]() -> Status {
    if (!plain) return Status::ok();
    Result<Path> path = plain->build();
    plain.reset();
    if (!path) return path.error();
    if (!path->empty()) ink.pieces.push_back({std::move(path).value(), true, Color{}});
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
        ink.pieces.push_back({std::move(layer.path), layer.foreground, layer.color});
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
