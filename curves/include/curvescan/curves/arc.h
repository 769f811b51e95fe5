// Elliptical arcs as exact conics.
//
// A circle has no polynomial parametrization (Ince, *Curves*, "Rational curves ... can represent circles and
// ellipses"), but the rational quadratic does: Dill, *Introduction to Parametric Curves* ("Parametric form")
// writes the first quadrant of the unit circle as x = (1-t²)/(1+t²), y = 2t/(1+t²), and Umetani, *Parametric
// Curve*, §4.1 shows how homogeneous weights make the circle exact. In Bézier form, the arc of the unit
// circle from angle a to a + φ (|φ| < π) is the rational quadratic with
//
//   P0 = (cos a, sin a),  P1 = (cos(a + φ/2), sin(a + φ/2)) / cos(φ/2),  P2 = (cos(a+φ), sin(a+φ)),
//   weights (1, cos(φ/2), 1)
//
// (P1 is where the end tangents meet). Rational Bézier curves are affine invariant (Ince, *Curves*, "Affine
// invariance property"; the weights are untouched), so an ellipse arc is the unit-circle arc mapped by
// translate(center)·rotate(x_rotation)·scale(rx, ry).
#pragma once

#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/curves/rational_bezier.h"

namespace curvescan {

/// The arc of the ellipse with centre `center`, radii rx, ry > 0, x axis rotated by `x_rotation` radians,
/// from angle `start_angle` to `start_angle + sweep_angle` (radians, in the ellipse's own frame, positive
/// from +x towards +y; |sweep| larger than 2π is clamped to one full turn) as exact conics: rational
/// quadratic Béziers with weights (1, cos(φ/2), 1), each spanning φ <= 90°. Empty for a zero sweep.
///
/// Segments are consecutive: segment k ends exactly (bit for bit) where segment k+1 starts, the first starts
/// at angle start_angle and the last ends at angle start_angle + sweep_angle (computed directly, not by
/// accumulation). Degenerate input: a NaN sweep, or a non-finite start angle, gives an empty vector; other
/// non-finite arguments propagate as NaN coordinates (NaN in, NaN out). Radii are used as given: zero or
/// negative radii give the degenerate or mirrored affine image of the circle arc (SVG callers take |r| and
/// treat zero radii as a line before calling).
[[nodiscard]] std::vector<RationalBezier> elliptical_arc_conics(Point center, double rx, double ry,
                                                                double x_rotation, double start_angle,
                                                                double sweep_angle);

}  // namespace curvescan
