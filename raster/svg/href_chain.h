// Paint-server inheritance through href (SVG 1.1 13.2.2/13.2.3 for gradients, 13.3 for patterns): an
// element takes each attribute it does not specify, and its content when it has none, from the element
// its href names, and so on down the chain. Gradients and patterns walk the chain the same way.
#pragma once

#include <initializer_list>
#include <pugixml.hpp>
#include <string_view>
#include <vector>

#include "computed_style.h"
#include "paint_server.h"

namespace curvescan::svg::detail {

/// `element` and the elements it inherits from, nearest first: the chain follows href (or xlink:href)
/// while it names an element whose local name is one of `kinds`, for at most `max_length` elements. A
/// reference to nothing and a loop end the chain with a warning naming `what` ("gradient", "pattern").
[[nodiscard]] std::vector<pugi::xml_node> href_chain(const pugi::xml_node& element, const IdIndex& ids,
                                                     std::initializer_list<std::string_view> kinds,
                                                     int max_length, std::string_view what,
                                                     Diagnostics& diagnostics);

/// The attribute `name` of the nearest element of `chain` that has it, or a null attribute.
[[nodiscard]] pugi::xml_attribute chain_attribute(const std::vector<pugi::xml_node>& chain, const char* name);

}  // namespace curvescan::svg::detail
