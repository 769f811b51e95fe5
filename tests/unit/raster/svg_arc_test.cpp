// SVG endpoint arcs (SVG 1.1 appendix F.6): centres of known examples, radius correction, the special
// cases of F.6.2, and a randomized check of the conversion against the ellipse equation.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "curvescan/curves/rational_bezier.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/path_builder.h"

using namespace curvescan;

namespace {

constexpr double kPi = std::numbers::pi;

// The point at angle θ on the ellipse (center, rx, ry, rotation φ): F.6.3's parametrization.
Point ellipse_point(const SvgArcCenter& arc, double x_rotation, double theta) {
  const double cs = std::cos(x_rotation), sn = std::sin(x_rotation);
  const double ux = arc.rx * std::cos(theta), uy = arc.ry * std::sin(theta);
  return {arc.center.x + cs * ux - sn * uy, arc.center.y + sn * ux + cs * uy};
}

// Doubles for points computed by a few trigonometric and square-root steps on inputs of size ~1..100:
// 1e-9 absolute is ~1e5 ulps there, far below any wrong-branch error (which is of the size of the radii).
constexpr double kGeometryTolerance = 1e-9;

}  // namespace

TEST_CASE("svg_arc_center: the four flag combinations on the unit circle", "[svg_arc]") {
  struct Case {
    bool large_arc, sweep;
    Point center;
    double sweep_angle;
  };
  // From (1, 0) to (0, 1) with r = 1 the two candidate centres are (0, 0) and (1, 1); small arcs turn a
  // quarter, large arcs three quarters, positive angles (sweep = 1) go from +x towards +y.
  const Case cases[] = {{false, true, {0, 0}, kPi / 2},
                        {false, false, {1, 1}, -kPi / 2},
                        {true, true, {1, 1}, 1.5 * kPi},
                        {true, false, {0, 0}, -1.5 * kPi}};
  for (const Case& c : cases) {
    CAPTURE(c.large_arc, c.sweep);
    const std::optional<SvgArcCenter> arc = svg_arc_center({1, 0}, {0, 1}, 1, 1, 0, c.large_arc, c.sweep);
    REQUIRE(arc);
    CHECK(arc->center.x == Approx(c.center.x).margin(kGeometryTolerance));
    CHECK(arc->center.y == Approx(c.center.y).margin(kGeometryTolerance));
    CHECK(arc->sweep_angle == Approx(c.sweep_angle));
    CHECK(arc->rx == 1.0);
  }
}

TEST_CASE("svg_arc_center: radii too small are scaled up to reach (F.6.6)", "[svg_arc]") {
  // The chord (0,0)-(2,0) needs r >= 1: r = 0.5 (and -0.5, F.6.6 step 1) become 1, centre the midpoint,
  // and the arc is a half turn either way.
  for (const double r : {0.5, -0.5, 1.0}) {
    CAPTURE(r);
    const std::optional<SvgArcCenter> arc = svg_arc_center({0, 0}, {2, 0}, r, r, 0, false, true);
    REQUIRE(arc);
    CHECK(arc->rx == Approx(1.0));
    CHECK(arc->ry == Approx(1.0));
    CHECK(arc->center.x == Approx(1.0));
    CHECK(arc->center.y == Approx(0.0).margin(kGeometryTolerance));
    CHECK(std::fabs(arc->sweep_angle) == Approx(kPi));
  }
  // An ellipse 2:1 rotated by 90 degrees: radii scale together, keeping their ratio.
  const std::optional<SvgArcCenter> arc = svg_arc_center({0, 0}, {0, 10}, 2, 1, kPi / 2, false, false);
  REQUIRE(arc);
  CHECK(arc->rx / arc->ry == Approx(2.0));
  CHECK(arc->rx == Approx(5.0));  // the chord of length 10 is the rotated major axis
}

TEST_CASE("svg_arc_center: random arcs start and end at their endpoints with the requested turn",
          "[svg_arc]") {
  std::mt19937 rng(8675309);
  std::uniform_real_distribution<double> coord(-100.0, 100.0);
  std::uniform_real_distribution<double> radius(1.0, 150.0);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  for (int trial = 0; trial < 2000; ++trial) {
    const Point from{coord(rng), coord(rng)}, to{coord(rng), coord(rng)};
    const double rx = radius(rng), ry = radius(rng), phi = angle(rng);
    const bool large_arc = (trial & 1) != 0, sweep = (trial & 2) != 0;
    const std::optional<SvgArcCenter> arc = svg_arc_center(from, to, rx, ry, phi, large_arc, sweep);
    REQUIRE(arc);
    const Point start = ellipse_point(*arc, phi, arc->start_angle);
    const Point end = ellipse_point(*arc, phi, arc->start_angle + arc->sweep_angle);
    // Relative to the size of the figure: radii up to ~150·scale, coordinates up to 100.
    const double tolerance = 1e-9 * (1.0 + arc->rx + arc->ry);
    CHECK(start.distance(from) < tolerance);
    CHECK(end.distance(to) < tolerance);
    CHECK((arc->sweep_angle > 0) == sweep);
    const bool scaled = arc->rx > rx * (1 + 1e-12);
    if (!scaled) CHECK((std::fabs(arc->sweep_angle) > kPi) == large_arc);
  }
}

TEST_CASE("svg_arc_to: zero radius is a line, coincident endpoints nothing, the end is exact", "[svg_arc]") {
  SECTION("zero radius") {
    const Result<Path> path = PathBuilder().move_to({0, 0}).svg_arc_to(0, 5, 0, false, true, {3, 4}).build();
    REQUIRE(path.is_ok());
    CHECK(std::vector<PathVerb>(path->verbs().begin(), path->verbs().end()) ==
          std::vector<PathVerb>{PathVerb::kMove, PathVerb::kLine});
  }
  SECTION("coincident endpoints") {
    const Result<Path> path =
        PathBuilder().move_to({1, 1}).svg_arc_to(5, 5, 0, true, true, {1, 1}).line_to({2, 2}).build();
    REQUIRE(path.is_ok());
    CHECK(std::vector<PathVerb>(path->verbs().begin(), path->verbs().end()) ==
          std::vector<PathVerb>{PathVerb::kMove, PathVerb::kLine});
    CHECK(PathBuilder().move_to({1, 1}).svg_arc_to(5, 5, 0, true, true, {1, 1}).build()->empty());
  }
  SECTION("a large elliptical arc as conics on the ellipse, ending exactly at the target") {
    const Point from{10, 10}, to{37.5, 21.25};
    constexpr double kRx = 30, kRy = 12, kPhi = 0.4;
    const Result<Path> path = PathBuilder().move_to(from).svg_arc_to(kRx, kRy, kPhi, true, false, to).build();
    REQUIRE(path.is_ok());
    const SvgArcCenter arc = *svg_arc_center(from, to, kRx, kRy, kPhi, true, false);
    const std::vector<PathElement> e(path->begin(), path->end());
    REQUIRE(e.size() >= 3);  // a large arc spans more than 180 degrees: at least two conics
    CHECK(e.back().end == to);
    const double cs = std::cos(kPhi), sn = std::sin(kPhi);
    for (std::size_t i = 1; i < e.size(); ++i) {
      REQUIRE(e[i].verb == PathVerb::kConic);
      for (const double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const Vec2 d = rational_de_casteljau(e[i].points, e[i].weights, t) - arc.center;
        const double u = (cs * d.x + sn * d.y) / arc.rx, v = (-sn * d.x + cs * d.y) / arc.ry;
        CHECK(u * u + v * v == Approx(1.0).margin(1e-9));  // on the ellipse, to rounding
      }
    }
  }
  SECTION("no current point is an error") {
    const Result<Path> path = PathBuilder().svg_arc_to(5, 5, 0, false, false, {1, 1}).build();
    REQUIRE_FALSE(path.is_ok());
    CHECK_THAT(path.error().message, Catch::Contains("no current point"));
  }
}
