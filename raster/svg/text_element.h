// SVG <text> (SVG 1.1 chapter 10, simplified as docs/svg.md states): the character data of a <text>
// element and its <tspan>s (and <a>s) becomes glyph outlines, one Path per run of characters that share
// a style, to be filled and stroked like any shape by the document renderer.
//
// Steps (SVG 1.1 10.4-10.5, 10.9, 10.15):
//  1. collect the character data in document order, each fragment with the computed style of the element
//     holding it (display:none elements contribute nothing);
//  2. white space per xml:space (text_whitespace.h);
//  3. per-character positions from x, y, dx, dy: each attribute is a list of lengths, the i-th value
//     applying to the i-th character (code point) of the element's content, descendants' values winning
//     over their ancestors' (SVG 1.1 10.5); an absolute x or y starts a new text chunk;
//  4. runs: a new run starts at every chunk, at every dx/dy and wherever the style changes; each run is
//     shaped by HarfBuzz with its font (text_layout.h) and the pen advances by its advance;
//  5. text-anchor (SVG 1.1 10.9.1) shifts every run of a chunk so that the chunk's extent starts, is
//     centred or ends at the chunk's initial x; the anchor is the one of the chunk's first character.
// Not supported (a note under --verbose): textPath, tref, rotate, textLength, letter- and word-spacing,
// baseline properties, writing modes, text decoration. A character the run's face lacks is drawn from
// the installed face fontconfig's fallback finds (font_fallback.h); .notdef only when none has it.
// The same pieces are a <clipPath> child's geometry (document.cpp).
#pragma once

#include <functional>
#include <pugixml.hpp>
#include <vector>

#include "computed_style.h"
#include "curvescan/raster/path.h"
#include "text_fonts.h"

namespace curvescan::svg::detail {

/// Glyph outlines in the user space of the <text> element, and the style to paint them with (fill-rule
/// is nonzero: glyph outlines are defined for it, font.h).
struct TextPiece {
  Path path;
  ComputedStyle style;
};

/// The computed style of a child element (the document renderer's cascade).
using ChildStyle = std::function<ComputedStyle(const pugi::xml_node& element, const ComputedStyle& parent)>;

struct TextContext {
  double viewport_width = 100.0;  ///< what 100% of an x or dx means
  double viewport_height = 100.0;
  double dpi = 96.0;
  int max_depth = 256;  ///< deepest <tspan> nesting walked (deeper content is skipped with a warning)
};

/// The pieces of `text` (a <text> element with computed style `style`), in painting order. Problems are
/// warnings (a missing font falls back; no font at all draws nothing), never errors.
[[nodiscard]] std::vector<TextPiece> text_pieces(const pugi::xml_node& text, const ComputedStyle& style,
                                                 const ChildStyle& child_style, const TextContext& context,
                                                 FontCache& fonts, Diagnostics& diagnostics);

}  // namespace curvescan::svg::detail
