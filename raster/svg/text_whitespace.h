// White space in SVG text, applied to the character data of one <text> element, which may be split over
// several fragments (text nodes of nested <tspan>s, each with its own white space processing, WhiteSpace in
// text_properties.h):
//  - SVG 1.1's xml:space (10.15), while no white-space is declared: "default" removes newline characters
//    (not turned into spaces: SVG 1.1, unlike CSS), tabs become spaces, leading and trailing spaces go,
//    runs of spaces become one; "preserve" turns newlines and tabs into spaces and keeps every space
//    (SVG 2's user agent sheet: white-space-collapse: preserve-spaces);
//  - CSS white-space (CSS Text 3 section 4.1, phases I and II, as SVG 2 11.7 refers to it):
//    normal and nowrap collapse — spaces and tabs next to a segment break are removed, a segment break
//    after another is removed and the rest become a space, or nothing between two East Asian wide
//    characters (neither Hangul) or next to a zero width space ("segment break transformation rules");
//    tabs become spaces; a collapsible space after another is removed; collapsible spaces at the start
//    and end of a line are removed. pre-line collapses spaces the same way but keeps segment breaks,
//    and pre, pre-wrap and break-spaces keep spaces, tabs and segment breaks. A kept segment break
//    stays in the text as U+000A: a forced line break (SVG 2 11.4 "Multi-line text via white-space"),
//    which the layout turns into a new line (text_element.cpp).
// Collapsing is judged across fragment boundaries, over the whole <text> element ("a <tspan> b</tspan>"
// keeps one space), as browsers and rsvg-convert do; the whole element is one line but for its forced
// line breaks (SVG 2 11.8.3: one line unless white-space breaks it).
#pragma once

#include <string>
#include <vector>

#include "text_properties.h"

namespace curvescan::svg::detail {

struct TextFragment {
  std::u32string text;
  WhiteSpace white_space = WhiteSpace::kXmlDefault;
  TextTransform transform;  ///< text-transform, applied after white space (text_transform.h)
  /// After text-transform: middle[i] says that character i is the second or later one produced from one
  /// source character (ß uppercased to SS), so that it takes no x, y, dx, dy or rotate value of its own
  /// (SVG 2 11.8.3: addressable characters are counted before text-transform). Empty: none is.
  std::vector<bool> middle;
};

/// The forced line break a kept segment break leaves in the text.
inline constexpr char32_t kForcedLineBreak = U'\n';

/// Rewrites the text of every fragment in place by the rules above. Fragments may become empty.
void apply_white_space(std::vector<TextFragment>& fragments);

}  // namespace curvescan::svg::detail
