// Private machinery shared by the polynomial and rational Bézier code (bezier.cpp, rational_bezier.cpp).
//
// Three algorithms, each generic over the "point" type so that one text serves polynomial curves (Point)
// and rational curves in homogeneous coordinates (Homogeneous: (w·x, w·y, w), Umetani, *Parametric Curve*, §4.1):
//
// * de Casteljau's triangle (Gallivan, *Parametric Curves*, "DeCasteljau's Algorithm"; Umetani, *Parametric Curve*, §2.1). Its left edge is the
//   control polygon of the curve on [0, t], its right edge the one on [t, 1], which is the split.
// * The blossom (polar form). For a degree-n curve, the point obtained by running de Casteljau with a
//   different parameter u_r at each level r is the blossom b(u_1, ..., u_n); it is symmetric in its
//   arguments, and the control points of the curve restricted to [t0, t1] are b(t0^(n-i), t1^i), i = 0..n
//   (Ramshaw, "Blossoms are polar forms", 1989). This gives subsegment() without dividing by t1 - t0, and
//   the first and last control points come out bit for bit equal to eval(t0) and eval(t1).
// * Adaptive Gauss–Legendre quadrature for arc length: the 8-point rule on an interval is compared with
//   the rule on its two halves; |whole − halves| estimates the error of the coarse value, and intervals
//   whose estimate exceeds their share of the requested accuracy are split again. An explicit stack and a
//   fixed budget of interval evaluations bound the work (plutovg's flattener keeps an explicit stack with a
//   depth cap for the same reason).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

#include "curvescan/curves/point.h"

namespace curvescan::detail {

/// A point of a rational curve lifted to homogeneous coordinates (w·x, w·y, w).
struct Homogeneous {
  double wx = 0.0, wy = 0.0, w = 0.0;

  [[nodiscard]] static constexpr Homogeneous lift(Point p, double weight) noexcept {
    return {p.x * weight, p.y * weight, weight};
  }
  /// The projection (wx/w, wy/w): non-finite when w is zero.
  [[nodiscard]] constexpr Point project() const noexcept { return {wx / w, wy / w}; }
};

[[nodiscard]] constexpr Homogeneous lerp(Homogeneous a, Homogeneous b, double t) noexcept {
  return {a.wx + (b.wx - a.wx) * t, a.wy + (b.wy - a.wy) * t, a.w + (b.w - a.w) * t};
}
[[nodiscard]] constexpr double lerp(double a, double b, double t) noexcept {
  return a + (b - a) * t;
}
using curvescan::lerp;

/// Runs de Casteljau's triangle on `points` (overwritten) at t, writing the left edge (control points on
/// [0, t]) to `left` and the right edge (on [t, 1]) to `right`; both have points.size() entries and share
/// their meeting point bit for bit.
template <class T>
void de_casteljau_split(std::span<T> points, double t, std::span<T> left, std::span<T> right) noexcept {
  const std::size_t n = points.size() - 1;
  left[0] = points[0];
  right[n] = points[n];
  for (std::size_t level = 1; level <= n; ++level) {
    for (std::size_t i = 0; i + level <= n; ++i) points[i] = lerp(points[i], points[i + 1], t);
    left[level] = points[0];
    right[n - level] = points[n - level];
  }
}

/// The control points of the curve `ctrl` restricted to [t0, t1] (t0 > t1 gives the reversed piece), by
/// the blossom b(t0^(n-i), t1^i). O(n³) work, which is nothing for the degrees drawn in practice.
template <class T>
std::vector<T> blossom_subsegment(std::span<const T> ctrl, double t0, double t1) {
  const std::size_t n = ctrl.size() - 1;
  std::vector<T> out(ctrl.size());
  std::vector<T> scratch(ctrl.size());
  for (std::size_t i = 0; i <= n; ++i) {
    std::copy(ctrl.begin(), ctrl.end(), scratch.begin());
    for (std::size_t level = 1; level <= n; ++level) {
      // t0 for the first n - i levels and t1 for the rest: at i = 0 this is de Casteljau at t0 exactly.
      const double u = level <= n - i ? t0 : t1;
      for (std::size_t j = 0; j + level <= n; ++j) scratch[j] = lerp(scratch[j], scratch[j + 1], u);
    }
    out[i] = scratch[0];
  }
  return out;
}

/// 8-point Gauss–Legendre rule on [-1, 1]: the positive nodes and their weights (the rule is symmetric).
/// Computed by Newton's method on the Legendre recurrence to 20 digits; the unit test checks that the rule
/// integrates every monomial up to degree 15 exactly.
inline constexpr std::array<double, 4> kGaussLegendre8Nodes{0.18343464249564980784, 0.52553240991632899082,
                                                            0.79666647741362672797, 0.96028985649753628717};
inline constexpr std::array<double, 4> kGaussLegendre8Weights{0.36268378337836199021, 0.31370664587788726907,
                                                              0.22238103445337448205, 0.10122853629037625867};

/// The 8-point Gauss–Legendre estimate of the integral of f over [a, b].
template <class F>
double gauss_legendre8(const F& f, double a, double b) noexcept {
  const double half = 0.5 * (b - a);
  const double mid = 0.5 * (a + b);
  double sum = 0.0;
  for (std::size_t k = 0; k < kGaussLegendre8Nodes.size(); ++k) {
    const double dx = half * kGaussLegendre8Nodes[k];
    sum += kGaussLegendre8Weights[k] * (f(mid - dx) + f(mid + dx));
  }
  return sum * half;
}

/// Most interval evaluations one adaptive integral may spend (each is 16 integrand calls, two halves of 8).
/// 2^14 intervals resolve even a cusp (where |B'| has a kink) to ~1e-12 of the length; beyond it the best
/// estimate so far is returned.
inline constexpr int kMaxQuadratureIntervals = 1 << 14;

/// The integral of f over [0, 1] to about `accuracy` absolute, by adaptive Gauss–Legendre (see top).
/// accuracy <= 0 or NaN asks for the best the work budget allows.
template <class F>
double integrate_adaptive(const F& f, double accuracy) noexcept {
  struct Interval {
    double a, b, tolerance, estimate;
  };
  const double requested = accuracy > 0.0 ? accuracy : 0.0;
  // Start from four pieces so that a symmetric integrand cannot fool the first comparison.
  constexpr int kInitialPieces = 4;
  std::array<Interval, 64> stack{};  // depth-first: at most one pending sibling per level, 64 levels
  std::size_t top = 0;
  for (int k = kInitialPieces - 1; k >= 0; --k) {
    const double a = k / double{kInitialPieces}, b = (k + 1) / double{kInitialPieces};
    stack[top++] = {a, b, requested / kInitialPieces, gauss_legendre8(f, a, b)};
  }
  double total = 0.0;
  int budget = kMaxQuadratureIntervals;
  while (top > 0) {
    const Interval iv = stack[--top];
    const double mid = 0.5 * (iv.a + iv.b);
    const double left = gauss_legendre8(f, iv.a, mid);
    const double right = gauss_legendre8(f, mid, iv.b);
    --budget;
    const double error = std::abs(left + right - iv.estimate);
    // Accept when within tolerance, out of budget, out of stack, or the interval can no longer be halved.
    if (!(error > iv.tolerance) || budget <= 0 || top + 2 > stack.size() || mid <= iv.a || mid >= iv.b) {
      total += left + right;
      continue;
    }
    stack[top++] = {mid, iv.b, 0.5 * iv.tolerance, right};
    stack[top++] = {iv.a, mid, 0.5 * iv.tolerance, left};
  }
  return total;
}

}  // namespace curvescan::detail
