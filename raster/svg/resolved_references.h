// References resolved into objects (docs/svg.md, "How a document is drawn", step 2): each paint server,
// clip path, mask, marker and filter a render meets is read from the XML once -- its href chain followed and
// loops cut, its attributes parsed and their warnings given, its units decided -- and the drawing code
// takes the resulting plain struct (paint_server.h, pattern.h, ...) for every use after that. A gradient
// filling a thousand shapes is read once, not a thousand times.
//
// Memoised per element and per viewport: lengths in user space are settled against the viewport of the
// element that refers to them (a percentage in a userSpaceOnUse gradient is of the viewport in force
// where it is used, SVG 1.1 7.10), and a document has one viewport unless it nests <svg> or <symbol>.
// The resolution and the style sheets are those of the whole render; reset() forgets everything when
// they change (the @media sheets chosen for the output size).
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <tuple>

#include "clip_path.h"
#include "computed_style.h"
#include "filter/resolved_filter.h"
#include "marker.h"
#include "mask.h"
#include "paint_server.h"
#include "pattern.h"

namespace curvescan::svg::detail {

/// The computed style of a referenced element from its own ancestors (SVG 1.1 6.7), supplied by the
/// drawing walk, which owns the cascade of the document.
using ReferencedStyle = std::function<ComputedStyle(const pugi::xml_node&)>;

class ResolvedReferences {
 public:
  /// Starts over with the id index `ids` (which must outlive the next reset) and forgets what was resolved.
  void reset(const IdIndex* ids);

  /// Gradient `element` (a <linearGradient> or <radialGradient>) resolved for `context`'s viewport.
  const ResolvedGradient& gradient(const pugi::xml_node& element, const ResolveContext& context,
                                   Diagnostics& diagnostics);

  /// Pattern `element` resolved for `context`'s viewport, its content's style from `style_of`.
  const ResolvedPattern& pattern(const pugi::xml_node& element, const ResolveContext& context,
                                 const ReferencedStyle& style_of, Diagnostics& diagnostics);

  /// The <clipPath> `id` names, resolved for `context`'s viewport; null when `id` names no <clipPath>.
  const ResolvedClipPath* clip_path(const std::string& id, const ResolveContext& context,
                                    const ClipPathReader& reader);

  /// The <marker> `id` names, resolved for `context`'s viewport with its style from `style_of`; null when
  /// `id` names no <marker>.
  const ResolvedMarker* marker(const std::string& id, const ResolveContext& context,
                               const ReferencedStyle& style_of, Diagnostics& diagnostics);

  /// The <mask> `id` names, resolved for `context`'s viewport with its style from `style_of`; null when
  /// `id` names no <mask>.
  const ResolvedMask* mask(const std::string& id, const ResolveContext& context,
                           const ReferencedStyle& style_of, Diagnostics& diagnostics);

  /// The <filter> `id` names, resolved for `context`'s viewport with its primitives' properties cascaded
  /// with `style_sheets` and the style an feImage's element inherits from `style_of`; null when `id` names
  /// no <filter>.
  const filter::ResolvedFilter* filter(const std::string& id, const ResolveContext& context,
                                       const css::StyleSheets* style_sheets, const ReferencedStyle& style_of,
                                       Diagnostics& diagnostics);

  /// How many objects have been resolved since the last reset (each a read of the XML).
  [[nodiscard]] std::size_t resolved_count() const noexcept { return resolved_count_; }

 private:
  // An element (pugixml's node identity) and the viewport its lengths were settled for.
  using Key = std::tuple<const void*, double, double>;
  static Key key_of(const pugi::xml_node& element, const ResolveContext& context) {
    return {element.internal_object(), context.viewport_width, context.viewport_height};
  }

  // The object `memo` holds for `element` in `context`'s viewport, made by `resolve()` the first time.
  template <class Resolved, class Resolve>
  Resolved& memoised(std::map<Key, Resolved>& memo, const pugi::xml_node& element,
                     const ResolveContext& context, Resolve&& resolve);

  // The element `id` names when it is a <`kind`>, memoised as above; null otherwise.
  template <class Resolved, class Resolve>
  const Resolved* memoised_by_id(std::map<Key, Resolved>& memo, const std::string& id, std::string_view kind,
                                 const ResolveContext& context, Resolve&& resolve);

  const IdIndex* ids_ = nullptr;
  std::map<Key, ResolvedGradient> gradients_;
  std::map<Key, ResolvedPattern> patterns_;
  std::map<Key, ResolvedClipPath> clip_paths_;
  std::map<Key, ResolvedMarker> markers_;
  std::map<Key, ResolvedMask> masks_;
  std::map<Key, filter::ResolvedFilter> filters_;
  std::size_t resolved_count_ = 0;
};

}  // namespace curvescan::svg::detail
