// The core's StrokeStyle (stroke.h) of an element's computed stroke properties: SVG 2 13.5
// ('stroke-width', 'stroke-linejoin', 'stroke-linecap', 'stroke-miterlimit', 'stroke-dasharray',
// 'stroke-dashoffset'), already validated and in user units by the cascade (computed_style.h).
#pragma once

#include "computed_style.h"
#include "curvescan/raster/stroke.h"

namespace curvescan::svg::detail {

/// The stroke `style` asks for. `arcs` (SVG 2) is drawn as `miter`, the fallback SVG 2 gives where arcs
/// joins are not supported; `miter-clip` is the core's own.
[[nodiscard]] StrokeStyle stroke_style_of(const ComputedStyle& style);

}  // namespace curvescan::svg::detail
