// RationalBezier: a rational Bézier curve of degree n >= 1 with positive weights.
//
//   R(t) = sum w_i P_i B_i(t) / sum w_i B_i(t)
//
// evaluated in homogeneous coordinates (w·x, w·y, w) by de Casteljau and projected (Umetani, *Parametric
// Curve*, section 4.1; U. of Toronto, *Parametric Curves*, "NURBS"). Degree 2 with weights (1, w, 1) is a
// conic: an ellipse arc for w < 1, a parabola for w = 1, a hyperbola for w > 1.
//
// Split, subsegment and reversal work on the homogeneous control points (the lifted curve is a polynomial
// Bézier in 3D; Dill, *Introduction to Parametric Curves*, "NonUniform Rational B-Splines": "curve is
// Q(t) = [X, Y, W] in homogeneous space") and project back, so each piece is again a rational Bézier of the
// same degree with positive weights (for parameters in [0, 1]). Functions that return a new curve allocate;
// the others are noexcept.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/curves/rect.h"

namespace curvescan {

/// Homogeneous de Casteljau evaluation of the rational Bézier (ctrl, weights) at t.
/// Total: mismatched or empty spans give NaN; a zero denominator gives non-finite output.
[[nodiscard]] Point rational_de_casteljau(std::span<const Point> ctrl, std::span<const double> weights,
                                          double t) noexcept;

class RationalBezier {
 public:
  RationalBezier() = default;
  /// Requires points.size() == weights.size(); builders validate positivity and finiteness before this.
  RationalBezier(std::vector<Point> points, std::vector<double> weights)
      : points_(std::move(points)), weights_(std::move(weights)) {}

  /// The conic arc from p0 to p2 whose end tangents meet at p1, with weights (1, w, 1): an ellipse arc
  /// for 0 < w < 1 (a circular arc of angle φ when w = cos(φ/2) and |p1 - p0| = |p2 - p1|), a parabola
  /// for w = 1, a hyperbola for w > 1 (Umetani, *Parametric Curve*, §4.1). Not validated: w <= 0 is the
  /// caller's to reject.
  [[nodiscard]] static RationalBezier conic(Point p0, Point p1, Point p2, double w) {
    return RationalBezier({p0, p1, p2}, {1.0, w, 1.0});
  }

  [[nodiscard]] int degree() const noexcept { return static_cast<int>(points_.size()) - 1; }
  [[nodiscard]] std::span<const Point> points() const noexcept { return points_; }
  [[nodiscard]] std::span<const double> weights() const noexcept { return weights_; }

  [[nodiscard]] Point eval(double t) const noexcept { return rational_de_casteljau(points_, weights_, t); }

  /// The derivative R'(t) by the quotient rule in homogeneous form: with H(t) = sum w_i P_i B_i(t) and
  /// W(t) = sum w_i B_i(t), R' = (H' W - H W') / W², where H' and W' come from the last-but-one level of
  /// the homogeneous de Casteljau triangle (the hodograph: n times the difference of its two points).
  /// Mismatched or empty spans give NaN; a single point gives (0, 0).
  [[nodiscard]] Vec2 deriv_at(double t) const noexcept;

  /// The curve cut at t into the pieces on [0, t] and [t, 1], each reparametrized to [0, 1]; the shared
  /// endpoint is exactly eval(t). Invalid curves (mismatched sizes, empty) give two empty curves.
  [[nodiscard]] std::pair<RationalBezier, RationalBezier> split(double t) const;

  /// The piece on [t0, t1] reparametrized to [0, 1] (t0 > t1 gives it reversed), by blossoming the
  /// homogeneous control points; its endpoints are exactly eval(t0) and eval(t1). Invalid curves give an
  /// empty curve.
  [[nodiscard]] RationalBezier subsegment(double t0, double t1) const;

  /// The tight axis-aligned box of the curve for t in [0, 1]: its ends and the points where a coordinate's
  /// derivative vanishes. By the quotient rule that happens where H'W - HW' = 0 (deriv_at's notation) for
  /// that coordinate, a polynomial of degree 2n - 1 in Bernstein form (the product of Bernstein
  /// polynomials, Farin, *Curves and Surfaces for CAGD*, "products"), whose roots are found as
  /// Bezier::bounding_box finds its hodograph's. An ellipse arc that is no quarter of its ellipse's axes
  /// reaches less far than its control point: the control-point box can be far larger. All-NaN when the
  /// curve is invalid or not finite; the control-point box on an axis whose coefficients overflow.
  [[nodiscard]] Rect bounding_box() const noexcept;

  /// The same curve traversed backwards: points and weights reversed, eval(t) == reversed().eval(1-t).
  [[nodiscard]] RationalBezier reversed() const;

  /// The length for t in [0, 1] to about `accuracy` (absolute), by adaptive Gauss–Legendre quadrature of
  /// |R'(t)|, with the same bounded work and conventions as Bezier::arc_length.
  [[nodiscard]] double arc_length(double accuracy) const noexcept;

  bool operator==(const RationalBezier&) const = default;

 private:
  [[nodiscard]] bool is_well_formed() const noexcept {
    return !points_.empty() && points_.size() == weights_.size();
  }

  std::vector<Point> points_;
  std::vector<double> weights_;
};

}  // namespace curvescan
