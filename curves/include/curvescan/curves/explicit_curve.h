// Explicit curves y = f(x) over [x0, x1] (Ince after Elias, *Lecture 11: Curves*, "Explicit
// representation"), flattened with a proof: every emitted segment is within the tolerance of the graph,
// as a vertical distance, which bounds the Hausdorff distance too.
//
// Adaptive subdivision of [x0, x1]. A piece [a, b] with its chord from (a, f(a)) to (b, f(b)) is accepted
// when interval arithmetic (interval.h, expression.h) proves one of:
//   - box: f over [a, b] lies in [lo, hi] and the box [a, b] × [lo, hi] has a diagonal <= tolerance (the
//     chord and the graph are both inside it);
//   - slope: with f' enclosed over [a, b] and s the chord's slope, |f − chord| <= e + (b − a)/2 · sup|f' − s|
//     <= tolerance, where e bounds the rounding of f(a) and f(b) (the mean value theorem from both ends);
// and is split at its midpoint otherwise. Where no proof comes down to the smallest piece (2^-max_depth of
// the range) — a pole, a jump, a point where f is undefined, an unbounded derivative — the graph is split
// there and the polyline ends; the output has several polylines. Parts of the graph wholly outside the
// vertical band [y_min, y_max] are dropped (a pole would otherwise need pieces without end) and reported.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "curvescan/curves/expression.h"
#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan {

struct ExplicitCurveOptions {
  double tolerance = 0.1;  ///< the largest distance between polyline and graph, in curve units
  int max_depth = 48;      ///< halvings of [x0, x1]: the smallest piece is 2^-48 of the range
  std::size_t max_pieces = std::size_t{1} << 22;  ///< pieces examined in all (accepted or split)
  /// Pieces examined times the expression's terms: the work bound for long expressions (a piece costs a
  /// few evaluations of every term). 2^23 is about 5 s for the longest expressions.
  std::size_t max_work = std::size_t{1} << 23;
  double y_min = -1e6;  ///< the vertical band the graph is drawn in
  double y_max = 1e6;
};

struct ExplicitCurve {
  /// One polyline per continuous stretch of the graph, left to right; vertices (x, f(x)) with f evaluated
  /// in double.
  std::vector<std::vector<Point>> polylines;
  /// The x ranges where the graph was split (pole, jump, undefined, or unprovable), merged, left to right.
  std::vector<std::pair<double, double>> splits;
  bool clipped = false;  ///< some of the graph lay outside [y_min, y_max] and was dropped
};

/// The graph of `f` (a function of x) over [x0, x1], x0 < x1 finite. Errors: invalid range or options
/// (kInvalidArgument), more than max_pieces pieces needed (kLimitExceeded, naming the tolerance).
Result<ExplicitCurve> flatten_explicit_curve(const Expression& f, double x0, double x1,
                                             const ExplicitCurveOptions& options = {});

}  // namespace curvescan
