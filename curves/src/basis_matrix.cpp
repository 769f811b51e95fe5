// T·M and T·M·G for the cubic basis matrices (basis_matrix.h; U. of Toronto, *Parametric Curves*, "Parametric Cubic Curves").
#include "curvescan/curves/basis_matrix.h"

#include <cstddef>

namespace curvescan {

std::array<double, 4> blending_functions(const BasisMatrix& m, double t) noexcept {
  std::array<double, 4> f{};
  for (std::size_t column = 0; column < 4; ++column) {
    // Horner on t³·m0 + t²·m1 + t·m2 + m3.
    f[column] = ((m[0][column] * t + m[1][column]) * t + m[2][column]) * t + m[3][column];
  }
  return f;
}

Point eval_basis(const BasisMatrix& m, double t, const std::array<Vec2, 4>& geometry) noexcept {
  const std::array<double, 4> f = blending_functions(m, t);
  Vec2 sum{0.0, 0.0};
  for (std::size_t row = 0; row < 4; ++row) sum += geometry[row] * f[row];
  return Point::from_vec(sum);
}

}  // namespace curvescan
