// Interpolating quadratics and cubics, and power form to Bézier (interpolate_points.h; Ince, *Curves*
// "Representations of Curves: Parametric Representation").
#include "curvescan/curves/interpolate_points.h"

#include <cmath>
#include <cstddef>
#include <vector>

namespace curvescan {

Bezier QuadraticPowerForm::to_bezier() const {
  const std::array<Vec2, 3> coefficients{c.to_vec(), b, a};
  return power_to_bezier(coefficients);
}

Bezier CubicPowerForm::to_bezier() const {
  const std::array<Vec2, 4> coefficients{d.to_vec(), c, b, a};
  return power_to_bezier(coefficients);
}

std::optional<QuadraticPowerForm> interpolate_quadratic(Point p0, Point p1, Point p2, double t1) noexcept {
  if (!std::isfinite(t1) || t1 == 0.0 || t1 == 1.0) return std::nullopt;
  const Vec2 a = ((p2 - p0) * t1 + (p0 - p1)) / (t1 * (1.0 - t1));
  return QuadraticPowerForm{a, (p2 - p0) - a, p0};
}

std::optional<BasisMatrix> cubic_interpolation_matrix(const std::array<double, 4>& params) noexcept {
  for (std::size_t j = 0; j < 4; ++j) {
    if (!std::isfinite(params[j])) return std::nullopt;
    for (std::size_t k = 0; k < j; ++k) {
      if (params[j] == params[k]) return std::nullopt;
    }
  }
  BasisMatrix inverse{};
  for (std::size_t j = 0; j < 4; ++j) {
    // L_j(t) = (t - r0)(t - r1)(t - r2) / D_j with r the other three parameters and D_j = prod (t_j - r).
    std::array<double, 3> r{};
    double denominator = 1.0;
    for (std::size_t k = 0, m = 0; k < 4; ++k) {
      if (k == j) continue;
      r[m++] = params[k];
      denominator *= params[j] - params[k];
    }
    // Expanding the product: t³ - (r0+r1+r2) t² + (r0r1 + r0r2 + r1r2) t - r0r1r2.
    inverse[0][j] = 1.0 / denominator;
    inverse[1][j] = -(r[0] + r[1] + r[2]) / denominator;
    inverse[2][j] = (r[0] * r[1] + r[0] * r[2] + r[1] * r[2]) / denominator;
    inverse[3][j] = -(r[0] * r[1] * r[2]) / denominator;
  }
  return inverse;
}

std::optional<CubicPowerForm> interpolate_cubic(const std::array<Point, 4>& points,
                                                const std::array<double, 4>& params) noexcept {
  const std::optional<BasisMatrix> m = cubic_interpolation_matrix(params);
  if (!m) return std::nullopt;
  std::array<Vec2, 4> coefficients{};  // [a b c d] = M · P
  for (std::size_t row = 0; row < 4; ++row) {
    for (std::size_t j = 0; j < 4; ++j) coefficients[row] += points[j].to_vec() * (*m)[row][j];
  }
  return CubicPowerForm{coefficients[0], coefficients[1], coefficients[2], Point::from_vec(coefficients[3])};
}

Bezier power_to_bezier(std::span<const Vec2> coefficients) {
  if (coefficients.empty()) return {};
  const std::size_t n = coefficients.size() - 1;
  // binomial(n, j) in double, built row by row; exact while below 2^53.
  auto binomial = [](std::size_t top, std::size_t k) {
    double value = 1.0;
    for (std::size_t q = 1; q <= k; ++q)
      value = value * static_cast<double>(top - k + q) / static_cast<double>(q);
    return value;
  };
  std::vector<Point> control(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    Vec2 sum{0.0, 0.0};
    for (std::size_t j = 0; j <= i; ++j) sum += coefficients[j] * (binomial(i, j) / binomial(n, j));
    control[i] = Point::from_vec(sum);
  }
  return Bezier(std::move(control));
}

}  // namespace curvescan
