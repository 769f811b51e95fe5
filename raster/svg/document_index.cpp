// The per-element decisions of one render (document_index.h).
#include "document_index.h"

#include <algorithm>
#include <functional>
#include <string_view>

#include "cascade.h"
#include "curve_elements.h"
#include "element_support.h"
#include "switch.h"
#include "xml_names.h"

namespace curvescan::svg::detail {
namespace {

// `ns`: the namespace of the element's name.
ElementRole role_of(const pugi::xml_node& element, std::string_view ns) {
  if (ns == kCurvescanNamespace) return ElementRole::kCurve;
  if (ns != kSvgNamespace && !ns.empty()) return ElementRole::kForeign;
  switch (element_support(local_name(element))) {
    case ElementSupport::kRendered:
      return ElementRole::kRendered;
    case ElementSupport::kNonRendering:
      return ElementRole::kNonRendering;
    case ElementSupport::kUnsupported:
      return ElementRole::kUnsupported;
    case ElementSupport::kUnknown:
      break;
  }
  return ElementRole::kUnknown;
}

std::string id_suffix(const pugi::xml_node& node) {
  const pugi::xml_attribute id = node.attribute("id");
  return id ? " id=\"" + std::string(id.value()) + "\"" : std::string();
}

// `top` and its element descendants, in document order.
std::vector<pugi::xml_node> subtree(const pugi::xml_node& top) {
  std::vector<pugi::xml_node> nodes{top};
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    for (pugi::xml_node child = nodes[i].first_child(); child; child = child.next_sibling()) {
      if (child.type() == pugi::node_element) nodes.push_back(child);
    }
  }
  return nodes;
}

// The entry of `element` in `facts` (sorted by node object), or facts.end().
template <typename Facts>
auto lookup(Facts& facts, const pugi::xml_node& element) {
  const void* const key = element.internal_object();
  const auto found = std::lower_bound(facts.begin(), facts.end(), key, [](const auto& entry, const void* k) {
    return std::less<const void*>()(entry.first, k);
  });
  return found != facts.end() && found->first == key ? found : facts.end();
}

}  // namespace

Result<DocumentIndex> DocumentIndex::build(const pugi::xml_node& root,
                                           const std::vector<std::string>& languages,
                                           std::size_t max_elements, const css::StyleSheets* style_sheets,
                                           Diagnostics& diagnostics) {
  DocumentIndex index;
  std::vector<pugi::xml_node> masks;
  std::vector<pugi::xml_node> resources;  // masks, patterns and markers (use_expansion.cpp)
  bool has_use = false;
  // Each element to visit, with the default namespace in scope at its parent (xml_names.h), so that a
  // name's namespace is found without walking up the ancestors for every element.
  struct Pending {
    pugi::xml_node node;
    std::string_view parent_default;
  };
  std::vector<Pending> stack{{root, default_namespace_of(root.parent())}};
  while (!stack.empty()) {
    const auto [node, parent_default] = stack.back();
    stack.pop_back();
    const std::string_view default_here = default_namespace_at(node, parent_default);
    if (index.facts_.size() >= max_elements) {
      return Error{ErrorKind::kLimitExceeded, "the document has more than " + std::to_string(max_elements) +
                                                  " elements (raise --max-elements)"};
    }
    ElementFacts facts;
    facts.role = role_of(node, namespace_with_default(node, default_here));
    facts.conditions_hold = conditions_hold(node, languages);
    index.facts_.emplace_back(node.internal_object(), facts);
    // emplace keeps the first element of an id, as browsers do; children are pushed last to first so
    // that they are visited in document order.
    if (const pugi::xml_attribute id = node.attribute("id")) index.ids_.emplace(id.value(), node);
    // Unsupported SVG elements are named wherever they are, <defs> and <text> included (no silent loss),
    // unless their own conditions fail: such an element is not drawn by any renderer, so nothing is lost
    // (Illustrator puts a <foreignObject requiredExtensions="…"> before the drawing in a <switch>).
    if (facts.role == ElementRole::kUnsupported && facts.conditions_hold)
      diagnostics.unsupported("<" + std::string(local_name(node)) + ">");
    const std::string_view name = local_name(node);
    if (name == "mask") masks.push_back(node);
    if (name == "use") has_use = true;
    if ((name == "mask" || name == "pattern" || name == "marker") && facts.role == ElementRole::kNonRendering)
      resources.push_back(node);
    for (pugi::xml_node child = node.last_child(); child; child = child.previous_sibling()) {
      if (child.type() == pugi::node_element) stack.push_back({child, default_here});
    }
  }
  std::sort(index.facts_.begin(), index.facts_.end(),
            [](const auto& a, const auto& b) { return std::less<const void*>()(a.first, b.first); });
  index.break_mask_loops(masks, style_sheets, diagnostics);
  // Without a <use> the walk meets each element at most once (the repeats of masks, patterns and markers
  // are counted while drawing), so the element count less the root bounds it and the limit above holds:
  // the count, a cascaded `display` per group, is taken only where a <use> can multiply the content.
  index.expanded_elements_ = has_use ? index.count_expanded_elements(root, resources, style_sheets)
                                     : index.facts_.size() - 1;
  if (index.expanded_elements_ > max_elements) {
    // The message the drawing walk gives when it reaches the limit (document.cpp), given before it starts.
    return Error{ErrorKind::kLimitExceeded,
                 "rendering needs more than " + std::to_string(max_elements) +
                     " elements, <use> expansions included (raise --max-elements)"};
  }
  return index;
}

std::size_t DocumentIndex::position(const pugi::xml_node& element) const {
  return static_cast<std::size_t>(lookup(facts_, element) - facts_.begin());
}

ElementFacts* DocumentIndex::find(const pugi::xml_node& element) {
  const auto found = lookup(facts_, element);
  return found != facts_.end() ? &found->second : nullptr;
}

const ElementFacts& DocumentIndex::facts(const pugi::xml_node& element) const {
  static const ElementFacts kOutside{};
  const auto found = lookup(facts_, element);
  return found != facts_.end() ? found->second : kOutside;
}

// Mask references that would make a loop are dropped before rendering, the way resvg does it (so that
// documents render as its reference images show): for each <mask> M in document order, a mask reference
// to M from M or its content, or from the content of a mask that M's content refers to, counts as none.
// The rendering also stops at a mask already being applied (the renderer's mask stack), which catches
// longer loops.
void DocumentIndex::break_mask_loops(const std::vector<pugi::xml_node>& masks,
                                     const css::StyleSheets* style_sheets, Diagnostics& diagnostics) {
  const auto linked = [&](const pugi::xml_node& node) -> pugi::xml_node {
    if (const ElementFacts* facts = find(node); facts != nullptr && facts->mask_loop_dropped) return {};
    // The mask property as the cascade gives it (style sheets, the style attribute, then the attribute).
    const std::optional<std::string> value = cascaded_value(node, "mask", style_sheets);
    const std::string id = value ? parse_url_reference(*value).value_or("") : std::string();
    const auto found = id.empty() ? ids_.end() : ids_.find(id);
    return found == ids_.end() ? pugi::xml_node() : found->second;
  };
  for (const pugi::xml_node& mask : masks) {
    for (const pugi::xml_node& node : subtree(mask)) {
      const pugi::xml_node link = linked(node);
      if (!link) continue;
      const auto drop = [&](const pugi::xml_node& referrer) {
        if (ElementFacts* facts = find(referrer)) facts->mask_loop_dropped = true;
        diagnostics.warnings.push_back("a mask reference closes a loop back to mask" + id_suffix(mask) +
                                       "; that reference is ignored");
      };
      if (link == mask) {
        drop(node);
        continue;
      }
      for (const pugi::xml_node& inner : subtree(link)) {
        if (linked(inner) == mask) drop(inner);
      }
    }
  }
}

}  // namespace curvescan::svg::detail
