// transform-origin (CSS Transforms 1, 6.1) for SVG elements, whose transform-box is view-box: the
// reference box is the nearest viewport, its top-left corner at the origin of the user space, so that
// percentages and keywords refer to the viewport's width and height.
//
// One to three components (the third, z, must be 0 in 2D); x is a length, a percentage or
// left/center/right, y a length, a percentage or top/center/bottom; a single keyword top or bottom sets
// y; what is left out is center. Besides the elements' transform, it applies to gradientTransform and
// patternTransform, which SVG 2 (13.2.2, 13.3) makes presentation attributes of the transform property.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string_view>

#include "computed_style.h"
#include "curvescan/curves/affine.h"

namespace curvescan::svg::detail {

/// The origin `text` names, in user units, for a viewport of `width` x `height`; nullopt when it is not
/// a valid transform-origin (or has a z other than 0).
[[nodiscard]] std::optional<Point> transform_origin_point(std::string_view text, double width, double height,
                                                          double font_size, Resolution dpi,
                                                          Diagnostics& diagnostics);

/// `transform` about the transform-origin of paint server `node` (its style sheets, style attribute or
/// attribute; not inherited through href), for its gradientTransform or patternTransform; `transform`
/// itself when it sets none or an invalid one (with a warning). Percentages refer to the viewport of
/// `context`, em to the initial font size (a paint server's own font size is not computed).
[[nodiscard]] Affine paint_server_transform(const pugi::xml_node& node, const Affine& transform,
                                            const ResolveContext& context, Diagnostics& diagnostics);

/// `transform` about `origin`: translate(origin) * transform * translate(-origin).
[[nodiscard]] Affine about_origin(const Affine& transform, const Point& origin) noexcept;

}  // namespace curvescan::svg::detail
