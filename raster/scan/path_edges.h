// add_path_edges: a device-space Path to rasterizer edges, through the one flattener (curves flatten.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/rasterizer.h"

namespace curvescan::detail {

/// How the fast walk (a path of fixed-size verbs inside the clip box, with a valid tolerance) flattens the
/// quadratics that need more than one segment: kFewest by the adaptive walk (flatten_quadratic_bezier,
/// nearly the fewest segments), kUniform in equal parameter steps from Wang's bound
/// (flatten_quadratic_bezier_uniform: up to ~13 % more segments, much less work per segment). Other
/// paths and curves are flattened the same either way.
enum class QuadraticSteps { kFewest, kUniform };

/// Adds the edges of every contour of `path` (device pixels) to `rasterizer`: lines as they are, curves
/// flattened within `tolerance`, every contour closed (explicitly or implicitly, for filling).
/// `polyline` is scratch space. Returns the number of edges added; stops early, with a count above
/// `max_edges`, once more than `max_edges` were added (the per-render segment and memory budgets of
/// Canvas, limits.h: the rest of the path is neither flattened nor stored).
std::size_t add_path_edges(const Path& path, double tolerance, Rasterizer& rasterizer,
                           std::vector<Point>& polyline, std::size_t max_edges = SIZE_MAX,
                           QuadraticSteps quadratics = QuadraticSteps::kFewest);

/// The plain reference of add_path_edges, kept beside it so that a test can hold the optimised walk to it:
/// every element through Path::Iterator, every curve through flatten_visible (the clip cull), every edge
/// through Rasterizer::add_line. Adds the same edges in the same order and returns the same count.
std::size_t add_path_edges_reference(const Path& path, double tolerance, Rasterizer& rasterizer,
                                     std::vector<Point>& polyline, std::size_t max_edges = SIZE_MAX);

}  // namespace curvescan::detail
