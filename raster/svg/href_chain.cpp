// Paint-server inheritance through href (href_chain.h).
#include "href_chain.h"

#include <algorithm>
#include <string>

#include "xml_names.h"

namespace curvescan::svg::detail {

std::vector<pugi::xml_node> href_chain(const pugi::xml_node& element, const IdIndex& ids,
                                       std::initializer_list<std::string_view> kinds, int max_length,
                                       std::string_view what, Diagnostics& diagnostics) {
  std::vector<pugi::xml_node> chain{element};
  while (static_cast<int>(chain.size()) < max_length) {
    pugi::xml_attribute attribute = chain.back().attribute("href");
    if (!attribute) attribute = chain.back().attribute("xlink:href");
    const std::string_view href = attribute.value();
    if (href.size() < 2 || href.front() != '#') break;
    const auto found = ids.find(std::string(href.substr(1)));
    if (found == ids.end()) {
      diagnostics.warnings.push_back(std::string(what) + " href '" + std::string(href) + "' does not exist");
      break;
    }
    if (std::find(kinds.begin(), kinds.end(), local_name(found->second)) == kinds.end()) break;
    if (std::find(chain.begin(), chain.end(), found->second) != chain.end()) {
      diagnostics.warnings.push_back(std::string(what) + " href '" + std::string(href) + "' is circular");
      break;
    }
    chain.push_back(found->second);
  }
  return chain;
}

pugi::xml_attribute chain_attribute(const std::vector<pugi::xml_node>& chain, const char* name) {
  for (const pugi::xml_node& node : chain) {
    if (const pugi::xml_attribute attribute = node.attribute(name)) return attribute;
  }
  return {};
}

}  // namespace curvescan::svg::detail
