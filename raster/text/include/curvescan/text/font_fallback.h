// Per-character font fallback: for a character the chosen face has no glyph for, the installed face that
// has one, as browsers do (CSS Fonts 3 section 5.2, step 5: "if no matching face exists or the matched
// face does not contain a glyph for the character to be rendered, [...] the user agent may search for
// other fonts installed on the system").
//
// The candidates are fontconfig's own ordering for the query (FcFontSort: the query's families first,
// then the faces its alias rules rank next, trimmed to those that add coverage; fontconfig-devel,
// "FcFontSort"), each face's coverage its FcCharSet (the characters its cmap maps). A candidate is opened
// only when first needed and then kept, and every answer is cached per character, so a document or a
// command-line run asks fontconfig once and opens each face once.
#pragma once

#include <cstddef>
#include <memory>

#include "curvescan/text/font.h"
#include "curvescan/text/font_lookup.h"

namespace curvescan {

class FontFallback {
 public:
  /// Fallback for `primary`, which must outlive this object, with the candidates fontconfig sorts for
  /// `query` (its family list, weight and slant). Nothing is looked up until a character is missing.
  FontFallback(const Font& primary, FontQuery query);
  FontFallback(FontFallback&&) noexcept;
  FontFallback& operator=(FontFallback&&) noexcept;
  ~FontFallback();

  [[nodiscard]] const Font& primary() const noexcept;

  /// The face to draw `character` with: the primary face when it has a glyph for it, else the first
  /// candidate (fontconfig's order) that has one, else nullptr — no installed face has it, or fontconfig
  /// cannot be used. A candidate that cannot be opened is skipped. Returned faces live as long as this.
  [[nodiscard]] const Font* face_for(char32_t character);

  /// How many faces besides the primary have been opened so far.
  [[nodiscard]] std::size_t opened_face_count() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvescan
