// Boehm knot insertion (Umetani, *Parametric Curve*, §3.3, eq. 8–9 with the standard indices) leaves the curve unchanged.
#include <algorithm>
#include <catch2/catch.hpp>
#include <random>

#include "curvescan/curves/bspline.h"
#include "random_spline.h"

namespace curvescan {
namespace {

// Each insertion replaces points by convex combinations of neighbours (one or two roundings of values of
// magnitude <= 1) and de Boor adds a few dozen more: 1e-12 is the task's bar with orders of margin.
constexpr double kTolerance = 1e-12;

void require_same_curve(const BSpline& a, const BSpline& b, std::mt19937_64& rng) {
  REQUIRE(a.domain_start() == b.domain_start());
  REQUIRE(a.domain_end() == b.domain_end());
  for (const double u : test::sample_parameters(rng, a, 100)) {
    INFO("u " << u);
    REQUIRE(a.eval(u).distance(b.eval(u)) <= kTolerance);
  }
}

TEST_CASE("Knot insertion leaves random curves unchanged", "[bspline][insert]") {
  std::mt19937_64 rng(9001);
  for (int degree = 1; degree <= 5; ++degree) {
    for (int trial = 0; trial < 40; ++trial) {
      const BSpline spline = test::random_bspline(rng, degree, trial % 2 == 0);
      std::uniform_real_distribution<double> in_domain(spline.domain_start(), spline.domain_end());
      // A fresh value, an existing knot inside the domain, and the domain ends.
      std::vector<double> candidates{in_domain(rng), spline.domain_start(), spline.domain_end()};
      const auto knots = spline.knots();
      candidates.push_back(knots[static_cast<std::size_t>(degree) + 1]);
      for (const double u : candidates) {
        INFO("degree " << degree << " trial " << trial << " insert " << u);
        const BSpline refined = spline.insert_knot(u);
        const bool full = std::count(knots.begin(), knots.end(), u) > degree;
        REQUIRE(refined.points().size() == spline.points().size() + (full ? 0 : 1));
        REQUIRE(std::is_sorted(refined.knots().begin(), refined.knots().end()));
        require_same_curve(spline, refined, rng);
      }
    }
  }
}

TEST_CASE("Repeated insertion up to a full knot keeps the curve and passes through a point",
          "[bspline][insert]") {
  std::mt19937_64 rng(9002);
  const BSpline spline = test::random_bspline(rng, 3, false);
  const double u = 0.5 * (spline.domain_start() + spline.domain_end());
  BSpline refined = spline;
  for (int i = 0; i < 6; ++i) refined = refined.insert_knot(u);  // the last insertions are refused
  const auto knots = refined.knots();
  REQUIRE(std::count(knots.begin(), knots.end(), u) == 4);
  require_same_curve(spline, refined, rng);
  // At multiplicity p (here reached) the curve passes through a control point (U. of Toronto, *Parametric Curves*, "Multiple knots").
  const std::size_t first =
      static_cast<std::size_t>(std::lower_bound(knots.begin(), knots.end(), u) - knots.begin());
  REQUIRE(refined.points()[first - 1].distance(spline.eval(u)) <= kTolerance);
}

TEST_CASE("Insertion outside the domain or of NaN returns the curve unchanged", "[bspline][insert]") {
  std::mt19937_64 rng(9003);
  const BSpline spline = test::random_bspline(rng, 2, true);
  REQUIRE(spline.insert_knot(spline.domain_end() + 1.0).points().size() == spline.points().size());
  REQUIRE(spline.insert_knot(std::nan("")).points().size() == spline.points().size());
}

}  // namespace
}  // namespace curvescan
