// Roots of a polynomial in Bernstein form on [0, 1] (bernstein_roots.h).
#include "bernstein_roots.h"

#include <cmath>
#include <cstddef>
#include <utility>

#include "bezier_p.h"

namespace curvescan::detail {
namespace {

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
    for (std::size_t i = 0; i < level; ++i) scratch[i] = lerp(scratch[i], scratch[i + 1], u);
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
    de_casteljau_split<double>(work, 0.5, left, right);
    stack.push_back({t_mid, piece.t1, piece.depth + 1, std::move(right)});
    stack.push_back({piece.t0, t_mid, piece.depth + 1, std::move(left)});
  }
}

}  // namespace

void bernstein_roots(std::span<const double> coeffs, std::vector<double>& roots) {
  switch (coeffs.size()) {
    case 0:
    case 1:  // a constant
      return;
    case 2: {  // degree 1: c0 (1-t) + c1 t = 0
      const double denominator = coeffs[0] - coeffs[1];
      if (denominator != 0.0) roots.push_back(coeffs[0] / denominator);
      return;
    }
    case 3:  // degree 2
      quadratic_bernstein_roots(coeffs[0], coeffs[1], coeffs[2], roots);
      return;
    default:
      subdivision_bernstein_roots(coeffs, roots);
  }
}

}  // namespace curvescan::detail
