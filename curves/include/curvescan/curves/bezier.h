// Bezier: a polynomial Bézier curve of any degree n >= 1 on t in [0, 1].
//
//   B(t) = sum_{i=0..n} C(n,i) t^i (1-t)^(n-i) P_i           (seed 001, "Bernstein Polynomials";
//                                                              seed 003, "Bezier Curves")
// evaluated by de Casteljau's repeated linear interpolation (seed 003, "DeCasteljau's Algorithm";
// seed 000 section 2.1), which is numerically stable and is also the split.
#pragma once

#include <span>
#include <vector>

#include "curvescan/curves/point.h"

namespace curvescan {

/// de Casteljau evaluation of the Bézier curve with control points `ctrl` at `t`.
/// Total: an empty span gives NaN, one point gives that point; t outside [0, 1] extrapolates.
[[nodiscard]] Point de_casteljau(std::span<const Point> ctrl, double t) noexcept;

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

  bool operator==(const Bezier&) const = default;

 private:
  std::vector<Point> points_;
};

}  // namespace curvescan
