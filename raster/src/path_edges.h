// add_path_edges: a device-space Path to rasterizer edges, through the one flattener (curves flatten.h).
#pragma once

#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/rasterizer.h"

namespace curvescan::detail {

/// Adds the edges of every contour of `path` (device pixels) to `rasterizer`: lines as they are, curves
/// flattened within `tolerance`, every contour closed (explicitly or implicitly, for filling).
/// `polyline` is scratch space.
void add_path_edges(const Path& path, double tolerance, Rasterizer& rasterizer, std::vector<Point>& polyline);

}  // namespace curvescan::detail
