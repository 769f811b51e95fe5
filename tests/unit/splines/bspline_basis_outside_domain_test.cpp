// Regression: bspline_basis returned the extrapolated end polynomial outside the curve domain
// (N_{0,1}(0.5) = 1.5 on knots 0..4), which drew a wrong Cox–de Boor figure (Umetani, *Parametric Curve*, Fig. 2).
#include <catch2/catch.hpp>
#include <vector>

#include "curvescan/curves/bspline.h"

namespace curvescan {

TEST_CASE("bspline_basis is the textbook N_{i,p} outside the curve domain", "[bspline][basis][regression]") {
  const std::vector<double> knots{0, 1, 2, 3, 4};  // p = 1: n = 3 functions, domain [1, 3]
  // Hat functions: N_{i,1} rises on [i, i+1] and falls on [i+1, i+2] (Umetani, *Parametric Curve*, eq. 6–7). Values are
  // exact in binary (halves and quarters), so equality is required.
  CHECK(bspline_basis(knots, 1, 0, 0.5) == 0.5);
  CHECK(bspline_basis(knots, 1, 0, 0.0) == 0.0);
  CHECK(bspline_basis(knots, 1, 1, 0.5) == 0.0);
  CHECK(bspline_basis(knots, 1, 2, 3.75) == 0.25);
  CHECK(bspline_basis(knots, 1, 2, 4.0) == 0.0);
  // Beyond the knot vector every basis function vanishes.
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(bspline_basis(knots, 1, i, -0.5) == 0.0);
    CHECK(bspline_basis(knots, 1, i, 4.5) == 0.0);
  }
  // On the domain nothing changed: the partition of unity still holds at the right end (u = u_n = 3).
  for (double u : {1.0, 1.5, 2.0, 2.5, 3.0}) {
    double sum = 0.0;
    for (std::size_t i = 0; i < 3; ++i) sum += bspline_basis(knots, 1, i, u);
    CHECK(sum == Approx(1.0).margin(1e-15));  // one rounding of (u - u_i)/(u_{i+1} - u_i) per term
  }
}

TEST_CASE("bspline_basis on a clamped vector ends at one on the last function", "[bspline][basis]") {
  const std::vector<double> knots{0, 0, 0, 1, 2, 2, 2};  // p = 2, n = 4, domain [0, 2] = [u_0, u_m]
  CHECK(bspline_basis(knots, 2, 3, 2.0) == 1.0);
  CHECK(bspline_basis(knots, 2, 0, 0.0) == 1.0);
  CHECK(bspline_basis(knots, 2, 0, 2.5) == 0.0);
}

}  // namespace curvescan
