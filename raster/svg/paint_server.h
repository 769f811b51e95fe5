// SVG paint servers: <linearGradient> and <radialGradient> (SVG 1.1 section 13.2) turned into curvescan
// Paints (gradient.h).
//
// Resolution (resolve_gradient, once per gradient and viewport in a render: resolved_references.h)
// follows 13.2.2-13.2.4: each attribute (x1 ... r, fx, fy, fr, gradientUnits, gradientTransform,
// spreadMethod) comes from the first gradient of the href chain that specifies it, and the stops from the
// first gradient of the chain that has any <stop> children. The chain is followed at most kMaxGradientChain
// links and stops at a cycle (with a warning). With gradientUnits= "objectBoundingBox" (the default) the
// geometry is in the unit square of the shape's bounding box: the gradient_to_user transform is then bbox ·
// gradientTransform, and a box with zero width or height makes the gradient unusable (SVG 1.1 7.11: the
// effect is ignored): the caller paints the fallback colour of the paint, if any, as for an invalid paint
// server (SVG 2 13.3; rsvg-convert and resvg do the same).
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string>
#include <unordered_map>
#include <vector>

#include "computed_style.h"
#include "curvescan/curves/rect.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/paint.h"

namespace curvescan::svg::detail {

using IdIndex = std::unordered_map<std::string, pugi::xml_node>;

inline constexpr int kMaxGradientChain = 16;

/// A <linearGradient> or <radialGradient> with its href chain followed and every attribute read: what a
/// use of it needs besides the painted shape's box, the paint's opacity and its space. Lengths are
/// settled for the viewport of the ResolveContext it was resolved for (user-space percentages refer to
/// it); in objectBoundingBox units they are fractions of the box.
struct ResolvedGradient {
  bool radial = false;
  bool bounding_box_units = true;  ///< gradientUnits="objectBoundingBox" (the default)
  /// gradientTransform about the paint server's transform-origin; nullopt when there is none (or it was
  /// ignored: singular or malformed, with a warning).
  std::optional<Affine> transform;
  SpreadMethod spread = SpreadMethod::kPad;
  /// The stops of the first gradient of the chain that has any, each alpha times its stop-opacity (the
  /// paint's opacity multiplies in per use); empty: the gradient paints none (13.2.4).
  std::vector<GradientStop> stops;
  LinearGradient linear;  ///< x1, y1, x2, y2 (when !radial)
  RadialGradient circle;  ///< cx, cy, r, fx, fy, fr (when radial)
};

/// Reads gradient `element` (linearGradient or radialGradient): follows its href chain (loops cut with a
/// warning), takes each attribute from the first gradient of the chain that has it, and resolves the
/// stops' colours (currentColor and inherit from the stops' own ancestors). Warnings go to `diagnostics`.
[[nodiscard]] ResolvedGradient resolve_gradient(const pugi::xml_node& element, const IdIndex& ids,
                                                const ResolveContext& context, Diagnostics& diagnostics);

/// The Paint of `gradient` for a shape with user-space bounding box `bbox`, every stop's alpha multiplied
/// by `opacity` (fill-opacity / stroke-opacity). nullopt = paint nothing; then `*refused_for_box` (when
/// given) tells whether that is because of a box without area. `bbox` and the gradient are in the user
/// space that `space` maps to the painted element's (identity: the element's own; another for
/// context-fill, drawn in the context element's space).
[[nodiscard]] std::optional<Paint> gradient_paint(const ResolvedGradient& gradient, const Rect& bbox,
                                                  double opacity, bool* refused_for_box = nullptr,
                                                  const Affine& space = Affine::identity());

}  // namespace curvescan::svg::detail
