// White space in SVG text (SVG 1.1 section 10.15 "White space handling"), applied to the character data
// of one <text> element, which may be split over several fragments (text nodes of nested <tspan>s, each
// with its own xml:space):
//  - xml:space="default": newline characters are removed (not turned into spaces: SVG 1.1, unlike CSS),
//    tabs become spaces, leading and trailing spaces go, and runs of spaces become one space;
//  - xml:space="preserve": newlines and tabs become spaces, and every space is kept.
// Leading, trailing and repeated spaces are judged across fragment boundaries, over the whole <text>
// element ("a <tspan> b</tspan>" keeps one space), as browsers and rsvg-convert do.
#pragma once

#include <string>
#include <vector>

namespace curvescan::svg::detail {

struct TextFragment {
  std::u32string text;
  bool preserve = false;  ///< xml:space="preserve" in effect for this fragment
};

/// Rewrites the text of every fragment in place by the rules above. Fragments may become empty.
void apply_xml_space(std::vector<TextFragment>& fragments);

}  // namespace curvescan::svg::detail
