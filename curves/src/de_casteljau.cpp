// de Casteljau evaluation, polynomial and rational (Gallivan, *Parametric Curves*, "DeCasteljau's Algorithm", Umetani, *Parametric Curve*, §2.1).
#include <cmath>
#include <limits>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/rational_bezier.h"

namespace curvescan {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Curves up to this degree are evaluated on the stack; higher degrees (rare) use the heap.
constexpr std::size_t kStackPoints = 16;

struct Homogeneous {
  double wx, wy, w;
};

template <class T, class Lerp>
T reduce(std::span<T> scratch, double t, Lerp lerp_fn) {
  for (std::size_t level = scratch.size() - 1; level > 0; --level) {
    for (std::size_t i = 0; i < level; ++i) scratch[i] = lerp_fn(scratch[i], scratch[i + 1], t);
  }
  return scratch[0];
}

}  // namespace

Point de_casteljau(std::span<const Point> ctrl, double t) noexcept {
  if (ctrl.empty()) return {kNaN, kNaN};
  auto run = [&](std::span<Point> scratch) {
    std::copy(ctrl.begin(), ctrl.end(), scratch.begin());
    return reduce(scratch, t, [](Point a, Point b, double u) { return lerp(a, b, u); });
  };
  if (ctrl.size() <= kStackPoints) {
    Point buffer[kStackPoints];
    return run(std::span<Point>(buffer, ctrl.size()));
  }
  std::vector<Point> buffer(ctrl.size());
  return run(buffer);
}

Point rational_de_casteljau(std::span<const Point> ctrl, std::span<const double> weights, double t) noexcept {
  if (ctrl.empty() || ctrl.size() != weights.size()) return {kNaN, kNaN};
  auto run = [&](std::span<Homogeneous> scratch) {
    for (std::size_t i = 0; i < ctrl.size(); ++i) {
      scratch[i] = {ctrl[i].x * weights[i], ctrl[i].y * weights[i], weights[i]};
    }
    const Homogeneous h = reduce(scratch, t, [](Homogeneous a, Homogeneous b, double u) {
      return Homogeneous{a.wx + (b.wx - a.wx) * u, a.wy + (b.wy - a.wy) * u, a.w + (b.w - a.w) * u};
    });
    return Point{h.wx / h.w, h.wy / h.w};
  };
  if (ctrl.size() <= kStackPoints) {
    Homogeneous buffer[kStackPoints];
    return run(std::span<Homogeneous>(buffer, ctrl.size()));
  }
  std::vector<Homogeneous> buffer(ctrl.size());
  return run(buffer);
}

// The Bernstein form, kept as the plain reference for de Casteljau (Dill, *Introduction to Parametric Curves*, "Bezier Curves": X(t) =
// sum P_i C(n,i) t^i (1-t)^(n-i)). The binomial coefficient is built multiplicatively in double, exact
// for every degree where C(n,i) < 2^53 (n <= 56), and correctly rounded-ish far beyond.
double bernstein(int n, int i, double t) noexcept {
  if (n < 0 || i < 0 || i > n) return 0.0;
  if (std::isnan(t)) return t;  // pow(NaN, 0) is 1, which would hide the NaN for i == 0 or i == n
  double binomial = 1.0;
  for (int k = 1; k <= i; ++k) binomial = binomial * (n - i + k) / k;
  return binomial * std::pow(t, i) * std::pow(1.0 - t, n - i);
}

Point eval_bernstein(std::span<const Point> ctrl, double t) noexcept {
  if (ctrl.empty()) return {kNaN, kNaN};
  const int n = static_cast<int>(ctrl.size()) - 1;
  Vec2 sum{0.0, 0.0};
  for (int i = 0; i <= n; ++i) sum += ctrl[static_cast<std::size_t>(i)].to_vec() * bernstein(n, i, t);
  return Point::from_vec(sum);
}

}  // namespace curvescan
