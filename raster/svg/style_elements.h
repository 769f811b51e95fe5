// The document's <style> elements (SVG 2 section 6.4 "Style sheets in SVG content", 6.5 "The 'style'
// element").
#pragma once

#include <pugixml.hpp>
#include <string>
#include <vector>

#include "css/style_sheet.h"

namespace curvescan::svg::detail {

/// Adds the text of every SVG <style> element under `root`, wherever it is (inside <defs>, after the
/// content it styles, ...), in document order, to `sheets`. A type other than text/css (ASCII case-
/// insensitive, parameters ignored; absent or empty means text/css) skips the element with a warning.
/// The text is the concatenation of its text and CDATA children. A `media` attribute is a media query
/// list the sheet applies under (css/media_query.h).
void add_style_elements(const pugi::xml_node& root, css::StyleSheets& sheets,
                        std::vector<std::string>& warnings);

}  // namespace curvescan::svg::detail
