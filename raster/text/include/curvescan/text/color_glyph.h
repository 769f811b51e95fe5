// Colour glyphs: the OpenType formats that give a glyph colours of its own (emoji, colour icons,
// multi-coloured lettering), and the one curvescan draws in colour.
//
// OpenType "COLR" version 0 with "CPAL" (OpenType spec, COLR and CPAL tables): a base glyph is drawn as a
// list of layers, each another glyph of the same face filled with one colour of a palette, composited
// source-over in the order listed; palette index 0xFFFF is the foreground colour, which for text is its
// own fill (CSS Fonts 4 section 9.2, font-palette: the colour of the text). curvescan draws these layers
// with palette 0 (CPAL: the default palette).
//
// Bitmap colour glyphs ("CBDT"/"CBLC" and "sbix" strikes of PNG images, e.g. Noto Color Emoji): the
// image of the strike nearest the size drawn (color_glyph_bitmap), scaled to the font size. Such a glyph
// may have no outline at all (a CBDT-only font).
//
// SVG-in-OpenType (the "SVG " table: an SVG document per glyph) is drawn by the SVG renderer
// (color_glyph_svg_document gives the document), in SVG text and in the text command alike.
//
// Not drawn in colour (drawn as the glyph's plain outline, and a caller warns once per face): COLR
// version 1 (a graph of gradients, transforms and compositing modes per glyph: FreeType 2.12 as Debian 12
// builds it has no COLR version 1 reader, FT_Get_Color_Glyph_Paint always answers "no paint").
//
// Where a glyph has several representations, COLR version 1 wins over version 0 (the COLR specification
// has applications that support version 1 use its record when a glyph has both), and COLR version 0 over
// a bitmap and an SVG document; a COLR version 1 glyph, which is not drawn in colour, gives way to a
// bitmap or an SVG document of the same glyph, so that the colours curvescan can draw are drawn.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/path.h"
#include "curvescan/status.h"
#include "curvescan/text/font.h"

namespace curvescan {

/// How a glyph is meant to be drawn.
enum class ColorGlyphKind {
  kOutline,     ///< its outline in the text's colour (no colour data for it)
  kLayers,      ///< COLR version 0 layers: color_glyph_layers gives them
  kPaintGraph,  ///< COLR version 1: drawn as its plain outline
  kSvg,         ///< an SVG document in the "SVG " table: color_glyph_svg_document gives it
  kBitmap,      ///< a colour bitmap ("CBDT", "sbix"): color_glyph_bitmap gives it
};

/// One layer of a COLR version 0 glyph: a glyph of the same face and its colour.
struct ColorGlyphLayer {
  GlyphId glyph = kNotdefGlyph;
  /// Palette index 0xFFFF: the text's own fill, `color` unused. (A layer with an index past the
  /// palette's end, invalid in COLR, ends the list: FreeType stops there, and so do the layers given.)
  bool foreground = false;
  Color color;  ///< the palette colour, straight (not premultiplied) alpha
};

/// The representation `glyph` of `font` has (see the header comment for the precedence); kOutline for a
/// glyph index outside the face.
[[nodiscard]] ColorGlyphKind color_glyph_kind(const Font& font, GlyphId glyph) noexcept;

/// The layers of a COLR version 0 glyph, bottom first; empty when color_glyph_kind is not kLayers.
[[nodiscard]] std::vector<ColorGlyphLayer> color_glyph_layers(const Font& font, GlyphId glyph);

/// A COLR version 0 layer as the outline to fill (non-zero rule) and how to paint it.
struct ColorLayerOutline {
  Path path;                ///< the layer glyph's outline, placed by the caller's transform
  bool foreground = false;  ///< as ColorGlyphLayer::foreground
  Color color;              ///< as ColorGlyphLayer::color
};

/// The layers of a COLR version 0 glyph (color_glyph_layers) as outlines mapped by `place` (font units to
/// the caller's space), bottom first; a layer whose outline is empty is left out. Font::append_glyph's
/// and Path's errors.
[[nodiscard]] Result<std::vector<ColorLayerOutline>> color_glyph_layer_outlines(const Font& font,
                                                                                GlyphId glyph,
                                                                                const Affine& place);

/// Whether the face has a colour bitmap for `glyph` (in its first strike; strikes of one face cover the
/// same glyphs in practice). False for a face without colour strikes.
[[nodiscard]] bool has_color_bitmap(const Font& font, GlyphId glyph) noexcept;

/// A bitmap colour glyph's image and where it lies.
struct ColorGlyphBitmap {
  Image image;                        ///< premultiplied RGBA8, as FreeType decoded it
  Affine image_to_font;               ///< image pixel space (y down) -> font units (y up), glyph origin at 0
  double strike_pixels_per_em = 0.0;  ///< the strike it comes from
};

/// The colour bitmap of `glyph` from the strike of `font` best for drawing at `pixels_per_em` device
/// pixels per em (the smallest strike at least that large, else the largest), or nullopt when the glyph
/// has none. kLimitExceeded when the image has more than `max_pixels` pixels (or is beyond limits.h),
/// kCorruptInput when FreeType's bitmap is malformed.
[[nodiscard]] Result<std::optional<ColorGlyphBitmap>> color_glyph_bitmap(const Font& font, GlyphId glyph,
                                                                         double pixels_per_em,
                                                                         std::int64_t max_pixels);

/// The rectangle `bitmap` covers once its image space is placed by `image_to_user` (the bitmap's
/// image_to_font after the glyph's placement): the path a bitmap glyph fills with its image, and clips by.
[[nodiscard]] Result<Path> color_glyph_bitmap_rectangle(const ColorGlyphBitmap& bitmap,
                                                        const Affine& image_to_user);

/// The SVG document the "SVG " table gives `glyph` (OpenType spec, "SVG — The SVG (Scalable Vector
/// Graphics) table": the glyph is its element with id "glyphN", N the glyph index, in font units with y
/// down, its origin the glyph origin), as stored: possibly gzip-compressed. Empty when there is none.
/// The bytes are the font's own (HarfBuzz keeps the table for the life of the face): valid as long as
/// `font`, and the same bytes, at the same address, for every glyph the document holds — what a cache of
/// parsed documents is keyed by, so a document of 100 glyphs is read once.
[[nodiscard]] std::string_view color_glyph_svg_document(const Font& font, GlyphId glyph);

/// The area an SVG colour glyph is drawn over, placed by `place` (font units to the caller's space): the
/// glyph's outline, or, when the outline is empty, its cell (the advance from the descender to the
/// ascender). `is_outline` says which.
struct SvgGlyphArea {
  Path path;
  bool is_outline = false;
};
[[nodiscard]] Result<SvgGlyphArea> svg_glyph_area(const Font& font, GlyphId glyph, const Affine& place);

/// The warning for a face whose glyphs of `kind` (kPaintGraph or kSvg) are drawn as plain outlines,
/// naming the face: "COLR v1 colour glyphs in font 'Name' are drawn as plain outlines". Empty for the
/// kinds that are drawn as they should be.
[[nodiscard]] std::string outline_only_warning(const Font& font, ColorGlyphKind kind);

}  // namespace curvescan
