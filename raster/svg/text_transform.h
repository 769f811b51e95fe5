// text-transform (CSS Text 3 section 2.1) of SVG text, applied to the character data of one <text>
// element after white space processing (CSS Text 3 section 1.3: transformation follows phase I of white
// space processing), each fragment by its own element's value:
//  - uppercase, lowercase: the full case mappings of the Unicode Character Database (SpecialCasing.txt
//    too: "ß" uppercases to "SS", "İ" lowercases to "i̇"), through GLib's g_utf8_strup and g_utf8_strdown,
//    and a final sigma lowercased to "ς" (Unicode's Final_Sigma condition, judged across fragments);
//  - capitalize: the first letter of each word to its titlecase (g_unichar_totitle; where the titlecase
//    is a single character the full uppercase mapping would not give, as "ß", the first character of the
//    full uppercase followed by the rest lowercased: "Ss", as SpecialCasing.txt titlecases it). A word is
//    a run of letters, marks and digits, with an apostrophe, period, colon or middle dot between two
//    letters inside it (UAX #29's MidLetter and MidNumLet), judged across fragments;
//  - full-width: each character with a full-width form (its <wide> counterpart in UnicodeData.txt, read
//    through GLib's compatibility decompositions: ASCII and the space to U+FF01..U+FF5E and U+3000, ¢ £ ¬
//    ¯ ¦ ¥ ₩, the white parentheses) to it, and the halfwidth forms (U+FF61..U+FFEE, <narrow>) back to
//    their ordinary full-width characters;
//  - full-size-kana: the small kana of CSS Text 3 appendix G to their full-size forms.
// A case transform comes first, then full-width, then full-size-kana (CSS Text 3 2.1). A character that
// becomes several (ß to SS) keeps one addressable position: the ones after the first are marked middle
// (TextFragment::middle), as SVG 2 11.8.3 counts addressable characters before text-transform.
#pragma once

#include <string>
#include <vector>

#include "text_whitespace.h"

namespace curvescan::svg::detail {

/// Transforms the text of every fragment by its own text-transform, filling `middle` where a character
/// became several.
void apply_text_transform(std::vector<TextFragment>& fragments);

/// The characters `c` becomes under uppercase or lowercase (full case mapping, no context).
[[nodiscard]] std::u32string full_case(char32_t c, bool upper);

}  // namespace curvescan::svg::detail
