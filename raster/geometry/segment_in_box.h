// The part of a line segment inside an axis-aligned box (Liang and Barsky's parametric clip).
#pragma once

#include <optional>

#include "curvescan/curves/point.h"
#include "curvescan/curves/rect.h"

namespace curvescan::detail {

/// The parameters [t0, t1] ⊆ [0, 1] of the points a + t·(b − a) inside the closed box, or nullopt when the
/// segment misses it. The segment's points and the box must be finite.
struct SegmentSpan {
  double t0 = 0.0, t1 = 1.0;
};

[[nodiscard]] inline std::optional<SegmentSpan> segment_in_box(Point a, Point b, const Rect& box) noexcept {
  SegmentSpan span;
  // Each side of the box bounds t from one side: p·t <= q, with p the segment's motion toward the side
  // and q the room left from a to the side.
  const auto bound = [&span](double p, double q) {
    if (p == 0.0) return q >= 0.0;  // parallel to the side: inside its half-plane or not at all
    const double t = q / p;
    if (p < 0.0) {
      if (t > span.t1) return false;
      if (t > span.t0) span.t0 = t;
    } else {
      if (t < span.t0) return false;
      if (t < span.t1) span.t1 = t;
    }
    return true;
  };
  const double dx = b.x - a.x, dy = b.y - a.y;
  if (bound(-dx, a.x - box.x0) && bound(dx, box.x1 - a.x) && bound(-dy, a.y - box.y0) &&
      bound(dy, box.y1 - a.y)) {
    return span;
  }
  return std::nullopt;
}

}  // namespace curvescan::detail
