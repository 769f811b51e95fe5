// References resolved once per render (resolved_references.h).
#include "resolved_references.h"

#include "xml_names.h"

namespace curvescan::svg::detail {

void ResolvedReferences::reset(const IdIndex* ids) {
  ids_ = ids;
  gradients_.clear();
  patterns_.clear();
  clip_paths_.clear();
  markers_.clear();
  masks_.clear();
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

const ResolvedClipPath* ResolvedReferences::clip_path(const std::string& id, const ResolveContext& context,
                                                      const ClipPathReader& reader) {
  const auto found = ids_->find(id);
  if (found == ids_->end() || local_name(found->second) != "clipPath") return nullptr;
  const auto [at, added] = clip_paths_.try_emplace(key_of(found->second, context));
  if (added) {
    at->second = resolve_clip_path(found->second, *ids_, reader);
    ++resolved_count_;
  }
  return &at->second;
}

const ResolvedMarker* ResolvedReferences::marker(const std::string& id, const ResolveContext& context,
                                                 const ReferencedStyle& style_of, Diagnostics& diagnostics) {
  const auto found = ids_->find(id);
  if (found == ids_->end() || local_name(found->second) != "marker") return nullptr;
  const auto [at, added] = markers_.try_emplace(key_of(found->second, context));
  if (added) {
    at->second = resolve_marker(found->second, style_of(found->second), context, diagnostics);
    ++resolved_count_;
  }
  return &at->second;
}

const ResolvedMask* ResolvedReferences::mask(const std::string& id, const ResolveContext& context,
                                             const ReferencedStyle& style_of, Diagnostics& diagnostics) {
  const auto found = ids_->find(id);
  if (found == ids_->end() || local_name(found->second) != "mask") return nullptr;
  const auto [at, added] = masks_.try_emplace(key_of(found->second, context));
  if (added) {
    at->second = resolve_mask(found->second, style_of(found->second), context, diagnostics);
    ++resolved_count_;
  }
  return &at->second;
}

}  // namespace curvescan::svg::detail
