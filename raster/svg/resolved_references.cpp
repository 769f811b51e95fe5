// References resolved once per render (resolved_references.h).
#include "resolved_references.h"

#include <utility>

#include "xml_names.h"

namespace curvescan::svg::detail {

template <class Resolved, class Resolve>
Resolved& ResolvedReferences::memoised(std::map<Key, Resolved>& memo, const pugi::xml_node& element,
                                       const ResolveContext& context, Resolve&& resolve) {
  const auto [at, added] = memo.try_emplace(key_of(element, context));
  if (added) {
    at->second = resolve(element);
    ++resolved_count_;
  }
  return at->second;
}

template <class Resolved, class Resolve>
const Resolved* ResolvedReferences::memoised_by_id(std::map<Key, Resolved>& memo, const std::string& id,
                                                   std::string_view kind, const ResolveContext& context,
                                                   Resolve&& resolve) {
  const auto found = ids_->find(id);
  if (found == ids_->end() || local_name(found->second) != kind) return nullptr;
  return &memoised(memo, found->second, context, std::forward<Resolve>(resolve));
}

void ResolvedReferences::reset(const IdIndex* ids) {
  ids_ = ids;
  gradients_.clear();
  patterns_.clear();
  clip_paths_.clear();
  markers_.clear();
  masks_.clear();
  filters_.clear();
  resolved_count_ = 0;
}

const ResolvedGradient& ResolvedReferences::gradient(const pugi::xml_node& element,
                                                     const ResolveContext& context,
                                                     Diagnostics& diagnostics) {
  return memoised(gradients_, element, context, [&](const pugi::xml_node& gradient) {
    return resolve_gradient(gradient, *ids_, context, diagnostics);
  });
}

const ResolvedPattern& ResolvedReferences::pattern(const pugi::xml_node& element,
                                                   const ResolveContext& context,
                                                   const ReferencedStyle& style_of,
                                                   Diagnostics& diagnostics) {
  return memoised(patterns_, element, context, [&](const pugi::xml_node& pattern) {
    ResolvedPattern resolved = resolve_pattern(pattern, *ids_, context, diagnostics);
    if (resolved.content) resolved.content_style = style_of(resolved.content);
    return resolved;
  });
}

const ResolvedClipPath* ResolvedReferences::clip_path(const std::string& id, const ResolveContext& context,
                                                      const ClipPathReader& reader) {
  return memoised_by_id(clip_paths_, id, "clipPath", context, [&](const pugi::xml_node& clip_path) {
    return resolve_clip_path(clip_path, *ids_, reader);
  });
}

const ResolvedMarker* ResolvedReferences::marker(const std::string& id, const ResolveContext& context,
                                                 const ReferencedStyle& style_of, Diagnostics& diagnostics) {
  return memoised_by_id(markers_, id, "marker", context, [&](const pugi::xml_node& marker) {
    return resolve_marker(marker, style_of(marker), context, diagnostics);
  });
}

const ResolvedMask* ResolvedReferences::mask(const std::string& id, const ResolveContext& context,
                                             const ReferencedStyle& style_of, Diagnostics& diagnostics) {
  return memoised_by_id(masks_, id, "mask", context, [&](const pugi::xml_node& mask) {
    return resolve_mask(mask, style_of(mask), context, diagnostics);
  });
}

const filter::ResolvedFilter* ResolvedReferences::filter(const std::string& id, const ResolveContext& context,
                                                         const css::StyleSheets* style_sheets,
                                                         const ReferencedStyle& style_of,
                                                         Diagnostics& diagnostics) {
  return memoised_by_id(filters_, id, "filter", context, [&](const pugi::xml_node& element) {
    return filter::resolve_filter(element, *ids_, context, style_sheets, style_of, diagnostics);
  });
}

}  // namespace curvescan::svg::detail
