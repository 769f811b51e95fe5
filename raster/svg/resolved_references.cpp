// References resolved once per render (resolved_references.h).
#include "resolved_references.h"

namespace curvescan::svg::detail {

void ResolvedReferences::reset(const IdIndex* ids) {
  ids_ = ids;
  gradients_.clear();
  patterns_.clear();
  resolved_count_ = 0;
}

const ResolvedGradient& ResolvedReferences::gradient(const pugi::xml_node& element,
                                                     const ResolveContext& context,
                                                     Diagnostics& diagnostics) {
  const auto [at, added] = gradients_.try_emplace(key_of(element, context));
  if (added) {
    at->second = resolve_gradient(element, *ids_, context, diagnostics);
    ++resolved_count_;
  }
  return at->second;
}

const ResolvedPattern& ResolvedReferences::pattern(const pugi::xml_node& element,
                                                   const ResolveContext& context,
                                                   const ReferencedStyle& style_of,
                                                   Diagnostics& diagnostics) {
  const auto [at, added] = patterns_.try_emplace(key_of(element, context));
  if (added) {
    at->second = resolve_pattern(element, *ids_, context, diagnostics);
    if (at->second.content) at->second.content_style = style_of(at->second.content);
    ++resolved_count_;
  }
  return at->second;
}

}  // namespace curvescan::svg::detail
