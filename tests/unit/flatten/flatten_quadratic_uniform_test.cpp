// flatten_quadratic_bezier_uniform (flatten_quadratic_uniform.h; proof in src/flatten_quadratic_uniform.cpp):
// uniform parameter steps from Wang's bound.
//  - The contract, measured by the independent Hausdorff measurement (hausdorff_measure.h): random
//    quadratics, glyph-sized and canvas-sized, flat and sharp (a cusp-like turn: P1 far off the chord), at
//    several tolerances — within the tolerance, vertices on the curve, the last vertex exactly P2.
//  - The step count is the closed form, ceil(sqrt(|D| / 4τ)), and the vertices are B(i/n): checked against
//    the formula directly on curves whose margins are far below the rounding of the ceiling.
//  - The bound is the exact maximum for a quadratic, so it is tight: on a symmetric parabola with n - 1
//    steps the middle chord is measured farther than the tolerance (the count is not padded).
//  - Its boundary: what it cannot certify goes to flatten_quadratic_bezier, with the same outcome and
//    polyline (non-finite points, coordinates beyond 1e100, a tolerance near the coordinates' resolution,
//    a segment cap below the step count).
#include "curvescan/curves/flatten_quadratic_uniform.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/flatten.h"
#include "hausdorff_measure.h"

namespace curvescan {
namespace {

std::size_t closed_form_steps(Point p0, Point p1, Point p2, double tolerance) {
  const double bulge = 0.25 * ((p0 - p1) + (p2 - p1)).length();
  return static_cast<std::size_t>(std::max(1.0, std::ceil(std::sqrt(bulge / tolerance))));
}

TEST_CASE("uniform quadratic flattening stays within the tolerance (measured)", "[flatten][quadratic]") {
  std::mt19937_64 rng(20261126);
  for (const double extent : {8.0, 100.0, 2000.0}) {
    std::uniform_real_distribution<double> coordinate(-extent, extent);
    for (const double tolerance : {0.01, 0.1, 0.25}) {
      for (int trial = 0; trial < 60; ++trial) {
        const Point p0{coordinate(rng), coordinate(rng)};
        Point p1{coordinate(rng), coordinate(rng)};
        const Point p2{coordinate(rng), coordinate(rng)};
        if (trial % 4 == 0) p1 = p1 + (p1 - midpoint(p0, p2)) * 20.0;  // a sharp turn
        const std::vector<Point> ctrl{p0, p1, p2};
        std::vector<Point> out{p0};
        REQUIRE(flatten_quadratic_bezier_uniform(p0, p1, p2, tolerance, out) == FlattenOutcome::kOk);
        REQUIRE(out.back() == p2);
        const testing::Measurement m = testing::measure_bezier(ctrl, tolerance, out);
        // Slack: the measurement's own rounding, 1e-12 of the largest coordinate (as
        // flatten_quadratic_test.cpp); the flattener's own margins sit inside its bound.
        const double slack = 1e-12 * 21.0 * extent;
        INFO("extent " << extent << " tolerance " << tolerance << " trial " << trial << " segments "
                       << out.size() - 1);
        CHECK(m.curve_to_polyline <= tolerance + slack);
        CHECK(m.polyline_to_curve <= tolerance + slack);
        CHECK(m.vertex_to_curve <= tolerance / 100.0 + slack);
      }
    }
  }
}

TEST_CASE("uniform quadratic flattening takes the closed-form step count at B(i/n)", "[flatten][quadratic]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> coordinate(0.0, 100.0);
  int multi_segment = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const Point p0{coordinate(rng), coordinate(rng)};
    const Point p1{coordinate(rng), coordinate(rng)};
    const Point p2{coordinate(rng), coordinate(rng)};
    const double tolerance = 0.1;
    const std::size_t n = closed_form_steps(p0, p1, p2, tolerance);
    // Skip the rare curve whose sqrt(|D| / 4τ) lies within the margins (~1e-8 relative) of an integer:
    // there the proven count may be one more than the plain formula.
    const double exact = std::sqrt(0.25 * ((p0 - p1) + (p2 - p1)).length() / tolerance);
    if (std::abs(exact - std::round(exact)) < 1e-6) continue;
    std::vector<Point> out;
    REQUIRE(flatten_quadratic_bezier_uniform(p0, p1, p2, tolerance, out) == FlattenOutcome::kOk);
    REQUIRE(out.size() == n);
    if (n > 1) ++multi_segment;
    const std::vector<Point> ctrl{p0, p1, p2};
    for (std::size_t i = 1; i < n; ++i) {
      const Point expected = de_casteljau(ctrl, static_cast<double>(i) / static_cast<double>(n));
      // A few ulps of coordinates below 200: the two evaluations round differently.
      CHECK(out[i - 1].distance(expected) <= 1e-12);
    }
    CHECK(out.back() == p2);
  }
  CHECK(multi_segment > 400);  // the cases exercise the stepping, not only the one-segment answer
}

TEST_CASE("uniform quadratic flattening is not padded: one step fewer exceeds the tolerance",
          "[flatten][quadratic]") {
  // Symmetric parabola: |D| = 2·height, chord sagitta with n steps is |D|/(4n²) exactly at the middle
  // step's midpoint when n is odd.
  for (const double height : {3.0, 17.0, 250.0}) {
    const Point p0{0.0, 0.0};
    const Point p1{10.0, height};
    const Point p2{20.0, 0.0};
    const double tolerance = 0.1;
    std::vector<Point> out{p0};
    REQUIRE(flatten_quadratic_bezier_uniform(p0, p1, p2, tolerance, out) == FlattenOutcome::kOk);
    const std::size_t n = out.size() - 1;
    REQUIRE(n == closed_form_steps(p0, p1, p2, tolerance));
    // n - 1 uniform steps: the largest chord distance is (|D|/4)/(n-1)² > tolerance by the ceiling.
    const std::size_t fewer = n - 1;
    std::vector<Point> coarse{p0};
    const std::vector<Point> ctrl{p0, p1, p2};
    for (std::size_t i = 1; i <= fewer; ++i) {
      coarse.push_back(de_casteljau(ctrl, static_cast<double>(i) / static_cast<double>(fewer)));
    }
    const testing::Measurement m = testing::measure_bezier(ctrl, tolerance, coarse);
    INFO("height " << height << " steps " << n);
    // The bound h²|D|/4 is attained at each step's middle, so the measured distance is it, up to the
    // measurement's resolution (a few 1e-4 of the tolerance, hausdorff_measure.h): well above τ here
    // unless (|D|/4)/(n-1)² is within that of τ, which these heights avoid.
    CHECK(m.curve_to_polyline > tolerance * 1.001);
  }
}

TEST_CASE("uniform quadratic flattening hands what it cannot certify to the adaptive walk",
          "[flatten][quadratic]") {
  const auto same_as_adaptive = [](Point p0, Point p1, Point p2, double tolerance, std::size_t max_segments) {
    std::vector<Point> uniform{Point{-1.0, -1.0}};
    std::vector<Point> adaptive{Point{-1.0, -1.0}};
    const FlattenOutcome a = flatten_quadratic_bezier_uniform(p0, p1, p2, tolerance, uniform, max_segments);
    const FlattenOutcome b = flatten_quadratic_bezier(p0, p1, p2, tolerance, adaptive, max_segments);
    CHECK(a == b);
    REQUIRE(uniform.size() == adaptive.size());
    for (std::size_t i = 0; i < uniform.size(); ++i) {
      CHECK(uniform[i].x == adaptive[i].x);  // the same call: the same doubles
      CHECK(uniform[i].y == adaptive[i].y);
    }
    return a;
  };
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(same_as_adaptive({0, 0}, {nan, 1}, {2, 0}, 0.1, kMaxFlattenSegments) == FlattenOutcome::kNonFinite);
  CHECK(same_as_adaptive({0, 0}, {1, inf}, {2, 0}, 0.1, kMaxFlattenSegments) == FlattenOutcome::kNonFinite);
  CHECK(same_as_adaptive({0, 0}, {1, 1}, {2, 0}, nan, kMaxFlattenSegments) == FlattenOutcome::kNonFinite);
  CHECK(same_as_adaptive({0, 0}, {1, 1}, {2, 0}, -1.0, kMaxFlattenSegments) == FlattenOutcome::kInvalid);
  same_as_adaptive({0, 0}, {1e120, 1e120}, {2e120, 0}, 1e110, kMaxFlattenSegments);    // beyond 1e100
  same_as_adaptive({1e9, 0}, {1e9 + 5, 5}, {1e9 + 10, 0}, 1e-9, kMaxFlattenSegments);  // near resolution
  // 317 steps needed, 10 allowed: the adaptive walk reports the cap.
  CHECK(same_as_adaptive({0, 0}, {50, 20000}, {100, 0}, 0.1, 10) == FlattenOutcome::kSegmentLimit);
}

}  // namespace
}  // namespace curvescan
