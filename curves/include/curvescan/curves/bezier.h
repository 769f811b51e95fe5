// Bezier: a polynomial Bézier curve of any degree n >= 1 on t in [0, 1].
//
//   B(t) = sum_{i=0..n} C(n,i) t^i (1-t)^(n-i) P_i      (Ince, *Curves*, "Bernstein Polynomials";
//                                                         Gallivan, *Parametric Curves*, "Bezier Curves")
// evaluated by de Casteljau's repeated linear interpolation (Gallivan, *Parametric Curves*, "DeCasteljau's
// Algorithm"; Umetani, *Parametric Curve*, section 2.1), which is numerically stable and is also the split.
// The Bernstein sum itself (bernstein, eval_bernstein) stays beside it as the plain reference the tests hold
// de Casteljau to.
//
// The vocabulary follows kurbo: eval, split / subsegment, deriv. Functions that return a new curve
// allocate (and may throw std::bad_alloc); every other function is noexcept. Degenerate input is total:
// an empty curve evaluates to NaN, NaN control points give NaN results, t outside [0, 1] extrapolates.
#pragma once

#include <span>
#include <utility>
#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/curves/rect.h"

namespace curvescan {

/// de Casteljau evaluation of the Bézier curve with control points `ctrl` at `t`.
/// Total: an empty span gives NaN, one point gives that point; t outside [0, 1] extrapolates.
[[nodiscard]] Point de_casteljau(std::span<const Point> ctrl, double t) noexcept;

/// The Bernstein basis polynomial B_{n,i}(t) = C(n,i) t^i (1-t)^(n-i) (Dill, *Introduction to Parametric
/// Curves*, "Bezier Curves", the blending functions of degree n). Zero when i < 0, i > n or n < 0; NaN t
/// gives NaN. On [0, 1] the B_{n,i} are non-negative and sum to one (Dill, *Introduction to Parametric
/// Curves*; U. of Toronto, *Parametric Curves*, "Convex hull property").
[[nodiscard]] double bernstein(int n, int i, double t) noexcept;

/// The Bézier curve evaluated as the Bernstein sum sum_i B_{n,i}(t) P_i, the reference for de Casteljau.
/// Less robust than de Casteljau far outside [0, 1] (large powers); empty `ctrl` gives NaN.
[[nodiscard]] Point eval_bernstein(std::span<const Point> ctrl, double t) noexcept;

class Bezier {
 public:
  Bezier() = default;
  /// A curve through `points`: degree = points.size() - 1. Fewer than two points is a degenerate
  /// (empty or single-point) curve that evaluates to NaN or the point; builders validate before this.
  explicit Bezier(std::vector<Point> points) : points_(std::move(points)) {}

  [[nodiscard]] int degree() const noexcept { return static_cast<int>(points_.size()) - 1; }
  [[nodiscard]] std::span<const Point> points() const noexcept { return points_; }
  [[nodiscard]] Point start() const noexcept { return points_.front(); }
  [[nodiscard]] Point end() const noexcept { return points_.back(); }

  /// The point at parameter t by de Casteljau.
  [[nodiscard]] Point eval(double t) const noexcept { return de_casteljau(points_, t); }

  /// The hodograph B'(t): the degree n-1 Bézier with control points n·(P_{i+1} - P_i) (Dill, *Introduction to
  /// Parametric Curves*, "Joining Bezier Curves" derives P'(1) = 3(P3 - P2) for the cubic). Its "points" are
  /// velocity vectors stored as Points (vector from the origin); eval() on it gives the derivative. A single
  /// point gives the zero curve {(0, 0)}, an empty curve stays empty.
  [[nodiscard]] Bezier deriv() const;

  /// The curve cut at t into the pieces on [0, t] and [t, 1], each reparametrized to [0, 1], by de
  /// Casteljau's triangle. first.end() and second.start() are both exactly eval(t).
  [[nodiscard]] std::pair<Bezier, Bezier> split(double t) const;

  /// The piece on [t0, t1] reparametrized to [0, 1] (t0 > t1 gives it reversed), by blossoming; its
  /// endpoints are exactly eval(t0) and eval(t1).
  [[nodiscard]] Bezier subsegment(double t0, double t1) const;

  /// The same curve as one of degree n + 1 (Dill, *Introduction to Parametric Curves*, "Degree Raising"):
  /// Q_0 = P_0, Q_i = (i P_{i-1} + (n + 1 - i) P_i) / (n + 1), Q_{n+1} = P_n.
  [[nodiscard]] Bezier elevate() const;

  /// The same curve traversed backwards: control points in reverse order, eval(t) == reversed().eval(1-t).
  [[nodiscard]] Bezier reversed() const;

  /// The tight axis-aligned bounding box of the curve for t in [0, 1]: the endpoints plus the curve points
  /// where a coordinate of B' vanishes. Exact roots for degree <= 3 (the derivative is at most quadratic:
  /// a stable quadratic formula); for higher degree the roots are isolated by Bernstein subdivision with a
  /// bounded depth and interval count, then refined by bisection (roots to ~1e-15 in t). NaN box if any
  /// control point is NaN; an empty curve gives a NaN box.
  [[nodiscard]] Rect bounding_box() const noexcept;

  /// The length of the curve for t in [0, 1] to within about `accuracy` (absolute, in the curve's units),
  /// by adaptive 8-point Gauss–Legendre quadrature of |B'(t)| (kurbo's arclen does the same). Work is
  /// bounded: at most 2^14 interval halvings, after which the best estimate so far is returned.
  /// accuracy <= 0 or NaN asks for the best within that bound. Fewer than two points gives 0 (one point)
  /// or NaN (none).
  [[nodiscard]] double arc_length(double accuracy) const noexcept;

  bool operator==(const Bezier&) const = default;

 private:
  std::vector<Point> points_;
};

}  // namespace curvescan
