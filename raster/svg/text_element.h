// SVG <text> (SVG 1.1 chapter 10, SVG 2 chapter 11 as docs/svg.md states): the character data of a <text>
// element and its <tspan>s, <a>s and <textPath>s becomes glyph outlines, one Path per run of glyphs that
// share a style (and one per decoration), to be filled and stroked like any shape by the document renderer.
//
// Steps (SVG 2 11.8.3 "Text layout algorithm", in the order SVG 1.1 defines its effects):
//  1. collect the character data in document order, each fragment with the computed style of the element
//     holding it (display:none elements contribute nothing); white space per white-space or xml:space
//     (text_whitespace.h: a kept newline is a forced line break, a new line and chunk), then text-transform
//     (text_transform.h);
//  2. per-character x, y, dx, dy, rotate from the lists of the elements, descendants' values winning over
//     their ancestors' (SVG 1.1 10.5); an absolute x or y, and a textPath, start a new text chunk;
//  3. per chunk: the bidi algorithm (bidi.h) with the <text>'s direction as paragraph direction and
//     unicode-bidi of the elements as injected bidi controls (CSS Writing Modes 3 2.4.2); runs of one style
//     and one level shaped by HarfBuzz (text_layout.h) and placed in visual order; letter-spacing and
//     word-spacing after each glyph; dx and dy accumulated in logical order, so kerning stays across them;
//  4. textLength / lengthAdjust, innermost elements first; text-anchor per chunk (start and end follow the
//     paragraph direction); dominant-baseline / alignment-baseline and baseline-shift from the fonts'
//     metrics; on a textPath, each glyph placed by its midpoint and turned to the path's tangent;
//  5. text-decoration of each declaring element, with that element's style;
//  6. vertical writing modes (tb, vertical-rl, vertical-lr): the chunk laid out as above along its line,
//     turned by 90 degrees; CJK characters stand upright, shaped with HarfBuzz's vertical direction
//     (vertical advances, origins and 'vert' alternates) and centred on the line, others are turned
//     sideways on the central baseline (CSS Writing Modes 3 text-orientation: mixed; upright and
//     sideways, and SVG 1.1's glyph-orientation-vertical 0 and 90, stand or turn every character).
// A COLR version 0 colour glyph is drawn as its layers (color_glyph.h), each a piece of its own filled
// with its palette colour or the element's fill, then its stroke along the glyph's own outline. A bitmap
// colour glyph (CBDT, sbix) is a piece of its own that carries the image of the strike nearest the font
// size (in user units); its stroke follows its outline when it has one (sbix fonts usually do), else
// there is none. An SVG-in-OpenType glyph is a piece of its own that carries its document, which the
// renderer draws.
// <tref> draws the referenced element's character data; <altGlyph> is drawn as a <tspan> (SVG fonts are
// not supported), with a warning. textPath method="stretch" bends plain glyph outlines along the path,
// their decorations and cells with them (text_path_bend.h; colour glyphs are placed as method="align"
// places them). Not supported (a
// warning): sideways writing modes (laid out as vertical-rl), glyph-orientation-horizontal. A character the
// run's face lacks is drawn from the installed face fontconfig's fallback finds (font_fallback.h); .notdef
// only when none has it. The same pieces are a <clipPath> child's geometry (document.cpp). The object
// bounding box is the union of the glyph cells (SVG 2 8.10), not of the outlines (bent with stretched
// glyphs). Code: step 1 is
// text_content.h; the others are a layout job (text_layout_job.h) over text_positions.cpp (step 2),
// text_chunk_layout.cpp (steps 3-4 and 6), text_decoration.cpp (step 5) and text_element.cpp (chunks,
// textPaths, the outlines).
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "computed_style.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/path.h"
#include "curvescan/text/color_glyph.h"
#include "text_fonts.h"

namespace curvescan::svg::detail {

/// An SVG-in-OpenType glyph's document and glyph index.
struct SvgGlyphDocument {
  /// The font the document is in, and the document as the font stores it (color_glyph_svg_document): the
  /// font's own bytes, valid as long as the font (the renderer's FontCache keeps it for the render). The
  /// pair names the document: the renderer parses each once per render, however many glyphs draw from it.
  const Font* font = nullptr;
  std::string_view document;
  GlyphId glyph = kNotdefGlyph;
  double units_per_em = 1000.0;  ///< what the document's percentages are of
  /// The piece's path is the glyph's outline (not its cell): what is filled when the document cannot be
  /// drawn.
  bool path_is_outline = false;
};

/// Glyph outlines in the user space of the <text> element, and the style to paint them with (fill-rule
/// is nonzero: glyph outlines are defined for it, font.h).
struct TextPiece {
  Path path;
  ComputedStyle style;
  /// The object bounding box of the whole <text> element (the same in every piece of it): the union of
  /// its glyph cells — each glyph's advance by the font's ascent and descent, placed, rotated and on its
  /// path as the glyph is (SVG 2 8.10: "all glyphs occupy the full glyph cell") — and its decorations.
  /// What objectBoundingBox units of its paint servers, clip paths, masks and filters refer to, for a
  /// <tspan> as for the <text> (a tspan has no box of its own). nullopt when no glyph is drawn.
  std::optional<Rect> object_box;
  /// A bitmap colour glyph (color_glyph.h): `path` is then the image's rectangle in user space, to be
  /// filled with the image mapped by `image_to_user` (as <image> is drawn) in the fill pass only, faded
  /// by the fill's alpha, fill-opacity and group opacity as a COLR layer is. Null for outlines.
  std::shared_ptr<const ColorGlyphBitmap> bitmap;
  Affine image_to_user;
  /// An SVG-in-OpenType glyph (color_glyph.h): the document (as the font stores it, possibly gzip-
  /// compressed) and the glyph, whose element "glyphN" is drawn by the renderer mapped by `svg_to_user`
  /// (font units, y down, to user space) in the fill pass only, faded as a bitmap glyph is. `path` is then
  /// the glyph's outline, or its cell where it has none (for clipping and measuring). Null otherwise.
  std::shared_ptr<const SvgGlyphDocument> svg_glyph = nullptr;
  Affine svg_to_user = Affine{};
};

/// The computed style of a child element (the document renderer's cascade).
using ChildStyle = std::function<ComputedStyle(const pugi::xml_node& element, const ComputedStyle& parent)>;

struct TextContext {
  double viewport_width = 100.0;  ///< what 100% of an x or dx means
  double viewport_height = 100.0;
  Resolution dpi;  ///< of in, cm, mm, pt and pc across and down
  /// x-like lengths (x, dx, textLength): 100% is the viewport's width; physical units at dpi.x.
  [[nodiscard]] LengthAxis horizontal() const noexcept { return {viewport_width, dpi.x}; }
  /// y-like lengths (y, dy): the viewport's height, dpi.y.
  [[nodiscard]] LengthAxis vertical() const noexcept { return {viewport_height, dpi.y}; }
  int max_depth = 256;  ///< deepest <tspan> nesting walked (deeper content is skipped with a warning)
  /// The geometry of the element with this id in the text's user space (its transform applied), for
  /// <textPath href>; nullopt when there is none or it is not a shape.
  std::function<std::optional<Path>(const std::string& id)> path_for_id;
  /// The element with this id (for <tref> and the pathLength of a <textPath>'s path), or a null node.
  std::function<pugi::xml_node(const std::string& id)> element_for_id;
  /// Largest bitmap colour glyph decoded, in pixels (the document's pixel limit); a larger one is not drawn
  /// (a warning).
  std::int64_t max_image_pixels = kMaxImagePixels;
  /// Whether the conditional processing attributes of a text content element hold, as the document's
  /// resolve pass decided (document_index.h): a <tspan>, <tref>, <textPath>, <a> or <altGlyph> whose
  /// conditions fail is not rendered, with its content (SVG 1.1 5.8.1, SVG 2 5.8.1 "conditional
  /// processing").
  std::function<bool(const pugi::xml_node& element)> conditions_hold = [](const pugi::xml_node&) {
    return true;
  };
  /// User space -> the device pixels the text is drawn in (the element's transforms and the output's
  /// scale), for choosing a bitmap colour glyph's strike by the pixels it covers; the identity where the
  /// pieces are only measured.
  Affine user_to_device = Affine::identity();
};

/// The pieces of `text` (a <text> element with computed style `style`), in painting order. Problems are
/// warnings (a missing font falls back; no font at all draws nothing), never errors.
[[nodiscard]] std::vector<TextPiece> text_pieces(const pugi::xml_node& text, const ComputedStyle& style,
                                                 const ChildStyle& child_style, const TextContext& context,
                                                 FontCache& fonts, Diagnostics& diagnostics);

}  // namespace curvescan::svg::detail
