// Element names in the XML tree (Namespaces in XML 1.0): the local part of a prefixed name and the
// namespace a prefix is bound to. The renderer and the CSS selector matcher read names the same way.
#pragma once

#include <pugixml.hpp>
#include <string_view>

namespace curvescan::svg::detail {

inline constexpr std::string_view kSvgNamespace = "http://www.w3.org/2000/svg";

/// "svg:rect" -> "rect"; "rect" -> "rect".
[[nodiscard]] std::string_view local_name(const pugi::xml_node& node);

/// The namespace URI of `node`'s name: the nearest xmlns[:prefix] declaration among it and its ancestors
/// (empty when there is none).
[[nodiscard]] std::string_view namespace_of(const pugi::xml_node& node);

}  // namespace curvescan::svg::detail
