// BSpline: a polynomial B-spline curve of degree p >= 0 with n control points and n + p + 1 knots.
//
//   C(u) = sum_{i=0..n-1} N_{i,p}(u) P_i,   u in [u_p, u_n]                    (Umetani, *Parametric Curve*, §3 eq. 5)
//
// The basis N_{i,p} is Cox–de Boor's recursion (Umetani, *Parametric Curve*, eq. 6–7, Ince, *Curves*, "The Basis Function"):
//
//   N_{i,0}(u) = 1 if u_i <= u < u_{i+1}, else 0
//   N_{i,p}(u) = (u - u_i)/(u_{i+p} - u_i) N_{i,p-1}(u) + (u_{i+p+1} - u)/(u_{i+p+1} - u_{i+1})
//   N_{i+1,p-1}(u)
//
// with 0/0 := 0 for repeated knots. Conventions, shared by every function here so that the reference sum
// and de Boor's algorithm agree everywhere:
//  - Half-open spans: u in [u_k, u_{k+1}) belongs to span k (Ince, *Curves*, uses t_i <= t < t_{i+1}; Umetani, *Parametric Curve*
//    eq. 6 writes the open interval, which would leave every knot uncovered).
//  - Right end: at u = u_n (the domain end) the last non-empty span k <= n-1 is used, so a clamped curve
//    ends exactly at its last control point instead of falling to zero.
//  - Outside the domain the first or last non-empty span's polynomial is extended (as Bezier::eval
//    extrapolates outside [0, 1]); NaN in gives NaN out.
//
// Evaluation is de Boor's algorithm (repeated linear interpolation, the B-spline analogue of de Casteljau).
// The derivative is again a B-spline, of degree p-1 with control points p (P_{i+1} - P_i)/(u_{i+p+1} -
// u_{i+1}) on the knots u_1 .. u_{m-1} (The NURBS Book, Piegl & Tiller, eq. 3.8). Knot insertion is Boehm's
// algorithm (Umetani, *Parametric Curve*, §3.3, eq. 8–9, with the standard indices, see insert_knot). A BSpline is built only
// through its factories, which validate; every method on a built BSpline is noexcept and total.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan {

/// The knot span k used for parameter u on the knot vector `knots` of a degree-`degree` spline: the
/// k in [p, n-1] with u_k <= u < u_{k+1}, under the right-end and outside-domain conventions above (always
/// a non-empty span). Requires a valid knot vector (validate_knots); returns 0 for a malformed one.
[[nodiscard]] std::size_t find_knot_span(std::span<const double> knots, int degree, double u) noexcept;

/// N_{i,p}(u) by the plain Cox–de Boor recursion (Umetani, *Parametric Curve*, eq. 6–7), computed bottom-up in a triangle of
/// at most p + 1 entries (no recursion). On the domain [u_p, u_n] the degree-0 functions follow the span
/// conventions above, so the bases sum to one there and de Boor's algorithm agrees with them (this is its
/// reference). Outside the domain this is still the textbook N_{i,p} (eq. 6 with half-open spans on
/// [u_0, u_m], zero beyond) — not the extrapolated end polynomial that BSpline::eval uses there.
/// NaN for a malformed knot vector (knots.size() < p + 2) or NaN u; 0 for i outside [0, n-1].
[[nodiscard]] double bspline_basis(std::span<const double> knots, int degree, std::size_t i,
                                   double u) noexcept;

class BSpline {
 public:
  /// A B-spline from control points, knots and degree. Fails (with a sentence naming the problem) on a
  /// non-finite control point or any knot vector that validate_knots rejects.
  [[nodiscard]] static Result<BSpline> create(std::vector<Point> points, std::vector<double> knots,
                                              int degree);
  /// A clamped (open uniform) B-spline on [0, 1] that starts at points.front() and ends at points.back().
  [[nodiscard]] static Result<BSpline> clamped(std::vector<Point> points, int degree);
  /// A uniform B-spline, knots u_i = i, domain [p, n].
  [[nodiscard]] static Result<BSpline> uniform(std::vector<Point> points, int degree);
  /// A closed (periodic) B-spline of degree >= 1 around the distinct control points `points` (do not repeat
  /// the first at the end): the first `degree` points are wrapped to the end and the knots are uniform
  /// (periodic_knots), so C(u_p) == C(u_n) and the curve is C^{p-1} at the seam (Gallivan, *Parametric Curves*).
  [[nodiscard]] static Result<BSpline> closed(std::vector<Point> points, int degree);

  [[nodiscard]] int degree() const noexcept { return degree_; }
  [[nodiscard]] std::span<const Point> points() const noexcept { return points_; }
  [[nodiscard]] std::span<const double> knots() const noexcept { return knots_; }
  /// The parameter domain [u_p, u_n].
  [[nodiscard]] double domain_start() const noexcept;
  [[nodiscard]] double domain_end() const noexcept;

  /// find_knot_span on this curve's knots.
  [[nodiscard]] std::size_t find_span(double u) const noexcept;
  /// N_{i,p}(u) on this curve's knots and degree (bspline_basis).
  [[nodiscard]] double basis(std::size_t i, double u) const noexcept;

  /// C(u) by de Boor's algorithm. Outside the domain the end span's polynomial is extended.
  [[nodiscard]] Point eval(double u) const noexcept;
  /// C(u) as the sum of Cox–de Boor bases times control points: the plain, slow reference for eval().
  [[nodiscard]] Point eval_reference(double u) const noexcept;

  /// C'(u) as a B-spline of degree p - 1 on the same domain; its "points" are derivative vectors stored as
  /// Points (read them with to_vec()). A coefficient over an empty support (u_{i+p+1} == u_{i+1}) is zero.
  /// The derivative of a degree-0 spline is the zero spline of degree 0.
  [[nodiscard]] BSpline derivative() const noexcept;

  /// The same curve with the knot `u` inserted once, by Boehm's algorithm (Umetani, *Parametric Curve*, eq. 8–9). The notes'
  /// eq. 8 reads q_i = (1-a_i) p_i + a_i p_{i+1}, an index slip: with a_i = (u - u_i)/(u_{i+p} - u_i) the
  /// standard rule (Boehm 1980; The NURBS Book eq. 5.15) for u in span k is
  ///   Q_i = P_i                              for i <= k - p
  ///   Q_i = (1 - a_i) P_{i-1} + a_i P_i      for k - p + 1 <= i <= k
  ///   Q_i = P_{i-1}                          for i >= k + 1.
  /// Returns the curve unchanged when u is outside the domain [u_p, u_n] or NaN, or when u already has
  /// multiplicity p + 1 (inserting it would give an invalid knot vector).
  [[nodiscard]] BSpline insert_knot(double u) const noexcept;

  /// The exact piecewise-Bézier form: one Bezier of degree p per non-empty span of the domain, in order;
  /// segment j reproduces C on [u_k, u_{k+1}] reparameterized to [0, 1]. Built by inserting every knot
  /// of the domain (ends included, which clamps an unclamped curve) up to multiplicity p; the segment's
  /// control points are then P_{k-p} .. P_k. The insertions run on a sliding window of the refined curve,
  /// so the cost is O(n p^2) in time and O(n p) in memory.
  [[nodiscard]] std::vector<Bezier> to_beziers() const noexcept;
  /// The same segments, bit for bit, by the plain algorithm: insert_knot on the whole curve for every
  /// inserted knot, O(n^2 p) — the slow reference for to_beziers().
  [[nodiscard]] std::vector<Bezier> to_beziers_reference() const noexcept;
  /// The knot values bounding the segments of to_beziers(): size to_beziers().size() + 1.
  [[nodiscard]] std::vector<double> bezier_breakpoints() const noexcept;

 private:
  BSpline(std::vector<Point> points, std::vector<double> knots, int degree)
      : points_(std::move(points)), knots_(std::move(knots)), degree_(degree) {}

  std::vector<Point> points_;
  std::vector<double> knots_;
  int degree_ = 0;
};

}  // namespace curvescan
