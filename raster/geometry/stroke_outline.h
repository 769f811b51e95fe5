// Private to the stroker: the outline of one flattened contour (algorithm essay in stroker_outline.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/raster/stroke.h"
#include "stroke_contour.h"

namespace curvescan::detail {

struct OutlineParams {
  double half_width = 0.5;
  LineJoin join = LineJoin::kMiter;
  LineCap cap = LineCap::kButt;
  double miter_limit = 4.0;
  /// Largest distance between a round join or cap and its polygon (vertices on the circle).
  /// stroke_path() gives tolerance/2 (the budget in stroker.cpp); also the threshold past which a chord
  /// whose tangent turns too far gets a cusp disc.
  double arc_tolerance = 0.05;
  /// Most points the polygons may hold (the stroke's outline budget); see append_outlines.
  std::size_t max_points = SIZE_MAX;
};

/// Most polygon segments of one round join or cap. Reached only when half_width / arc_tolerance
/// exceeds ~10^6 (a stroke millions of pixels wide); the arc is then coarser than arc_tolerance.
inline constexpr int kMaxArcSegments = 1 << 12;

/// Polygons as one point array and the end index of each polygon (closed implicitly).
struct Polygons {
  std::vector<Point> points;
  std::vector<std::size_t> ends;
};

/// Appends the closed polygons whose nonzero union is the stroke of each contour (one for an open contour,
/// two for a closed one, none or one for a zero-length one), all wound clockwise in a y-up frame.
/// Returns false, leaving `out` partial, as soon as the points would pass params.max_points (checked
/// after every chord and join, so the overshoot before stopping is at most two arcs of kMaxArcSegments).
[[nodiscard]] bool append_outlines(std::span<const FlatContour> contours, const OutlineParams& params, Polygons& out);

}  // namespace curvescan::detail
