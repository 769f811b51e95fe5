// The render tree's Group node (docs/svg.md, "How a document is drawn"): what applies to an element's
// content as one -- its transform, opacity, blend mode and isolation, its clip path, mask and filters --
// with every value resolved, so that applying them (`draw_group` in document.cpp) reads no attribute
// and no computed style. A group element (<g>, <svg>, <use>, <switch>, <a>, <text>, <image>) and every
// shape is drawn through one; a shape's fill and stroke are then its Path node (render_path.h).
//
// The clip path, mask and filters are the objects read once per render (resolved_references.h). What is
// still decided while drawing is what depends on the drawing: a clip path or mask met again inside its own
// content (a loop, cut where it closes), a filter cycle through <feImage>, and how deep clips and layers
// nest.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "clip_path.h"
#include "curvescan/curves/affine.h"
#include "curvescan/curves/rect.h"
#include "curvescan/raster/layer.h"
#include "curvescan/svg/color.h"
#include "filter/filter_property.h"
#include "filter/resolved_filter.h"
#include "mask.h"

namespace curvescan::svg::detail {

/// One entry of a filter list (Filter Effects 1, 15: `filter`): a filter function with its lengths in
/// user units, or a url() with the <filter> it names.
struct GroupFilter {
  filter::FilterFunction function;  ///< em lengths resolved for the element's font size (resolved_for)
  /// kUrl: the <filter> read for this viewport; null when the url() names no <filter> (the drawing then
  /// skips it, or draws nothing when no entry of the list is usable).
  const filter::ResolvedFilter* filter = nullptr;
};

/// A clip-path or mask reference: the object it names, or -- when it names no element of that kind -- its
/// name alone, for the warning the drawing gives. Its id is derived, never kept twice.
template <class Resolved>
struct EffectReference {
  const Resolved* resolved = nullptr;  ///< the object read for this viewport; null when it names none
  std::string unresolved;              ///< the id as written when `resolved` is null; empty otherwise

  /// Whether the element has the reference at all.
  [[nodiscard]] bool present() const noexcept { return resolved != nullptr || !unresolved.empty(); }
  /// The id as written, for warnings (a loop, a depth): the id index keys elements by their `id`
  /// attribute (document_index.h), so a resolved object's element carries it.
  [[nodiscard]] std::string id() const {
    return resolved != nullptr ? std::string(resolved->element.attribute("id").value()) : unresolved;
  }
};

/// The reference `id` (not empty) whose object is `resolved` (null: it names none).
template <class Resolved>
[[nodiscard]] EffectReference<Resolved> referenced(const Resolved* resolved, const std::string& id) {
  if (resolved != nullptr) return {resolved, {}};
  return {nullptr, id};
}

struct GroupNode {
  /// The element's transform about its transform-origin (CSS Transforms 1, 6.1), from the element's
  /// parent's user space to its own; for the root <svg>, its viewBox mapping follows it (SVG 2 8.5).
  Affine transform;
  double opacity = 1.0;                       ///< 0..1, composited as a layer
  BlendMode blend_mode = BlendMode::kNormal;  ///< mix-blend-mode (CSS Compositing 1, 3.2)
  bool isolate = false;                       ///< isolation: isolate (CSS Compositing 1, 3.3)

  /// clip-path: the <clipPath> read for this viewport; absent when the element has none, the name alone
  /// when it names no <clipPath> (drawn unclipped, with a warning).
  EffectReference<ResolvedClipPath> clip_path;
  /// mask: as clip_path, for a <mask>.
  EffectReference<ResolvedMask> mask;
  /// filter: each entry of the list in order; empty when the element has none.
  std::vector<GroupFilter> filters;
  /// The element's `color`: what currentColor means in its filters (drop-shadow(), flood-color).
  Color current_color;

  /// The element's object bounding box (SVG 1.1 7.11) in its own user space, for the objectBoundingBox
  /// units of its effects: a shape's whenever it has a clip path, mask or filter (a pass over its
  /// curves' extrema; a clipPath's own clip-path may refer to it); another element's only when a mask,
  /// a filter or a clip path in objectBoundingBox units asks (a walk of its content). nullopt
  /// otherwise, or when it has no geometry.
  std::optional<Rect> box;
};

}  // namespace curvescan::svg::detail
