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

/// The default namespace (xmlns="…") in scope at `node`: the nearest declaration among it and its
/// ancestors (empty when there is none, or for a null node).
[[nodiscard]] std::string_view default_namespace_of(const pugi::xml_node& node);

/// For a walk down the tree: the default namespace (xmlns="…") in scope at `node`, its own declaration
/// or else `parent_default`, the one in scope at its parent (empty: none).
[[nodiscard]] std::string_view default_namespace_at(const pugi::xml_node& node,
                                                    std::string_view parent_default);

/// namespace_of(node) when `default_here` is the default namespace in scope at it (default_namespace_at):
/// an unprefixed name takes it without a walk up the ancestors; a prefixed one is looked up as in
/// namespace_of.
[[nodiscard]] std::string_view namespace_with_default(const pugi::xml_node& node,
                                                      std::string_view default_here);

}  // namespace curvescan::svg::detail
