// The fonts of one rendered document: each (font-family, font-weight, font-style, font-stretch) is looked up through
// fontconfig once (font_lookup.h; CSS Fonts 3 section 5: the first installed family of the list wins,
// generic families always match) and each face file is opened once (fallback faces too, font_fallback.h), however many <text> elements use it.
// A family list none of whose names is installed falls back to the initial family, serif, as browsers
// do (CSS Fonts 4 5.1: the user agent's default face), with a warning: a missing font never fails the render.
//
// A variable font (OpenType "fvar") is opened once more for each point of its design space the document
// asks for (CSS Fonts 4 7.2, "Feature and variation precedence"): first the axes font-weight (wght),
// font-stretch (wdth) and font-style (ital 1 for italic, slnt minus the oblique angle) imply, then
// opsz = the font size in px under font-optical-sizing: auto (CSS Fonts 4 7.12), then
// font-variation-settings, which wins. Only the axes the face has count, so a size never makes a new
// instance of a face without an opsz axis.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "computed_style.h"
#include "curvescan/text/color_glyph.h"
#include "curvescan/text/font.h"
#include "curvescan/text/font_fallback.h"

namespace curvescan::svg::detail {

/// The variation coordinates `style` asks of the variable face `face` (the order of the header comment;
/// later entries win), restricted to the axes the face has; empty for a face without axes.
[[nodiscard]] std::vector<FontVariation> variations_for(const ComputedStyle& style, const Font& face);

class FontCache {
 public:
  /// The face for `style`'s font-family, font-weight, font-style and font-stretch (at the coordinates
  /// variations_for gives when it is a variable font), or nullptr when no font can be loaded at all
  /// (fontconfig knows no font, or the file is unreadable); problems are warned once.
  [[nodiscard]] const Font* font_for(const ComputedStyle& style, Diagnostics& diagnostics);
  /// font_for's face with per-character fallback (font_fallback.h) for the same family list, weight and
  /// slant, one per query for the whole document; nullptr when font_for gives none.
  [[nodiscard]] FontFallback* fallback_for(const ComputedStyle& style, Diagnostics& diagnostics);
  /// Warns, once per document, face and kind, that `face`'s colour glyphs of `kind` (COLR version 1, SVG;
  /// color_glyph.h) are drawn as plain outlines.
  void warn_outline_only(const Font& face, ColorGlyphKind kind, Diagnostics& diagnostics);

 private:
  using QueryKey = std::tuple<std::string, int, bool, double>;
  using FaceKey = std::pair<std::string, int>;  // file and face index
  static QueryKey key_of(const ComputedStyle& style);
  const Font* base_font_for(const ComputedStyle& style, Diagnostics& diagnostics);
  std::map<QueryKey, const Font*> queries_;
  std::map<std::pair<QueryKey, const Font*>, std::unique_ptr<FontFallback>> fallbacks_;
  std::map<FaceKey, std::unique_ptr<Font>> faces_;
  std::map<const Font*, FaceKey> face_keys_;  // the file of each face in faces_
  std::map<const Font*, bool> variable_;      // whether a face in faces_ has variation axes
  std::map<std::pair<FaceKey, std::vector<FontVariation>>, std::unique_ptr<Font>> instances_;
  std::set<std::pair<std::string, ColorGlyphKind>> outline_only_warned_;  // font name, kind
};

}  // namespace curvescan::svg::detail
