// Implicit curves f(x, y) = 0 in a box (Ince after Elias, *Lecture 11: Curves*, "Implicit
// representation"), contoured with interval arithmetic.
//
// An interval quadtree (Snyder, "Interval analysis for computer graphics", SIGGRAPH 1992): a cell where
// the enclosure of f excludes a sign change is discarded; the others are split until they are no larger
// than the tolerance (diagonal) and their topology is certified, in the spirit of Plantinga and Vegter
// ("Isotopic approximation of implicit curves and surfaces", SGP 2004): ∂f/∂y excludes 0 over the cell (the
// curve is a graph over x there: no loops, at most one crossing per vertical edge) and along each
// horizontal edge f has no sign change or ∂f/∂x excludes 0 (at most one crossing), or the same with x and
// y exchanged. In such a cell the curve crosses the boundary exactly where the corner signs change, and
// the marching-squares segments between those crossings pair them as the curve does (no saddle case can
// occur), each within the cell's diagonal of the curve.
//
// Crossings are found by bisection along the edge down to a fixed dyadic grid (2^-12 of the deepest cell),
// so that a large cell and its smaller neighbours find the same point for a crossing on their common edge,
// and the segments join exactly. Cells that cannot be certified down to the deepest level (tolerance / 2^4)
// are grouped with their neighbours; a group no wider than the tolerance becomes a star, every crossing on
// its outer edges joined to its centre. A group where the gradient enclosure contains 0 in both components is
// a singular point (a node where branches cross, such as the lemniscate's), reported in
// `singular_points`; other groups (near-tangencies), wider groups and cells where f is undefined in part
// are contoured by marching squares with the centre value deciding saddles and counted in
// `uncertified_cells`.
// The segments are joined into the fewest polylines per connected component (euler_trails.h): a smooth
// closed component is one polyline whose last point repeats its first.
//
// The sign convention is f >= 0 versus f < 0: a curve where f touches 0 without changing sign (f = g²) is
// not found.
#pragma once

#include <cstddef>
#include <vector>

#include "curvescan/curves/expression.h"
#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan {

struct ImplicitCurveOptions {
  double tolerance = 0.1;  ///< cells are refined to this diagonal: the largest distance polyline — curve
  std::size_t max_cells = std::size_t{1} << 22;  ///< quadtree cells examined in all
  /// Cells examined times the expression's terms: the work bound for long expressions (a cell costs a
  /// handful of evaluations of every term, and its crossings a bisection each). 2^23 is about 5 s for the
  /// longest expressions.
  std::size_t max_work = std::size_t{1} << 23;
  int extra_levels = 4;  ///< levels below the tolerance's for cells that cannot be certified
};

struct ImplicitCurve {
  std::vector<std::vector<Point>> polylines;
  std::vector<Point> singular_points;  ///< centres of groups of cells where the gradient may vanish
  std::size_t uncertified_cells = 0;   ///< deepest cells contoured without a topology certificate
  std::size_t cells = 0;               ///< quadtree cells examined
};

/// The curve f(x, y) = 0 inside the box [min, max] (finite, min < max in both coordinates, extents
/// finite). Errors: invalid box or tolerance (kInvalidArgument), a tolerance too fine for the box (more
/// than 36 halvings) or more than max_cells cells (kLimitExceeded).
Result<ImplicitCurve> contour_implicit_curve(const Expression& f, Point min, Point max,
                                             const ImplicitCurveOptions& options = {});

}  // namespace curvescan
