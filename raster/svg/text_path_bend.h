// textPath method="stretch" (SVG 1.1 10.13.2): geometry in a path's own coordinates — x the distance along
// the path, y the offset across it (down, to the right of the direction of travel) — bent onto the path.
// Glyph outlines, their decorations and their cells go through the same mapping, so that a bent glyph
// keeps its underline under it and its bounding box around it.
#pragma once

#include <span>
#include <vector>

#include "curvescan/curves/point.h"
#include "text_path_measure.h"

namespace curvescan::svg::detail {

/// The point at distance p.x along `path`, moved by p.y along the normal there (the tangent turned a quarter
/// turn clockwise on screen); the path's tangent turns continuously (PathMeasure::at_smooth). Past either
/// end the end's tangent continues the path.
[[nodiscard]] Point bend_point(const PathMeasure& path, Point p) noexcept;

/// The longest piece a straight edge of a glyph of em size `size` is cut into before it is bent: a fortieth
/// of the em, so that a stem or an underline follows the path's curve smoothly at any size.
[[nodiscard]] constexpr double bend_step(double size) noexcept {
  return size / 40.0;
}

/// Appends to `bent` the closed polygon `polygon` bent onto `path`: each edge cut into pieces no longer than
/// `step` (at most 1000 per edge), every vertex and cut mapped by bend_point, so that a straight edge
/// follows the path's curve (a bent polyline stays within the flattening tolerance of the exact warp where
/// moved control points of curves would not). The closing edge is cut too; its end, the first vertex, is
/// not repeated.
void bend_polygon(const PathMeasure& path, std::span<const Point> polygon, double step,
                  std::vector<Point>& bent);

}  // namespace curvescan::svg::detail
