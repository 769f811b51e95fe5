// Element names (xml_names.h).
#include "xml_names.h"

#include <string>

namespace curvescan::svg::detail {

std::string_view local_name(const pugi::xml_node& node) {
  const std::string_view name = node.name();
  const std::size_t colon = name.find(':');
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

std::string_view namespace_of(const pugi::xml_node& node) {
  const std::string_view name = node.name();
  const std::size_t colon = name.find(':');
  const std::string attribute =
      colon == std::string_view::npos ? std::string("xmlns") : "xmlns:" + std::string(name.substr(0, colon));
  for (pugi::xml_node scope = node; scope; scope = scope.parent()) {
    if (const pugi::xml_attribute declaration = scope.attribute(attribute.c_str()))
      return declaration.value();
  }
  return {};
}

std::string_view default_namespace_of(const pugi::xml_node& node) {
  for (pugi::xml_node scope = node; scope; scope = scope.parent()) {
    if (const pugi::xml_attribute declaration = scope.attribute("xmlns")) return declaration.value();
  }
  return {};
}

std::string_view default_namespace_at(const pugi::xml_node& node, std::string_view parent_default) {
  const pugi::xml_attribute declaration = node.attribute("xmlns");
  return declaration ? std::string_view(declaration.value()) : parent_default;
}

std::string_view namespace_with_default(const pugi::xml_node& node, std::string_view default_here) {
  return std::string_view(node.name()).find(':') == std::string_view::npos ? default_here
                                                                           : namespace_of(node);
}

}  // namespace curvescan::svg::detail
