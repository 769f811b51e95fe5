// Private to the stroker and dasher: the curve piece a chord of a FlatContour was flattened from, and the
// exact point and tangent on it where a chord is cut (a flattener vertex, a dash end).
//
// Why: a dash end falls inside a chord. Its cap (butt, square, round) is cut on the curve's normal there,
// and a wide stroke multiplies any error in that normal by h = width/2. Interpolating between the chord's
// exact end tangents is off by a fraction of the chord's turn where the curvature changes along the chord
// (near a tight bend: 0.15 px at h = 50, 63/255 off the swept reference on oracle scene 129). The piece
// gives the exact answer instead: it is monotone along any chord of it (its tangents lie within max_turn/2
// <= π/8 of one another, stroker_flatten.cpp, so within π/4 of the chord's direction, which is an average of
// them), hence the curve point whose projection on the chord's direction equals the dash end's is unique,
// found by Newton's method kept inside the bracket [0, 1] (bisection where a step leaves it), and the
// tangent there is the direction between the last two de Casteljau points (Umetani, *Parametric Curve*, eq. 8; the hodograph's direction, Umetani, *Parametric Curve*, §2.3).
#pragma once

#include <optional>
#include <span>

#include "curvescan/curves/point.h"

namespace curvescan::detail {

/// A control point in homogeneous form (x·w, y·w, w); w = 1 for a polynomial Bézier.
struct HomogeneousPoint {
  double x, y, w;
};

/// A point of a curve piece and the curve's unit tangent there.
struct CurvePoint {
  Point point;
  Vec2 tangent;
};

/// On the Bézier piece `control` (homogeneous, positive weights, at most kMaxPathCurveDegree + 1 points),
/// the point whose projection on `axis` equals q's, and the unit tangent there. std::nullopt when q's
/// projection is not strictly between the piece's ends' (rounding at the ends, a piece that is not monotone
/// along `axis`: a cusp piece), when the tangent vanishes there, or on NaN input.
[[nodiscard]] std::optional<CurvePoint> curve_point_along(std::span<const HomogeneousPoint> control, Point q,
                                                          Vec2 axis) noexcept;

}  // namespace curvescan::detail
