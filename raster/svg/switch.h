// <switch> and the conditional processing attributes (SVG 1.1 section 5.8): a <switch> renders the first
// of its direct children whose conditions hold, and nothing else.
#pragma once

#include <pugixml.hpp>
#include <string>
#include <vector>

namespace curvescan::svg::detail {

/// Whether the conditional processing attributes of `element` hold (SVG 1.1 5.8.2-5.8.5):
///  - requiredFeatures: true whatever it lists. SVG 2 dropped the feature strings, and browsers answer
///    true; this reader would otherwise have to claim features one by one.
///  - requiredExtensions: false when present -- this reader supports no extension, and SVG 1.1 5.8.4
///    makes an empty value false too.
///  - systemLanguage: a comma-separated list of BCP 47 tags; true when one of them equals one of
///    `languages` (case-insensitively, as BCP 47 tags compare) or begins with one of them followed by
///    '-' (SVG 1.1 5.8.5: "en" accepts "en-GB"). An empty value is false.
[[nodiscard]] bool conditions_hold(const pugi::xml_node& element, const std::vector<std::string>& languages);

}  // namespace curvescan::svg::detail
