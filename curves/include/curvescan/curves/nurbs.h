// Nurbs: a non-uniform rational B-spline of degree p with positive weights.
//
//   C(u) = sum N_{i,p}(u) w_i P_i / sum N_{i,p}(u) w_i                (Umetani, *Parametric Curve*, §4 eq. 10, Ince, *Curves*, "NURBS
//   Curves")
//
// Held in homogeneous coordinates (Umetani, *Parametric Curve*, §4.1): the polynomial B-spline of the points (w_i x_i, w_i y_i)
// and the scalar B-spline of the weights w_i, on the same knots. Every linear operation (de Boor, Boehm
// insertion, Bézier decomposition) acts on both alike and the point is projected (x/w, y/w) at the end, so
// the rational curve inherits the B-spline conventions of bspline.h (half-open spans, right end, domain
// [u_p, u_n], extension outside the domain, NaN in gives NaN out).
#pragma once

#include <span>
#include <vector>

#include "curvescan/curves/bspline.h"
#include "curvescan/curves/point.h"
#include "curvescan/curves/rational_bezier.h"
#include "curvescan/status.h"

namespace curvescan {

class Nurbs {
 public:
  /// A NURBS from control points, one weight per point, knots and degree. Fails on a point/weight count
  /// mismatch, a weight that is not finite or not > 0, a non-finite point, a product w_i P_i that
  /// overflows, or any knot vector validate_knots rejects.
  [[nodiscard]] static Result<Nurbs> create(std::vector<Point> points, std::vector<double> weights,
                                            std::vector<double> knots, int degree);
  /// The full circle of `radius` around `center` as the classic 9-point quadratic NURBS: the corners and
  /// edge midpoints of the bounding square, weights 1, √2/2, 1, √2/2, ..., 1 and knots
  /// {0,0,0,¼,¼,½,½,¾,¾,1,1,1} (Umetani, *Parametric Curve*, §4.1; The NURBS Book §7.5). C(0) = C(1) = center + (radius, 0),
  /// C(¼) = center + (0, radius): counter-clockwise with y up, clockwise on a y-down screen. Each quarter is
  /// exactly the rational quadratic of a 90° arc. Fails on a non-finite center or a radius that is negative
  /// or not finite (radius 0 gives the center point).
  [[nodiscard]] static Result<Nurbs> circle(Point center, double radius);

  [[nodiscard]] int degree() const noexcept { return weighted_.degree(); }
  [[nodiscard]] std::span<const double> knots() const noexcept { return weighted_.knots(); }
  /// The control points P_i (projected back from homogeneous form).
  [[nodiscard]] std::vector<Point> points() const noexcept;
  [[nodiscard]] std::vector<double> weights() const noexcept;
  [[nodiscard]] double domain_start() const noexcept { return weighted_.domain_start(); }
  [[nodiscard]] double domain_end() const noexcept { return weighted_.domain_end(); }

  /// C(u): de Boor on the homogeneous points, then projection.
  [[nodiscard]] Point eval(double u) const noexcept;
  /// The same curve with knot u inserted once (Boehm on homogeneous points; BSpline::insert_knot rules).
  [[nodiscard]] Nurbs insert_knot(double u) const noexcept;
  /// The exact piecewise rational Bézier form, one segment of degree p per non-empty span of the domain,
  /// segment j covering [bezier_breakpoints()[j], bezier_breakpoints()[j+1]]. Weights stay positive
  /// (insertion takes convex combinations of positive weights).
  [[nodiscard]] std::vector<RationalBezier> to_rational_beziers() const noexcept;
  [[nodiscard]] std::vector<double> bezier_breakpoints() const noexcept {
    return weighted_.bezier_breakpoints();
  }

 private:
  Nurbs(BSpline weighted, BSpline weight) : weighted_(std::move(weighted)), weight_(std::move(weight)) {}

  BSpline weighted_;  ///< control points (w_i x_i, w_i y_i)
  BSpline weight_;    ///< control "points" (w_i, 0): the denominator as a scalar B-spline
};

}  // namespace curvescan
