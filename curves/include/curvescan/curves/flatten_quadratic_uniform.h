// A quadratic Bézier flattened in uniform parameter steps, their number from Wang's bound in closed form:
// the flattener's contract (flatten.h) with a few more segments than its adaptive walk and no search per
// segment. Proof of the bound in src/flatten_quadratic_uniform.cpp; measurements in docs/flattening.md §1d.
#pragma once

#include <cstddef>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/curves/point.h"

namespace curvescan {

/// The quadratic Bézier (p0, p1, p2) flattened in n equal parameter steps, n = ceil(sqrt(|p0 - 2·p1 + p2|
/// / (4·tolerance))) from Wang's bound (plus the rounding margins; proof in
/// src/flatten_quadratic_uniform.cpp and docs/flattening.md §1d): the same contract as flatten_bezier —
/// Hausdorff distance <= tolerance, vertices on the curve, the last exactly p2 — with about 9-13 %
/// more segments than flatten_quadratic_bezier but no search per segment. Curves it cannot certify
/// (non-finite input, coordinates beyond 1e100, tolerances near their resolution, more than
/// `max_segments` steps) go to flatten_quadratic_bezier, with its outcome.
FlattenOutcome flatten_quadratic_bezier_uniform(Point p0, Point p1, Point p2, double tolerance,
                                                std::vector<Point>& out,
                                                std::size_t max_segments = kMaxFlattenSegments);

/// flatten_quadratic_bezier_uniform for a caller that has already computed `second_length`, the length of the
/// second difference as the function above does: std::sqrt(((p0 - p1) + (p2 - p1)).length_squared()), these
/// operations in this order (a glyph's walk in raster/scan/path_edges.cpp has it from its one-segment test).
/// Then the outcome and the polyline are those of the function above, bit for bit, and the square root is not
/// taken a second time. Another value gives a polyline whose error bound is not proven.
FlattenOutcome flatten_quadratic_bezier_uniform_with_length(Point p0, Point p1, Point p2,
                                                            double second_length, double tolerance,
                                                            std::vector<Point>& out,
                                                            std::size_t max_segments = kMaxFlattenSegments);

}  // namespace curvescan
