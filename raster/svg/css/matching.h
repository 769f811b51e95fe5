// Matching selectors against the XML tree (Selectors Level 3 sections 6-8).
//
// Elements are pugixml nodes; a type selector compares the element's local name (xml_names.h), case-
// sensitively as XML requires, in any namespace (CSS Namespaces 3, section 2: without a default
// namespace declared, an unprefixed type selector matches elements of every namespace). Attribute names
// and values compare case-sensitively too, except values under the "i" flag.
//
// A complex selector is matched right to left. Descendant and sibling combinators backtrack; the
// backtracking is cut with the four-outcome scheme described by Servo's selector matcher (a failure
// that no other ancestor or sibling can fix ends the search at once), which keeps matching linear in
// the number of ancestors and siblings visited for each compound.
#pragma once

#include <pugixml.hpp>

#include "selector.h"

namespace curvescan::svg::css {

/// Whether `element` matches every simple selector of `compound`.
[[nodiscard]] bool matches_compound(const CompoundSelector& compound, const pugi::xml_node& element);

/// Whether `element` is the subject of `selector`.
[[nodiscard]] bool matches(const ComplexSelector& selector, const pugi::xml_node& element);

}  // namespace curvescan::svg::css
