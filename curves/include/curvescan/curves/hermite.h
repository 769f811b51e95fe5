// Cubic Hermite curves: a cubic given by its end points and end tangents.
//
//   P(t) = f1(t) P1 + f2(t) P4 + f3(t) R1 + f4(t) R4,   t in [0, 1]
//   f1 = 2t^3 - 3t^2 + 1,  f2 = -2t^3 + 3t^2,
//   f3 = t^3 - 2t^2 + t,   f4 = t^3 - t^2
// (U. of Toronto, *Parametric Curves*, "Hermite Curves"; Dill, *Introduction to Parametric Curves*,
// "Parametric Cubic (Hermite) Curves", Blending Functions). Dill prints the R1 blend as t^3 - 2t^2 + 1, a
// typo: it must vanish at t = 0 with slope 1 (the Toronto notes and the Hermite matrix M_h of both notes give
// t^3 - 2t^2 + t). The same cubic in Bézier form has points P1, P1 + R1/3, P4 - R4/3, P4 (Dill, "Bezier
// Curves": R1 = 3(P2 - P1), R4 = 3(P4 - P3)).
#pragma once

#include <span>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan {

/// One Hermite cubic on t in [0, 1]: start p0, end p1, and the derivatives dP/dt r0 at t = 0, r1 at t = 1.
struct HermiteSegment {
  Point p0;
  Point p1;
  Vec2 r0;
  Vec2 r1;

  /// P(t) by the blending functions above; t outside [0, 1] extrapolates, NaN gives NaN.
  [[nodiscard]] Point eval(double t) const noexcept;
  /// dP/dt.
  [[nodiscard]] Vec2 derivative(double t) const noexcept;
  /// The identical cubic as a Bézier: p0, p0 + r0/3, p1 - r1/3, p1.
  [[nodiscard]] Bezier to_bezier() const noexcept;
};

/// Piecewise Hermite through `points` with derivative `tangents[i]` at each point, the parameter running
/// 0, 1, 2, ... (unit intervals): one cubic Bézier per consecutive pair, C1 by construction.
/// Fails on fewer than two points, a tangent count != point count, or a non-finite point or tangent.
[[nodiscard]] Result<std::vector<Bezier>> hermite_spline(std::span<const Point> points,
                                                         std::span<const Vec2> tangents);

/// As above with point i at parameter parameters[i] (strictly increasing, finite) and tangents[i] the
/// derivative with respect to that parameter. Segment i covers [t_i, t_{i+1}]; in its local parameter
/// s = (t - t_i)/h, h = t_{i+1} - t_i, the end derivatives are h · tangents, so its Bézier points are
/// P_i, P_i + h R_i / 3, P_{i+1} - h R_{i+1} / 3, P_{i+1}.
[[nodiscard]] Result<std::vector<Bezier>> hermite_spline(std::span<const Point> points,
                                                         std::span<const Vec2> tangents,
                                                         std::span<const double> parameters);

}  // namespace curvescan
