// Repeated attributes in a start-tag (repeated_attribute.h).
#include "repeated_attribute.h"

#include <algorithm>
#include <cstring>
#include <string_view>
#include <vector>

namespace curvescan::svg::detail {
namespace {

// Up to this many attributes an element is checked pairwise (no allocation); beyond, by sorting its names,
// so that a hostile element with 10^5 attributes costs n log n, not n^2.
constexpr int kPairwiseLimit = 16;

pugi::xml_attribute repeated_in(const pugi::xml_node& element, std::vector<pugi::xml_attribute>& scratch) {
  int count = 0;
  for (pugi::xml_attribute a = element.first_attribute(); a && count <= kPairwiseLimit;
       a = a.next_attribute())
    ++count;
  if (count <= kPairwiseLimit) {
    for (pugi::xml_attribute a = element.first_attribute(); a; a = a.next_attribute()) {
      for (pugi::xml_attribute b = a.next_attribute(); b; b = b.next_attribute()) {
        if (std::strcmp(a.name(), b.name()) == 0) return b;
      }
    }
    return {};
  }
  scratch.clear();
  for (pugi::xml_attribute a = element.first_attribute(); a; a = a.next_attribute()) scratch.push_back(a);
  std::stable_sort(scratch.begin(), scratch.end(),
                   [](const pugi::xml_attribute& a, const pugi::xml_attribute& b) {
                     return std::string_view(a.name()) < std::string_view(b.name());
                   });
  const auto same = std::adjacent_find(scratch.begin(), scratch.end(),
                                       [](const pugi::xml_attribute& a, const pugi::xml_attribute& b) {
                                         return std::string_view(a.name()) == std::string_view(b.name());
                                       });
  return same == scratch.end() ? pugi::xml_attribute() : *(same + 1);
}

}  // namespace

RepeatedAttribute find_repeated_attribute(const pugi::xml_node& root) {
  std::vector<pugi::xml_attribute> scratch;
  // Depth-first in document order without recursion: a document may nest elements many thousands deep.
  for (pugi::xml_node node = root; node;) {
    if (node.type() == pugi::node_element) {
      if (const pugi::xml_attribute repeated = repeated_in(node, scratch)) return {node, repeated};
    }
    if (node.first_child()) {
      node = node.first_child();
      continue;
    }
    while (node && node != root && !node.next_sibling()) node = node.parent();
    if (!node || node == root) break;
    node = node.next_sibling();
  }
  return {};
}

}  // namespace curvescan::svg::detail
