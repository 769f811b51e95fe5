// Bezier: hodograph, split, subsegment, degree elevation, reversal, tight bounds and arc length (bezier.h).
#include "curvescan/curves/bezier.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "bezier_p.h"

namespace curvescan {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// --- Roots of a derivative coordinate --------------------------------------------------------------------
//
// A coordinate of B' is a polynomial of degree m = n - 1 with Bernstein coefficients c_i = n (P_{i+1} -
// P_i) along that axis (the scale n does not move roots, so it is left out). For m <= 2 the roots come from
// the power form by the quadratic formula; above that they are isolated by subdivision.

// Roots in [0, 1] of c0 (1-t)² + 2 c1 t (1-t) + c2 t², i.e. a t² + b t + c with a = c0 - 2c1 + c2,
// b = 2(c1 - c0), c = c0. The form q = -(b + sign(b)·sqrt(disc))/2, roots c/q and q/a avoids the
// cancellation of the textbook formula (Numerical Recipes §5.6); a rounding-sized a only produces a huge
// q/a root, which the [0, 1] filter drops, while c/q stays accurate.
void quadratic_bernstein_roots(double c0, double c1, double c2, std::vector<double>& roots) {
  const double a = c0 - 2.0 * c1 + c2;
  const double b = 2.0 * (c1 - c0);
  const double c = c0;
  if (a == 0.0) {
    if (b != 0.0) roots.push_back(-c / b);
    return;
  }
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0) return;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) {  // b == 0 and disc == 0, so c == 0: the double root t = 0
    roots.push_back(0.0);
    return;
  }
  roots.push_back(c / q);
  roots.push_back(q / a);
}

double eval_scalar_bernstein(std::span<const double> coeffs, double u, std::vector<double>& scratch) {
  scratch.assign(coeffs.begin(), coeffs.end());
  for (std::size_t level = scratch.size() - 1; level > 0; --level) {
    for (std::size_t i = 0; i < level; ++i) scratch[i] = detail::lerp(scratch[i], scratch[i + 1], u);
  }
  return scratch[0];
}

int sign_changes(std::span<const double> coeffs) {
  int changes = 0;
  double previous = 0.0;
  for (double c : coeffs) {
    if (c == 0.0) continue;
    if (previous != 0.0 && (c > 0.0) != (previous > 0.0)) ++changes;
    previous = c;
  }
  return changes;
}

// Deepest subdivision: intervals of 2^-48 ≈ 3.6e-15 in t, below which a multiple root cluster is reported
// by its midpoint (the bounding box only needs a curve point where the coordinate is extreme, and moving
// t by 4e-15 moves the point by less than rounding).
constexpr int kMaxRootDepth = 48;
// Most intervals examined per coordinate: m roots need O(m · depth) intervals, far below this.
constexpr int kMaxRootIntervals = 4096;
// Bisection halves the bracket to the last bit of a double long before 64 steps.
constexpr int kBisectionSteps = 64;

// Roots in [0, 1] of the Bernstein polynomial `coeffs` (degree >= 1). By the variation-diminishing property
// of the Bernstein basis, a polynomial has at most as many roots in an interval as its coefficients there
// have sign changes: none means no root, one with non-zero end values means exactly one (then bisection);
// otherwise the interval is halved by de Casteljau and both halves are examined. Explicit stack, bounded.
void subdivision_bernstein_roots(std::span<const double> coeffs, std::vector<double>& roots) {
  struct Piece {
    double t0, t1;
    int depth;
    std::vector<double> coeffs;
  };
  std::vector<Piece> stack;
  stack.push_back({0.0, 1.0, 0, std::vector<double>(coeffs.begin(), coeffs.end())});
  std::vector<double> scratch;
  int examined = 0;
  while (!stack.empty()) {
    Piece piece = std::move(stack.back());
    stack.pop_back();
    ++examined;
    const std::vector<double>& c = piece.coeffs;
    if (c.front() == 0.0) roots.push_back(piece.t0);
    const int changes = sign_changes(c);
    if (changes == 0) continue;
    if (changes == 1 && c.front() != 0.0 && c.back() != 0.0) {
      const bool low_is_positive = c.front() > 0.0;
      double lo = 0.0, hi = 1.0;
      for (int step = 0; step < kBisectionSteps; ++step) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        const double value = eval_scalar_bernstein(c, mid, scratch);
        if (value == 0.0) {
          lo = hi = mid;
          break;
        }
        ((value > 0.0) == low_is_positive ? lo : hi) = mid;
      }
      roots.push_back(piece.t0 + (piece.t1 - piece.t0) * (0.5 * (lo + hi)));
      continue;
    }
    const double t_mid = 0.5 * (piece.t0 + piece.t1);
    if (piece.depth >= kMaxRootDepth || examined + static_cast<int>(stack.size()) >= kMaxRootIntervals) {
      roots.push_back(t_mid);
      continue;
    }
    std::vector<double> work = c, left(c.size()), right(c.size());
    detail::de_casteljau_split<double>(work, 0.5, left, right);
    stack.push_back({t_mid, piece.t1, piece.depth + 1, std::move(right)});
    stack.push_back({piece.t0, t_mid, piece.depth + 1, std::move(left)});
  }
}

// Roots of one coordinate of B' (the differences d_i = P_{i+1} - P_i along that axis) in [0, 1].
void derivative_roots(std::span<const double> differences, std::vector<double>& roots) {
  switch (differences.size()) {
    case 0:
    case 1:  // a line: the derivative is constant
      return;
    case 2: {  // quadratic curve: d0 (1-t) + d1 t = 0
      const double denominator = differences[0] - differences[1];
      if (denominator != 0.0) roots.push_back(differences[0] / denominator);
      return;
    }
    case 3:  // cubic curve
      quadratic_bernstein_roots(differences[0], differences[1], differences[2], roots);
      return;
    default:
      subdivision_bernstein_roots(differences, roots);
  }
}

}  // namespace

Bezier Bezier::deriv() const {
  if (points_.empty()) return {};
  if (points_.size() == 1) return Bezier({Point{0.0, 0.0}});
  const double n = static_cast<double>(points_.size() - 1);
  std::vector<Point> hodograph(points_.size() - 1);
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    hodograph[i] = Point::from_vec((points_[i + 1] - points_[i]) * n);
  }
  return Bezier(std::move(hodograph));
}

std::pair<Bezier, Bezier> Bezier::split(double t) const {
  if (points_.empty()) return {};
  std::vector<Point> work = points_, left(points_.size()), right(points_.size());
  detail::de_casteljau_split<Point>(work, t, left, right);
  return {Bezier(std::move(left)), Bezier(std::move(right))};
}

Bezier Bezier::subsegment(double t0, double t1) const {
  if (points_.empty()) return {};
  return Bezier(detail::blossom_subsegment<Point>(points_, t0, t1));
}

Bezier Bezier::elevate() const {
  if (points_.empty()) return {};
  const std::size_t n = points_.size() - 1;
  const double inv = 1.0 / static_cast<double>(n + 1);
  std::vector<Point> raised(n + 2);
  raised.front() = points_.front();
  raised.back() = points_.back();
  for (std::size_t i = 1; i <= n; ++i) {
    // (i P_{i-1} + (n+1-i) P_i) / (n+1) as a lerp from P_i towards P_{i-1}: exact when P_{i-1} == P_i.
    raised[i] = lerp(points_[i], points_[i - 1], static_cast<double>(i) * inv);
  }
  return Bezier(std::move(raised));
}

Bezier Bezier::reversed() const {
  return Bezier(std::vector<Point>(points_.rbegin(), points_.rend()));
}

Rect Bezier::bounding_box() const noexcept {
  if (points_.empty()) return {kNaN, kNaN, kNaN, kNaN};
  Rect box = Rect::from_point(points_.front());
  box.include(points_.back());
  if (!box.is_finite()) return {kNaN, kNaN, kNaN, kNaN};
  for (const Point& p : points_) {
    if (!p.is_finite()) return {kNaN, kNaN, kNaN, kNaN};
  }
  std::vector<double> roots;
  std::vector<double> differences(points_.size() - 1);
  for (int axis = 0; axis < 2; ++axis) {
    for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
      const Vec2 d = points_[i + 1] - points_[i];
      differences[i] = axis == 0 ? d.x : d.y;
    }
    derivative_roots(differences, roots);
  }
  for (double t : roots) {
    if (t > 0.0 && t < 1.0) box.include(eval(t));
  }
  return box;
}

double Bezier::arc_length(double accuracy) const noexcept {
  if (points_.empty()) return kNaN;
  if (points_.size() == 1) return 0.0;
  const Bezier hodograph = deriv();
  const auto speed = [&hodograph](double t) { return hodograph.eval(t).to_vec().length(); };
  return detail::integrate_adaptive(speed, accuracy);
}

}  // namespace curvescan
