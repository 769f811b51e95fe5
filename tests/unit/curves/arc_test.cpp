// elliptical_arc_conics: exactness of the conic representation of circle and ellipse arcs (arc.h).
#include "curvescan/curves/arc.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "curvescan/curves/affine.h"

using curvescan::Affine;
using curvescan::elliptical_arc_conics;
using curvescan::Point;
using curvescan::RationalBezier;

namespace {

constexpr double kPi = std::numbers::pi;

// The rational quadratic is an exact circle; what remains is double rounding in cos/sin, the division by
// cos(φ/2) and ~10 flops of homogeneous de Casteljau, each ~1e-16 relative: 1e-12 leaves a wide margin
// while still catching any approximation (a cubic arc approximation is off by ~3e-4).
constexpr double kRadiusRelTol = 1e-12;

}  // namespace

TEST_CASE("arc: circle arcs stay on the circle at many parameters", "[arc]") {
  std::mt19937_64 rng(20240501);
  std::uniform_real_distribution<double> angle(-10.0, 10.0);
  std::uniform_real_distribution<double> radius(0.01, 1000.0);
  std::uniform_real_distribution<double> coord(-500.0, 500.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Point center{coord(rng), coord(rng)};
    const double r = radius(rng);
    const auto conics = elliptical_arc_conics(center, r, r, angle(rng), angle(rng), angle(rng));
    REQUIRE(!conics.empty());
    for (const RationalBezier& conic : conics) {
      for (int i = 0; i <= 64; ++i) {
        const Point p = conic.eval(i / 64.0);
        // Relative to the radius plus the centre's magnitude, the scale of the coordinates being rounded.
        const double scale = r + std::hypot(center.x, center.y);
        REQUIRE(std::abs(p.distance(center) - r) <= kRadiusRelTol * scale);
      }
    }
  }
}

TEST_CASE("arc: each conic spans at most 90 degrees with weights (1, cos(phi/2), 1)", "[arc]") {
  for (double sweep : {0.1, kPi / 2, kPi / 2 + 1e-3, kPi, 1.5 * kPi, 2 * kPi, -0.7, -3.0, -2 * kPi}) {
    const auto conics = elliptical_arc_conics({0, 0}, 1, 1, 0, 0.3, sweep);
    const auto expected_count = static_cast<std::size_t>(std::ceil(std::abs(sweep) / (kPi / 2) - 1e-9));
    REQUIRE(conics.size() == expected_count);
    for (const RationalBezier& conic : conics) {
      REQUIRE(conic.degree() == 2);
      const auto w = conic.weights();
      REQUIRE(w[0] == 1.0);
      REQUIRE(w[2] == 1.0);
      // The chord subtends φ on the unit circle: |P2 - P0| = 2 sin(φ/2), hence cos(φ/2) = w1.
      const double half = std::asin(0.5 * conic.points()[0].distance(conic.points()[2]));
      REQUIRE(half <= kPi / 4 + 1e-12);
      REQUIRE(w[1] == Approx(std::cos(half)).margin(1e-12));
    }
  }
}

TEST_CASE("arc: zero sweep is empty, huge sweeps clamp to one turn, NaN sweep is empty", "[arc]") {
  REQUIRE(elliptical_arc_conics({1, 2}, 3, 4, 0.5, 0.2, 0.0).empty());
  REQUIRE(elliptical_arc_conics({1, 2}, 3, 4, 0.5, 0.2, std::nan("")).empty());
  REQUIRE(elliptical_arc_conics({1, 2}, 3, 4, 0.5, INFINITY, 1.0).empty());
  const auto clamped = elliptical_arc_conics({0, 0}, 1, 1, 0, 0, 100.0);
  REQUIRE(clamped.size() == 4);
  REQUIRE(clamped.back().points().back().x == Approx(1.0).margin(1e-12));
  REQUIRE(clamped.back().points().back().y == Approx(0.0).margin(1e-12));
  const auto clamped_negative = elliptical_arc_conics({0, 0}, 1, 1, 0, 0, -INFINITY);
  REQUIRE(clamped_negative.size() == 4);
}

TEST_CASE("arc: endpoints are the ellipse points at the start and end angles", "[arc]") {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> angle(-7.0, 7.0);
  std::uniform_real_distribution<double> radius(0.1, 50.0);
  for (int trial = 0; trial < 200; ++trial) {
    const Point center{angle(rng), angle(rng)};
    const double rx = radius(rng), ry = radius(rng), rot = angle(rng), start = angle(rng);
    const double sweep =
        std::clamp(angle(rng), -2 * kPi, 2 * kPi);  // beyond one turn is clamped, tested above
    const auto conics = elliptical_arc_conics(center, rx, ry, rot, start, sweep);
    const Affine map = Affine::translate(center.x, center.y) * Affine::rotate(rot) * Affine::scale(rx, ry);
    const Point expected_start = map.apply(Point{std::cos(start), std::sin(start)});
    const Point expected_end = map.apply(Point{std::cos(start + sweep), std::sin(start + sweep)});
    // Same formula, same rounding: only the order of the affine products could differ, ~1e-15 relative.
    const double tol = 1e-12 * (rx + ry + std::hypot(center.x, center.y));
    REQUIRE(conics.front().eval(0.0).distance(expected_start) <= tol);
    REQUIRE(conics.back().eval(1.0).distance(expected_end) <= tol);
    for (std::size_t k = 0; k + 1 < conics.size(); ++k) {
      // Consecutive segments share their endpoint bit for bit (the path must close without gaps).
      REQUIRE(conics[k].points().back() == conics[k + 1].points().front());
    }
  }
}

TEST_CASE("arc: consecutive conics join with a continuous tangent direction", "[arc]") {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> angle(-7.0, 7.0);
  std::uniform_real_distribution<double> radius(0.1, 50.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double rx = radius(rng), ry = radius(rng);
    const auto conics = elliptical_arc_conics({1, -2}, rx, ry, angle(rng), angle(rng), angle(rng));
    for (std::size_t k = 0; k + 1 < conics.size(); ++k) {
      // A rational Bézier's end tangents point along its end control legs (weights only scale them).
      const auto a = conics[k].points();
      const auto b = conics[k + 1].points();
      const curvescan::Vec2 incoming = (a[2] - a[1]).normalized();
      const curvescan::Vec2 outgoing = (b[1] - b[0]).normalized();
      // Unit vectors from coordinates of size <= ~100 rounded at 1e-16: 1e-12 is generous.
      REQUIRE(std::abs(incoming.cross(outgoing)) <= 1e-12);
      REQUIRE(incoming.dot(outgoing) > 0.0);
    }
  }
}

TEST_CASE("arc: ellipse arcs satisfy the implicit ellipse equation", "[arc]") {
  const Point center{10, 20};
  const double rx = 30, ry = 7, rot = 0.6;
  const auto conics = elliptical_arc_conics(center, rx, ry, rot, -1.0, 5.0);
  const auto to_unit =
      (Affine::translate(center.x, center.y) * Affine::rotate(rot) * Affine::scale(rx, ry)).inverse();
  REQUIRE(to_unit.has_value());
  for (const RationalBezier& conic : conics) {
    for (int i = 0; i <= 100; ++i) {
      const Point u = to_unit->apply(conic.eval(i / 100.0));
      // Coordinates ~30 rounded at 1e-16 and mapped back by a 1/7 scale: 1e-12 has three orders of margin.
      REQUIRE(std::abs(std::hypot(u.x, u.y) - 1.0) <= 1e-12);
    }
  }
}
