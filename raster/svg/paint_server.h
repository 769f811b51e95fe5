// SVG paint servers: <linearGradient> and <radialGradient> (SVG 1.1 section 13.2) turned into curvescan
// Paints (gradient.h).
//
// Attribute resolution follows 13.2.2-13.2.4: each attribute (x1 ... r, fx, fy, fr, gradientUnits,
// gradientTransform, spreadMethod) comes from the first gradient of the href chain that specifies it, and
// the stops from the first gradient of the chain that has any <stop> children. The chain is followed at
// most kMaxGradientChain links and stops at a cycle (with a warning). With gradientUnits=
// "objectBoundingBox" (the default) the geometry is in the unit square of the shape's bounding box: the
// gradient_to_user transform is then bbox · gradientTransform, and a box with zero width or height makes
// the gradient unusable (SVG 1.1 7.11: the effect is ignored): the caller paints the fallback colour of
// the paint, if any, as for an invalid paint server (SVG 2 13.3; rsvg-convert and resvg do the same).
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string>
#include <unordered_map>

#include "computed_style.h"
#include "curvescan/curves/rect.h"
#include "curvescan/raster/paint.h"

namespace curvescan::svg::detail {

using IdIndex = std::unordered_map<std::string, pugi::xml_node>;

inline constexpr int kMaxGradientChain = 16;

/// The Paint of gradient `element` for a shape with user-space bounding box `bbox`, every stop's alpha
/// multiplied by `opacity` (fill-opacity / stroke-opacity). nullopt = paint nothing; then
/// `*refused_for_box` (when given) tells whether that is because of a box without area. `bbox` and the
/// gradient are in the user space that `space` maps to the painted element's (identity: the element's
/// own; another for context-fill, drawn in the context element's space).
[[nodiscard]] std::optional<Paint> gradient_paint(const pugi::xml_node& element, const IdIndex& ids,
                                                  const Rect& bbox, double opacity,
                                                  const ResolveContext& context, Diagnostics& diagnostics,
                                                  bool* refused_for_box = nullptr,
                                                  const Affine& space = Affine::identity());

}  // namespace curvescan::svg::detail
