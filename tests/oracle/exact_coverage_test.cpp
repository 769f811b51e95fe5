// Exact-coverage oracle (no Cairo): curvescan's coverage against coverage computed independently in the
// test (support/exact_coverage.h), for random simple and self-overlapping polygons under both rules.
//
// Tolerance: the output is round(area·255), so a correct rasterizer is within 0.5/255 of the exact area;
// double rounding in both computations is ~1e-12 of a pixel. The promised bound, 1/255, leaves 0.5/255 of
// margin that no rounding can use up; anything above it is a real error.
#include "exact_coverage.h"

#include <catch2/catch.hpp>
#include <random>

#include "coverage_mask.h"
#include "polygon_scenes.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr double kMaxError = 1.0;  // in 8-bit steps, see above

FillRule rule_of(int i) {
  return i % 2 == 0 ? FillRule::kNonZero : FillRule::kEvenOdd;
}

}  // namespace

TEST_CASE("exact coverage: random simple polygons match Sutherland-Hodgman areas", "[oracle][exact]") {
  std::mt19937 rng(20240601);
  std::uniform_real_distribution<double> centre(6.0, 18.0);
  std::uniform_int_distribution<int> vertices(3, 24);
  constexpr int kSize = 24;
  double worst = 0.0;
  for (int scene = 0; scene < 120; ++scene) {
    const Contour polygon = random_simple_polygon(rng, {centre(rng), centre(rng)}, 0.2, 11.0, vertices(rng));
    const std::vector<double> exact = sutherland_hodgman_coverage(polygon, kSize, kSize);
    const CoverageMask mask = render_curvescan({polygon}, kSize, kSize, rule_of(scene));
    const double error = max_error_vs_exact(mask, exact);
    worst = std::max(worst, error);
    INFO("scene " << scene << " error " << error);
    REQUIRE(error <= kMaxError);
  }
  // The rounding bound itself: no error above half a step plus rounding noise.
  CHECK(worst <= 0.5 + 1e-6);
}

TEST_CASE("exact coverage: self-overlapping polygons match the rule-resolved exact area", "[oracle][exact]") {
  std::mt19937 rng(777);
  std::uniform_int_distribution<int> vertices(3, 14);
  constexpr int kSize = 20;
  double worst = 0.0;
  for (int scene = 0; scene < 160; ++scene) {
    // Vertices a little beyond the canvas too, so that clipping takes part.
    const Contour polygon = random_polygon(rng, -3.0, -3.0, kSize + 3.0, kSize + 3.0, vertices(rng));
    const FillRule rule = rule_of(scene);
    const std::vector<double> exact = rule_resolved_coverage({polygon}, kSize, kSize, rule);
    const CoverageMask mask = render_curvescan({polygon}, kSize, kSize, rule);
    const double error = max_error_vs_exact(mask, exact);
    worst = std::max(worst, error);
    INFO("scene " << scene << " rule " << (rule == FillRule::kNonZero ? "nonzero" : "evenodd") << " error "
                  << error);
    REQUIRE(error <= kMaxError);
  }
  CHECK(worst <= 0.5 + 1e-6);
}

TEST_CASE("exact coverage: overlapping contours in both orientations", "[oracle][exact]") {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> centre(5.0, 15.0);
  std::uniform_int_distribution<int> vertices(3, 10);
  std::bernoulli_distribution flip(0.5);
  constexpr int kSize = 20;
  for (int scene = 0; scene < 120; ++scene) {
    Shape shape;
    for (int k = 0; k < 3; ++k) {
      Contour c = random_simple_polygon(rng, {centre(rng), centre(rng)}, 0.5, 8.0, vertices(rng));
      if (flip(rng)) std::reverse(c.begin(), c.end());
      shape.push_back(std::move(c));
    }
    const FillRule rule = rule_of(scene);
    const std::vector<double> exact = rule_resolved_coverage(shape, kSize, kSize, rule);
    const CoverageMask mask = render_curvescan(shape, kSize, kSize, rule);
    INFO("scene " << scene);
    REQUIRE(max_error_vs_exact(mask, exact) <= kMaxError);
  }
}

TEST_CASE("optimised scan equals the plain reference scan", "[oracle][reference]") {
  std::mt19937 rng(99);
  std::uniform_int_distribution<int> vertices(3, 40);
  std::uniform_real_distribution<double> centre(4.0, 36.0);
  constexpr int kSize = 40;
  for (int scene = 0; scene < 150; ++scene) {
    Shape shape;
    if (scene % 3 == 0) {
      shape.push_back(random_polygon(rng, -5.0, -5.0, kSize + 5.0, kSize + 5.0, vertices(rng)));
    } else if (scene % 3 == 1) {
      // Finely flattened curves: many joints per row (the chain path), overlapping rings, a ring crossing
      // the clip edges, and even-odd holes.
      const double r = 3.0 + 0.2 * scene;
      shape.push_back(regular_polygon({centre(rng), centre(rng)}, r, 0.7 * r, 200 + scene * 7, 0.01 * scene));
      shape.push_back(regular_polygon({centre(rng), centre(rng)}, 9.0, 12.0, 300, 0.3, scene % 2 == 0));
      shape.push_back(regular_polygon({centre(rng), 2.0}, 6.0, 6.0, 150));
    } else {
      shape.push_back(random_simple_polygon(rng, {centre(rng), centre(rng)}, 0.3, 25.0, vertices(rng)));
      shape.push_back(star_polygon({centre(rng), centre(rng)}, 12.0, 7, 3, scene * 0.1));
    }
    for (const Antialias aa : {Antialias::kExact, Antialias::kNone}) {
      const FillRule rule = rule_of(scene);
      int violations_fast = 0;
      int violations_ref = 0;
      const CoverageMask fast =
          render_curvescan(shape, kSize, kSize, rule, aa, ScanPath::kOptimised, &violations_fast);
      const CoverageMask ref =
          render_curvescan(shape, kSize, kSize, rule, aa, ScanPath::kReference, &violations_ref);
      INFO("scene " << scene << " aliased " << (aa == Antialias::kNone));
      CHECK(violations_fast == 0);
      CHECK(violations_ref == 0);
      // Both compute the same exact area in a different order of floating-point operations; an area
      // within ~1e-12 of a rounding midpoint may round either way: 1 step. Aliased output has no such
      // midpoint (same comparisons), so it must be identical.
      REQUIRE(max_abs_diff(fast, ref) <= (aa == Antialias::kExact ? 1 : 0));
    }
  }
}

TEST_CASE("exact coverage: finely flattened overlapping rings", "[oracle][exact]") {
  // Hundreds of short edges per contour, so most rows hold many joints (the chain path of the scan) and
  // some rows hold two rings whose x extents overlap (the per-edge fallback).
  std::mt19937 rng(2718);
  std::uniform_real_distribution<double> centre(6.0, 18.0);
  std::uniform_real_distribution<double> radius(2.0, 9.0);
  constexpr int kSize = 24;
  for (int scene = 0; scene < 24; ++scene) {
    Shape shape;
    for (int k = 0; k < 3; ++k) {
      const double r = radius(rng);
      shape.push_back(regular_polygon({centre(rng), centre(rng)}, r, r * 0.8, 120 + 40 * k, 0.1 * scene, k == 1));
    }
    const FillRule rule = rule_of(scene);
    const std::vector<double> exact = rule_resolved_coverage(shape, kSize, kSize, rule);
    const CoverageMask mask = render_curvescan(shape, kSize, kSize, rule);
    INFO("scene " << scene);
    REQUIRE(max_error_vs_exact(mask, exact) <= kMaxError);
  }
}
