// The JSON curve specification read by `curvescan curve` (documented in docs/curve-spec.md).
//
// A spec names one curve of any family; build_curve_segments() converts it exactly into Bézier pieces
// (polynomial or rational), the common currency that the flattener and the renderer understand.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan::cli {

/// One exact Bézier piece of the curve; weights is empty for a polynomial piece.
struct CurveSegment {
  std::vector<Point> points;
  std::vector<double> weights;
};

/// Limits on what one spec may ask for, so that a hostile spec cannot exhaust memory or time.
struct CurveSpecLimits {
  std::size_t max_points = 1'000'000;
  int max_degree = 64;
  /// Explicit and implicit curves: pieces or cells examined times the terms of the expression
  /// (ExplicitCurveOptions::max_work).
  std::size_t max_work = std::size_t{1} << 23;
};

/// Validates `spec` and converts the curve it describes into Bézier pieces. Every error names the field.
Result<std::vector<CurveSegment>> build_curve_segments(const nlohmann::json& spec, const CurveSpecLimits& limits);

/// The polyline of all pieces at `tolerance`, at most `max_segments` (>= 1) segments in all. Each piece is
/// flattened with what is left of the budget as its own cap, so the work is bounded by the budget, not by
/// the flattener's per-curve cap times the number of pieces. Errors (kLimitExceeded or kInvalidArgument)
/// say which limit was reached and what to raise: the budget, the per-curve cap, or a tolerance finer
/// than the coordinates can resolve (control points near ±1e308); and why a piece cannot be flattened at
/// all (control points further apart than the double range).
Result<std::vector<Point>> flatten_curve_segments(const std::vector<CurveSegment>& segments, double tolerance,
                                                  std::size_t max_segments);

}  // namespace curvescan::cli
