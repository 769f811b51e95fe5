// The basic shapes of SVG as Paths (SVG 1.1 chapter 9; the equivalent path of each is given in SVG 2
// section 10). Circles and ellipses are exact conics (PathBuilder::arc), so no approximation enters.
#pragma once

#include <optional>
#include <span>

#include "curvescan/curves/point.h"
#include "curvescan/raster/path.h"

namespace curvescan::svg::detail {

/// rect: rx/ry resolved by SVG 1.1 9.2 (a missing one takes the other's value, both clamped to half the
/// size). nullopt when width or height is <= 0 (the element is not rendered).
[[nodiscard]] std::optional<Path> rect_path(double x, double y, double width, double height,
                                            std::optional<double> rx, std::optional<double> ry);
/// ellipse (and circle with rx == ry): starts at (cx + rx, cy), positive angles (SVG 2 10.4). nullopt
/// when a radius is <= 0.
[[nodiscard]] std::optional<Path> ellipse_path(double cx, double cy, double rx, double ry);
[[nodiscard]] std::optional<Path> line_path(Point from, Point to);
/// polyline / polygon from a point list; an odd trailing coordinate is dropped by the caller.
[[nodiscard]] std::optional<Path> polyline_path(std::span<const double> coordinates, bool closed);

}  // namespace curvescan::svg::detail
