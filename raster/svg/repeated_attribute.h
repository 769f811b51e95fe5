// XML 1.0, 3.1, well-formedness constraint "Unique Att Spec": no attribute name may appear more than once
// in the same start-tag. pugixml does not check it, so a document such as <rect width="1" width="9"/>
// would parse, and which value counted would be an accident of the parser; browsers, librsvg and resvg
// refuse such a document, and so does curvescan.
#pragma once

#include <pugixml.hpp>

namespace curvescan::svg::detail {

/// The first element under `root` (itself included, in document order) with an attribute name that
/// appears twice in it, and that name; an empty node when there is none. Linear in the document's size,
/// also for an element with very many attributes.
struct RepeatedAttribute {
  pugi::xml_node element;
  pugi::xml_attribute attribute;
};
[[nodiscard]] RepeatedAttribute find_repeated_attribute(const pugi::xml_node& root);

}  // namespace curvescan::svg::detail
