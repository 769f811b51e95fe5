// The fewest trails covering every edge of a graph once, one set per connected component: the polylines of
// a contoured implicit curve (implicit_curve.cpp), where a smooth closed component is a cycle, an open one
// (cut by the box) a path, and a singular point (a lemniscate's node) a vertex of degree 4.
//
// Each component with 2k odd-degree vertices needs exactly max(k, 1) trails (Euler; Listing). The odd
// vertices are paired by k virtual edges, an Euler circuit of the now even component is found by
// Hierholzer's algorithm (iterative, with an explicit stack), and the circuit is cut at the virtual edges.
// A component without odd vertices gives one closed trail, whose last vertex repeats its first.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace curvescan::detail {

/// Trails (vertex sequences) of the graph with `vertex_count` vertices and the given undirected edges
/// (self-loops ignored). Every edge lies on exactly one trail.
std::vector<std::vector<std::size_t>> euler_trails(
    std::size_t vertex_count, const std::vector<std::pair<std::size_t, std::size_t>>& edges);

}  // namespace curvescan::detail
