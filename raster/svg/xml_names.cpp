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

}  // namespace curvescan::svg::detail
