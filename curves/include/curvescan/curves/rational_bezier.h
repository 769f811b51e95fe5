// RationalBezier: a rational Bézier curve of degree n >= 1 with positive weights.
//
//   R(t) = sum w_i P_i B_i(t) / sum w_i B_i(t)
//
// evaluated in homogeneous coordinates (w·x, w·y, w) by de Casteljau and projected (seed 000 section 4.1,
// seed 004 "NURBS"). Degree 2 with weights (1, w, 1) is a conic: an ellipse arc for w < 1, a parabola for
// w = 1, a hyperbola for w > 1.
#pragma once

#include <span>
#include <vector>

#include "curvescan/curves/point.h"

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

  [[nodiscard]] int degree() const noexcept { return static_cast<int>(points_.size()) - 1; }
  [[nodiscard]] std::span<const Point> points() const noexcept { return points_; }
  [[nodiscard]] std::span<const double> weights() const noexcept { return weights_; }

  [[nodiscard]] Point eval(double t) const noexcept { return rational_de_casteljau(points_, weights_, t); }

  bool operator==(const RationalBezier&) const = default;

 private:
  std::vector<Point> points_;
  std::vector<double> weights_;
};

}  // namespace curvescan
