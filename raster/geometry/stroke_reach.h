// How far a stroke's outline reaches from its path: the margin beyond which a piece of the path cannot
// put ink in a given box, so that its dashes need not be made (dash_contours) or counted (Canvas).
#pragma once

#include <algorithm>
#include <numbers>

#include "curvescan/curves/rect.h"
#include "curvescan/raster/stroke.h"

namespace curvescan::detail {

/// The farthest any point of `style`'s outline lies from the path it strokes, flattened within
/// `tolerance`: half the width times the largest of 1 (the body and round joins and caps), √2 (a square
/// cap's corners) and the miter limit (a miter's tip, SVG 2 §13.5.4: miter length / width <= limit),
/// plus twice the tolerance (the outline's arcs and a dash end placed on the curve rather than its chord
/// are each within the tolerance of the true shape).
[[nodiscard]] inline double stroke_reach(const StrokeStyle& style, double tolerance) noexcept {
  double factor = 1.0;
  if (style.cap == LineCap::kSquare) factor = std::numbers::sqrt2;
  if (style.join == LineJoin::kMiter || style.join == LineJoin::kMiterClip) {
    factor = std::max(factor, style.miter_limit);
  }
  return 0.5 * style.width * factor + 2.0 * tolerance;
}

/// `visible` grown by the stroke's reach on every side. A piece of path outside this box is farther than
/// the reach from every point of `visible` (its distance along x or y alone is), so no dash made of it,
/// nor a cap or join where it is cut, can draw inside `visible`.
[[nodiscard]] inline Rect dash_cull_box(const Rect& visible, const StrokeStyle& style,
                                        double tolerance) noexcept {
  const double reach = stroke_reach(style, tolerance);
  return {visible.x0 - reach, visible.y0 - reach, visible.x1 + reach, visible.y1 + reach};
}

}  // namespace curvescan::detail
