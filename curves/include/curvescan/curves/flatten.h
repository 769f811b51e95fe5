// The flattener: every curve in curvescan becomes a polyline here, and only here.
//
// Interface fixed by the skeleton; the algorithm and its tuning live in src/flatten.cpp, the flatness bound
// and its proof in src/flatness_bound.h, the same bound in closed form for quadratics and conics (O(1) per
// trial, no split) in src/flatten_quadratic.h and src/flatten_conic.h, a closed-form bound of a cubic's
// sub-arc in src/flatten_cubic.h, measurements in docs/flattening.md.
// Contract: the Hausdorff distance between the emitted polyline and the curve is <= tolerance (in the
// units of the control points: device pixels when called after the transform). All polyline vertices lie
// on the curve (de Casteljau split points). Work is bounded on any input.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "curvescan/curves/point.h"

namespace curvescan {

/// Default tolerance in device pixels, as Cairo's default (0.1 px).
inline constexpr double kDefaultFlattenTolerance = 0.1;

/// Most segments one curve may be cut into; past it the flattener stops refining and reports it.
inline constexpr std::size_t kMaxFlattenSegments = std::size_t{1} << 22;

enum class FlattenOutcome {
  kOk,            ///< the polyline is within tolerance
  kNonFinite,     ///< a control point, weight or the tolerance is NaN or infinite, or finite values whose
                  ///< differences (or weight·coordinate products) overflow double: nothing appended
  kInvalid,       ///< fewer than two control points, mismatched weights, a weight <= 0, tolerance <= 0
  kSegmentLimit,  ///< kMaxFlattenSegments reached, or a tolerance below the floating-point resolution of the
                  ///< coordinates: the polyline is complete (ends at ctrl.back()) but may exceed tolerance
};

/// Flattens the polynomial Bézier with control points `ctrl` (any degree >= 1).
/// Appends the polyline's vertices after the first (the first is ctrl.front()) to `out`; the last
/// appended vertex is exactly ctrl.back().
/// `max_segments` (at least 1) caps the segments of this one curve: callers with a budget (a render's
/// segment limit, the stroker's outline budget) pass what is left of it, so that a curve far too fine for
/// the budget costs at most that much work; past it the result is kSegmentLimit, as at kMaxFlattenSegments.
/// The work per segment is bounded too: at most 200 bound evaluations for one segment and 200 + 8 per
/// segment of the cap for the whole curve, past which the result is kSegmentLimit as well (the rest of
/// the curve is a chord to its end; docs/flattening.md §2).
FlattenOutcome flatten_bezier(std::span<const Point> ctrl, double tolerance, std::vector<Point>& out,
                              std::size_t max_segments = kMaxFlattenSegments);

/// flatten_bezier({p0, p1, p2}, tolerance, out, max_segments) for one quadratic, without the general
/// degree dispatch: the same contract, outcome and polyline, bit for bit (tests/unit/flatten holds them
/// equal). For callers that flatten many small quadratics, such as TrueType glyph outlines, most of
/// which need a single segment (docs/flattening.md).
FlattenOutcome flatten_quadratic_bezier(Point p0, Point p1, Point p2, double tolerance, std::vector<Point>& out,
                                        std::size_t max_segments = kMaxFlattenSegments);

/// flatten_quadratic_bezier(p0, p1, p2, tolerance, out, max_segments) for a caller that has already made
/// its first test: the points are finite, the tolerance is finite and positive, and Wang's bound
/// |p0 - 2·p1 + p2| / 4 exceeds the tolerance (so one segment is not enough). Then the outcome and the
/// polyline are those of flatten_quadratic_bezier, bit for bit; the checks and the bound are not computed
/// a second time (a glyph's walk in raster/scan/path_edges.cpp makes them inline, where about half of
/// the quadratics at 12 px stop). Outside that precondition the contract above still holds, only the
/// vertices may differ.
FlattenOutcome flatten_quadratic_bezier_past_one_segment(Point p0, Point p1, Point p2, double tolerance,
                                                         std::vector<Point>& out,
                                                         std::size_t max_segments = kMaxFlattenSegments);

/// The finest tolerance flatten_bezier and flatten_rational can certify for the control points `ctrl`: a
/// few dozen ulps of their largest |coordinate| (every vertex is a de Casteljau point carrying that much
/// rounding). A curve that is not already within a finer tolerance is walked at this one instead and
/// reported as kSegmentLimit, so callers can tell the user why (for ±1e308 it is about 7e293).
double flatten_resolution(std::span<const Point> ctrl) noexcept;
/// Flattens the rational Bézier (ctrl, weights), weights > 0, with the same contract.
FlattenOutcome flatten_rational(std::span<const Point> ctrl, std::span<const double> weights,
                                double tolerance, std::vector<Point>& out,
                                std::size_t max_segments = kMaxFlattenSegments);

}  // namespace curvescan
