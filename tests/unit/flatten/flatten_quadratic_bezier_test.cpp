// flatten_quadratic_bezier (flatten.h): the quadratic entry point without the degree dispatch must give
// exactly what flatten_bezier, its plain reference, gives for the same three points: outcome and every
// vertex bit for bit (no tolerance: the arithmetic is meant to be the same, step for step), over the
// inputs that take each branch of flatten_bezier — one segment (Wang's bound), the closed form
// (flatten_quadratic.h), a tolerance below the coordinates' resolution, coordinates beyond the closed
// form's range (general walk), non-finite and invalid input, and a segment cap. The same holds for
// flatten_quadratic_bezier_past_one_segment wherever its precondition does.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "curvescan/curves/flatten.h"

namespace curvescan {
namespace {

struct Flattened {
  FlattenOutcome outcome;
  std::vector<Point> polyline;
};

// Both entry points, each appending after the same pre-existing vertex (the contract is "appends").
void require_same(Point p0, Point p1, Point p2, double tolerance,
                  std::size_t max_segments = kMaxFlattenSegments) {
  const std::vector<Point> ctrl{p0, p1, p2};
  Flattened reference{FlattenOutcome::kOk, {Point{-1.0, -1.0}}};
  Flattened direct{FlattenOutcome::kOk, {Point{-1.0, -1.0}}};
  reference.outcome = flatten_bezier(ctrl, tolerance, reference.polyline, max_segments);
  direct.outcome = flatten_quadratic_bezier(p0, p1, p2, tolerance, direct.polyline, max_segments);
  // The entry point for callers that made the first test themselves, within its precondition (finite
  // points, a finite positive tolerance, Wang's bound above it).
  const bool past_one_segment = p0.is_finite() && p1.is_finite() && p2.is_finite() &&
                                std::isfinite(tolerance) && tolerance > 0.0 &&
                                0.25 * std::sqrt(((p0 - p1) + (p2 - p1)).length_squared()) > tolerance;
  Flattened past{FlattenOutcome::kOk, {Point{-1.0, -1.0}}};
  if (past_one_segment) {
    past.outcome =
        flatten_quadratic_bezier_past_one_segment(p0, p1, p2, tolerance, past.polyline, max_segments);
  } else {
    past = reference;  // outside the precondition nothing is claimed
  }
  INFO("p0 (" << p0.x << ", " << p0.y << ") p1 (" << p1.x << ", " << p1.y << ") p2 (" << p2.x << ", " << p2.y
              << ") tolerance " << tolerance);
  REQUIRE(direct.outcome == reference.outcome);
  REQUIRE(direct.polyline.size() == reference.polyline.size());
  for (std::size_t i = 0; i < direct.polyline.size(); ++i) {
    // Exact comparison on purpose: the same operations in the same order give the same doubles.
    REQUIRE(direct.polyline[i].x == reference.polyline[i].x);
    REQUIRE(direct.polyline[i].y == reference.polyline[i].y);
  }
  REQUIRE(past.outcome == reference.outcome);
  REQUIRE(past.polyline.size() == reference.polyline.size());
  for (std::size_t i = 0; i < past.polyline.size(); ++i) {
    REQUIRE(past.polyline[i].x == reference.polyline[i].x);
    REQUIRE(past.polyline[i].y == reference.polyline[i].y);
  }
}

TEST_CASE("flatten_quadratic_bezier equals flatten_bezier on glyph-sized quadratics",
          "[flatten][quadratic]") {
  std::mt19937_64 rng(606);
  // Glyph outlines from 8 to 200 px: control points within a few hundred pixels, tolerances around 0.1.
  std::uniform_real_distribution<double> coord(-300.0, 300.0), offset(-20.0, 20.0), log_tolerance(-4.0, 0.0);
  for (int i = 0; i < 20000; ++i) {
    const Point p0{coord(rng), coord(rng)};
    // Half of them short (one segment by Wang's bound), half long (the closed-form walk).
    const double spread = i % 2 == 0 ? 0.05 : 1.0;
    const Point p1{p0.x + spread * offset(rng), p0.y + spread * offset(rng)};
    const Point p2{p1.x + spread * offset(rng), p1.y + spread * offset(rng)};
    require_same(p0, p1, p2, std::pow(10.0, log_tolerance(rng)));
  }
}

TEST_CASE("flatten_quadratic_bezier equals flatten_bezier on degenerate and extreme input",
          "[flatten][quadratic]") {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kMax = std::numeric_limits<double>::max();
  const Point a{0, 0}, b{10, 20}, c{20, 0};
  // Straight, a point, a cusp (control point past the ends).
  require_same(a, {10, 0}, c, 0.1);
  require_same(a, a, a, 0.1);
  require_same(a, {30, 0}, {10, 0}, 0.01);
  // Non-finite points and tolerance, differences that overflow, invalid tolerances.
  require_same({kNaN, 0}, b, c, 0.1);
  require_same(a, {0, kInf}, c, 0.1);
  require_same(a, b, c, kNaN);
  require_same(a, b, c, kInf);
  require_same({-kMax, 0}, {kMax, 1}, c, 0.1);
  require_same(a, b, c, 0.0);
  require_same(a, b, c, -1.0);
  // A tolerance below the resolution of the coordinates (walked at the floor, reported uncertified).
  require_same({1e7, 1e7}, {1e7 + 3, 1e7 + 9}, {1e7 + 6, 1e7}, 1e-10);
  // Coordinates beyond the closed form's 1e100: the general walk.
  require_same({1e120, 0}, {2e120, 1e120}, {3e120, 0}, 1e110);
  // Tiny control polygon next to large coordinates: the closed form declines on its margin.
  require_same({1e9, 1e9}, {1e9 + 1e-3, 1e9 + 2e-3}, {1e9 + 2e-3, 1e9}, 1e-6);
  // The segment cap, tight and loose.
  require_same(a, {500, 1000}, {1000, 0}, 1e-3, 1);
  require_same(a, {500, 1000}, {1000, 0}, 1e-3, 5);
}

}  // namespace
}  // namespace curvescan
