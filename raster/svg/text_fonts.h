// The fonts of one rendered document: each (font-family, font-weight, font-style, font-stretch) is looked up through
// fontconfig once (font_lookup.h; CSS Fonts 3 section 5: the first installed family of the list wins,
// generic families always match) and each face file is opened once (fallback faces too, font_fallback.h), however many <text> elements use it.
// A family list none of whose names is installed falls back to fontconfig's choice with a warning: a
// missing font never fails the render.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <tuple>

#include "computed_style.h"
#include "curvescan/text/font.h"
#include "curvescan/text/font_fallback.h"

namespace curvescan::svg::detail {

class FontCache {
 public:
  /// The face for `style`'s font-family, font-weight, font-style and font-stretch, or nullptr when no font can be
  /// loaded at all (fontconfig knows no font, or the file is unreadable); problems are warned once.
  [[nodiscard]] const Font* font_for(const ComputedStyle& style, Diagnostics& diagnostics);
  /// font_for's face with per-character fallback (font_fallback.h) for the same family list, weight and
  /// slant, one per query for the whole document; nullptr when font_for gives none.
  [[nodiscard]] FontFallback* fallback_for(const ComputedStyle& style, Diagnostics& diagnostics);

 private:
  using QueryKey = std::tuple<std::string, int, bool, double>;
  static QueryKey key_of(const ComputedStyle& style);
  std::map<QueryKey, const Font*> queries_;
  std::map<QueryKey, std::unique_ptr<FontFallback>> fallbacks_;
  std::map<std::pair<std::string, int>, std::unique_ptr<Font>> faces_;  // by file and face index
};

}  // namespace curvescan::svg::detail
