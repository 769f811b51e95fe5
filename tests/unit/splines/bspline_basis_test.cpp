// Cox–de Boor basis (Umetani, *Parametric Curve*, eq. 6–7): partition of unity, non-negativity, local support, agreement
// with the Bernstein basis on a knot vector without interior knots, and the span conventions.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "curvescan/curves/bspline.h"
#include "curvescan/curves/knot_vector.h"
#include "random_spline.h"

namespace curvescan {
namespace {

// Each basis value is a sum of at most 2^p products of p factors in [0, 1], each rounded once or twice:
// the sum of all n of them is off from 1 by at most a few dozen ulps for p <= 5. 1e-12 leaves room.
constexpr double kUnityTolerance = 1e-12;

TEST_CASE("B-spline bases are a non-negative partition of unity on random knot vectors", "[bspline][basis]") {
  std::mt19937_64 rng(20240601);
  for (int degree = 0; degree <= 5; ++degree) {
    for (int trial = 0; trial < 100; ++trial) {
      const bool clamp = trial % 2 == 0;
      const BSpline spline = test::random_bspline(rng, degree, clamp);
      for (const double u : test::sample_parameters(rng, spline, 40)) {
        double sum = 0.0;
        const std::size_t span = spline.find_span(u);
        for (std::size_t i = 0; i < spline.points().size(); ++i) {
          const double value = spline.basis(i, u);
          INFO("degree " << degree << " trial " << trial << " u " << u << " i " << i);
          REQUIRE(value >= 0.0);
          // Local support: only N_{k-p..k,p} can be non-zero on span k (Umetani, *Parametric Curve*, §3.2).
          if (i + static_cast<std::size_t>(degree) < span || i > span) REQUIRE(value == 0.0);
          sum += value;
        }
        REQUIRE_THAT(sum, Catch::Matchers::WithinAbs(1.0, kUnityTolerance));
      }
    }
  }
}

TEST_CASE("Clamped knots without interior knots give the Bernstein basis", "[bspline][basis]") {
  // With knots {0 x (p+1), 1 x (p+1)} the B-spline basis is the Bernstein basis C(p,i) u^i (1-u)^(p-i)
  // (Ince, *Curves*, "Bernstein Polynomials"): an independent closed form.
  for (int degree = 1; degree <= 5; ++degree) {
    const std::size_t count = static_cast<std::size_t>(degree) + 1;
    auto knots = clamped_knots(count, degree);
    REQUIRE(knots.is_ok());
    for (int step = 0; step <= 20; ++step) {
      const double u = step / 20.0;
      for (std::size_t i = 0; i < count; ++i) {
        double binomial = 1.0;
        for (std::size_t j = 0; j < i; ++j)
          binomial = binomial * static_cast<double>(count - 1 - j) / static_cast<double>(j + 1);
        const double expected = binomial * std::pow(u, static_cast<double>(i)) *
                                std::pow(1.0 - u, static_cast<double>(count - 1 - i));
        // Both sides are a handful of roundings of values <= 1.
        REQUIRE_THAT(bspline_basis(*knots, degree, i, u), Catch::Matchers::WithinAbs(expected, 1e-14));
      }
    }
  }
}

TEST_CASE("Uniform quadratic basis matches the closed-form pieces", "[bspline][basis]") {
  // Uniform knots: N_{2,2} on [2, 5] is the translate of the textbook quadratic: with s = u - 2,
  // s^2/2 on [0,1), (-2s^2 + 6s - 3)/2 on [1,2), (3-s)^2/2 on [2,3) (Dill, *Introduction to Parametric Curves*, "Uniform BSpline").
  const std::vector<double> knots{0, 1, 2, 3, 4, 5, 6, 7};  // five points, degree 2, domain [2, 5]
  for (int step = 0; step <= 24; ++step) {
    const double s = step / 8.0;
    double expected = 0.0;
    if (s < 1.0) {
      expected = s * s / 2.0;
    } else if (s < 2.0) {
      expected = (-2.0 * s * s + 6.0 * s - 3.0) / 2.0;
    } else {
      expected = (3.0 - s) * (3.0 - s) / 2.0;
    }
    // Values are multiples of 1/128 computed with exact dyadic arithmetic except the divisions by 1.
    REQUIRE_THAT(bspline_basis(knots, 2, 2, 2.0 + s), Catch::Matchers::WithinAbs(expected, 1e-15));
  }
}

TEST_CASE("Right-end convention: a clamped basis is 1 at the last point at u_max", "[bspline][basis]") {
  for (int degree = 0; degree <= 4; ++degree) {
    const std::size_t count = static_cast<std::size_t>(degree) + 4;
    auto knots = clamped_knots(count, degree);
    REQUIRE(knots.is_ok());
    // Half-open spans alone would make every basis zero at u = 1; the convention picks the last span.
    REQUIRE(bspline_basis(*knots, degree, count - 1, 1.0) == 1.0);
    REQUIRE(bspline_basis(*knots, degree, 0, 0.0) == 1.0);
    REQUIRE(find_knot_span(*knots, degree, 1.0) == count - 1);
  }
}

TEST_CASE("Half-open convention: a knot belongs to the span it starts", "[bspline][basis]") {
  const std::vector<double> knots{0, 0, 0, 1, 2, 3, 3, 3};  // five points, degree 2
  REQUIRE(find_knot_span(knots, 2, 1.0) == 3);
  REQUIRE(find_knot_span(knots, 2, 0.999) == 2);
  REQUIRE(find_knot_span(knots, 2, 2.0) == 4);
  REQUIRE(find_knot_span(knots, 2, 3.0) == 4);
  // Degree 0: N_{i,0} is the indicator of [u_i, u_{i+1}).
  const std::vector<double> steps{0, 1, 2, 3};
  REQUIRE(bspline_basis(steps, 0, 1, 1.0) == 1.0);
  REQUIRE(bspline_basis(steps, 0, 0, 1.0) == 0.0);
}

TEST_CASE("Basis propagates NaN and rejects malformed input", "[bspline][basis]") {
  const std::vector<double> knots{0, 0, 0, 1, 1, 1};
  REQUIRE(std::isnan(bspline_basis(knots, 2, 0, std::nan(""))));
  REQUIRE(std::isnan(bspline_basis(knots, 5, 0, 0.5)));  // too few knots for degree 5
  REQUIRE(bspline_basis(knots, 2, 3, 0.5) == 0.0);       // index past the last basis function
}

}  // namespace
}  // namespace curvescan
