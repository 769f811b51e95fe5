// PathBuilder and Path: every verb, the contour rules, validation messages, exact appends, bounds and
// transforms.
#include "curvescan/raster/path_builder.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/rational_bezier.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/path.h"

using namespace curvescan;

namespace {

std::vector<PathElement> elements_of(const Path& path) {
  return {path.begin(), path.end()};
}

std::vector<PathVerb> verbs_of(const Path& path) {
  return {path.verbs().begin(), path.verbs().end()};
}

std::vector<Point> as_vector(std::span<const Point> points) {
  return {points.begin(), points.end()};
}

}  // namespace

TEST_CASE("every verb is stored and iterated with its start point and weights", "[path]") {
  const Point high_degree[] = {{6, 0}, {7, 2}, {8, -2}, {9, 1}, {10, 0}};  // degree 5
  const Point rational_points[] = {{11, 1}, {12, 3}, {13, 0}};             // degree 3
  const double rational_weights[] = {2.0, 0.5, 3.0, 1.5};                  // incl. the current point's
  PathBuilder builder;
  builder.move_to({0, 0})
      .line_to({1, 0})
      .quad_to({2, 1}, {3, 0})
      .cubic_to({3, 1}, {4, 1}, {4, 0})
      .conic_to({5, 1}, {6, 0}, 0.7)
      .bezier_to(high_degree)
      .rational_bezier_to(rational_points, rational_weights)
      .close();
  const Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  const std::vector<PathElement> e = elements_of(*path);
  REQUIRE(e.size() == 8);

  CHECK(e[0].verb == PathVerb::kMove);
  CHECK(as_vector(e[0].points) == std::vector<Point>{{0, 0}});
  CHECK(e[1].verb == PathVerb::kLine);
  CHECK(as_vector(e[1].points) == std::vector<Point>{{0, 0}, {1, 0}});
  CHECK(e[2].verb == PathVerb::kQuad);
  CHECK(as_vector(e[2].points) == std::vector<Point>{{1, 0}, {2, 1}, {3, 0}});
  CHECK(e[3].verb == PathVerb::kCubic);
  CHECK(as_vector(e[3].points) == std::vector<Point>{{3, 0}, {3, 1}, {4, 1}, {4, 0}});
  CHECK(e[4].verb == PathVerb::kConic);
  CHECK(as_vector(e[4].points) == std::vector<Point>{{4, 0}, {5, 1}, {6, 0}});
  CHECK(std::vector<double>(e[4].weights.begin(), e[4].weights.end()) == std::vector<double>{1.0, 0.7, 1.0});
  CHECK(e[5].verb == PathVerb::kBezier);
  CHECK(e[5].degree() == 5);
  CHECK(e[5].points.front() == Point{6, 0});
  CHECK(e[5].weights.empty());
  CHECK(e[6].verb == PathVerb::kRationalBezier);
  CHECK(e[6].degree() == 3);
  CHECK(as_vector(e[6].points) == std::vector<Point>{{10, 0}, {11, 1}, {12, 3}, {13, 0}});
  CHECK(std::vector<double>(e[6].weights.begin(), e[6].weights.end()) ==
        std::vector<double>{2.0, 0.5, 3.0, 1.5});
  CHECK(e[7].verb == PathVerb::kClose);
  CHECK(e[7].start == Point{13, 0});
  CHECK(e[7].end == Point{0, 0});
  for (std::size_t i = 1; i < 7; ++i) {
    CHECK(e[i].start == e[i - 1].end);  // contiguous: each segment starts where the previous ended
  }
}

TEST_CASE("contour rules: moves collapse, lone moves vanish, close restarts at the contour start", "[path]") {
  PathBuilder builder;
  builder.move_to({9, 9}).move_to({0, 0}).line_to({4, 0}).line_to({4, 4}).close().line_to({0, 4}).close();
  builder.close();            // nothing to close: no effect
  builder.move_to({50, 50});  // trailing move: dropped
  const Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  CHECK(verbs_of(*path) == std::vector<PathVerb>{PathVerb::kMove, PathVerb::kLine, PathVerb::kLine,
                                                 PathVerb::kClose, PathVerb::kMove, PathVerb::kLine,
                                                 PathVerb::kClose});
  const std::vector<PathElement> e = elements_of(*path);
  CHECK(e[4].start == Point{0, 0});  // the second contour starts at the first one's start (SVG 8.3.3)
  CHECK(e[6].end == Point{0, 0});
  CHECK(builder.current_point() == Point{50, 50});
  CHECK(path->bounds() == Rect{0, 0, 4, 4});  // the dropped moves do not widen the bounds
}

TEST_CASE("polygon() builds what move_to, line_to per point and close() build", "[path]") {
  // Random polygons after a drawn contour and between other commands, so that the contour bookkeeping
  // (pending move, current point, the next contour's start after the close) is compared too.
  std::mt19937 rng(18);
  std::uniform_real_distribution<double> coordinate(-100.0, 100.0);
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<Point> points(static_cast<std::size_t>(trial % 7));  // 0 to 6 points: the edge cases too
    for (Point& p : points) p = {coordinate(rng), coordinate(rng)};
    PathBuilder by_commands;
    PathBuilder by_polygon;
    for (PathBuilder* b : {&by_commands, &by_polygon}) b->move_to({1, 2}).line_to({3, 5});
    if (!points.empty()) {
      by_commands.move_to(points[0]);
      for (std::size_t i = 1; i < points.size(); ++i) by_commands.line_to(points[i]);
      by_commands.close();
    }
    by_polygon.polygon(points);
    CHECK(by_commands.current_point() == by_polygon.current_point());
    for (PathBuilder* b : {&by_commands, &by_polygon}) b->line_to({7, 7});  // after the polygon
    const Result<Path> expected = by_commands.build();
    const Result<Path> got = std::move(by_polygon).build();
    REQUIRE(expected.is_ok());
    REQUIRE(got.is_ok());
    CHECK(*got == *expected);  // verbs, points and bounds, bit for bit
  }
}

TEST_CASE("polygon() rejects a non-finite point as one command", "[path]") {
  const Point points[] = {{0, 0}, {1, 0}, {std::numeric_limits<double>::quiet_NaN(), 1}};
  PathBuilder builder;
  builder.move_to({5, 5}).polygon(points).line_to({9, 9});
  const Result<Path> path = std::move(builder).build();
  REQUIRE(!path.is_ok());
  CHECK(path.error().message.find("path command 1 (polygon)") != std::string::npos);
}

TEST_CASE("build() on a finished builder moves the same path out", "[path]") {
  PathBuilder builder;
  builder.move_to({0, 0}).cubic_to({1, 2}, {3, 4}, {5, 0}).close();
  const Result<Path> copied = builder.build();
  const Result<Path> moved = std::move(builder).build();
  REQUIRE(copied.is_ok());
  REQUIRE(moved.is_ok());
  CHECK(*moved == *copied);
}

TEST_CASE("the empty builder builds the empty path", "[path]") {
  const Result<Path> path = PathBuilder().build();
  REQUIRE(path.is_ok());
  CHECK(path->empty());
  CHECK(path->begin() == path->end());
  CHECK(path->bounds() == Rect{});
  CHECK(path->tight_bounds() == Rect{});
}

TEST_CASE("non-finite input is rejected with the index and name of the command", "[path]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    const char* expected;
    void (*apply)(PathBuilder&, double, double);
  };
  const Case cases[] = {
      {"path command 2 (line_to)",
       [](PathBuilder& b, double bad, double) {
         b.line_to({bad, 0});
       }},
      {"path command 2 (move_to)",
       [](PathBuilder& b, double bad, double) {
         b.move_to({0, bad});
       }},
      {"path command 2 (quad_to)",
       [](PathBuilder& b, double bad, double) {
         b.quad_to({bad, 1}, {2, 2});
       }},
      {"path command 2 (cubic_to)",
       [](PathBuilder& b, double bad, double) {
         b.cubic_to({0, 1}, {1, 1}, {bad, 0});
       }},
      {"path command 2 (conic_to)",
       [](PathBuilder& b, double bad, double) {
         b.conic_to({0, 1}, {1, bad}, 0.5);
       }},
      {"path command 2 (conic_to)",
       [](PathBuilder& b, double bad, double) {
         b.conic_to({0, 1}, {1, 1}, bad);
       }},
      {"path command 2 (arc)",
       [](PathBuilder& b, double bad, double) {
         b.arc({0, 0}, 1, 1, 0, 0, bad);
       }},
      {"path command 2 (svg_arc_to)",
       [](PathBuilder& b, double bad, double) {
         b.svg_arc_to(bad, 1, 0, false, true, {5, 5});
       }},
      {"path command 2 (rational_bezier_to)",
       [](PathBuilder& b, double bad, double) {
         const Point points[] = {{1, 1}, {2, 0}};
         const double weights[] = {1, bad, 1};
         b.rational_bezier_to(points, weights);
       }},
  };
  for (const double bad : {nan, inf, -inf}) {
    for (const Case& c : cases) {
      CAPTURE(c.expected, bad);
      PathBuilder builder;
      builder.move_to({0, 0}).line_to({1, 1});
      c.apply(builder, bad, 0);
      builder.line_to({3, 3});  // later commands do not replace the first error
      const Result<Path> path = builder.build();
      REQUIRE_FALSE(path.is_ok());
      CHECK(path.error().kind == ErrorKind::kInvalidArgument);
      CHECK_THAT(path.error().message, Catch::StartsWith(c.expected));
    }
  }
}

TEST_CASE("invalid weights, degrees and a missing current point are clear errors", "[path]") {
  SECTION("weight zero or negative") {
    for (const double w : {0.0, -1.0}) {
      const Result<Path> path = PathBuilder().move_to({0, 0}).conic_to({1, 1}, {2, 0}, w).build();
      REQUIRE_FALSE(path.is_ok());
      CHECK_THAT(path.error().message, Catch::Contains("weights must be finite and > 0"));
    }
  }
  SECTION("weights count does not match") {
    const Point points[] = {{1, 1}, {2, 0}};
    const double weights[] = {1, 1};  // needs 3: the current point has a weight too
    const Result<Path> path = PathBuilder().move_to({0, 0}).rational_bezier_to(points, weights).build();
    REQUIRE_FALSE(path.is_ok());
    CHECK_THAT(path.error().message, Catch::Contains("2 weights given for 3 control points"));
  }
  SECTION("degree above the limit") {
    const std::vector<Point> points(static_cast<std::size_t>(kMaxPathCurveDegree) + 1, Point{1, 1});
    const Result<Path> path = PathBuilder().move_to({0, 0}).bezier_to(points).build();
    REQUIRE_FALSE(path.is_ok());
    CHECK(path.error().kind == ErrorKind::kLimitExceeded);
    // ...and exactly at the limit it is accepted.
    const std::vector<Point> at_limit(static_cast<std::size_t>(kMaxPathCurveDegree), Point{1, 1});
    CHECK(PathBuilder().move_to({0, 0}).bezier_to(at_limit).build().is_ok());
  }
  SECTION("empty bezier_to") {
    const Result<Path> path = PathBuilder().move_to({0, 0}).bezier_to({}).build();
    REQUIRE_FALSE(path.is_ok());
    CHECK_THAT(path.error().message, Catch::StartsWith("path command 1 (bezier_to)"));
  }
  SECTION("drawing before any move_to") {
    const Result<Path> path = PathBuilder().line_to({1, 1}).build();
    REQUIRE_FALSE(path.is_ok());
    CHECK_THAT(path.error().message, Catch::Contains("path command 0 (line_to): there is no current point"));
  }
}

TEST_CASE("append adds curves exactly, continuing the contour only from the exact start", "[path]") {
  const Bezier quartic({{0, 0}, {1, 3}, {2, -1}, {3, 2}, {4, 0}});
  const RationalBezier rational({{4, 0}, {5, 2}, {6, 0}}, {0.5, 2.0, 1.25});
  const Bezier detached({{10, 10}, {11, 11}});
  const Result<Path> path = PathBuilder().append(quartic).append(rational).append(detached).build();
  REQUIRE(path.is_ok());
  CHECK(verbs_of(*path) == std::vector<PathVerb>{PathVerb::kMove, PathVerb::kBezier,
                                                 PathVerb::kRationalBezier, PathVerb::kMove,
                                                 PathVerb::kBezier});
  const std::vector<PathElement> e = elements_of(*path);
  CHECK(as_vector(e[1].points) == as_vector(quartic.points()));
  CHECK(as_vector(e[2].points) == as_vector(rational.points()));
  CHECK(std::vector<double>(e[2].weights.begin(), e[2].weights.end()) ==
        std::vector<double>(rational.weights().begin(), rational.weights().end()));
  CHECK(as_vector(e[4].points) == as_vector(detached.points()));
}

TEST_CASE("bounds hold every control point — tight bounds hug the curve", "[path]") {
  // A cubic whose control points overshoot: the control box is [0, 10] x [-10, 10], the curve reaches
  // y = ±10·(2/(3√3))·(3/2)... computed below by dense sampling instead of by formula.
  const Result<Path> path = PathBuilder().move_to({0, 0}).cubic_to({3, 10}, {7, -10}, {10, 0}).build();
  REQUIRE(path.is_ok());
  CHECK(path->bounds() == Rect{0, -10, 10, 10});
  const Rect tight = path->tight_bounds();
  const Bezier cubic({{0, 0}, {3, 10}, {7, -10}, {10, 0}});
  Rect sampled = Rect::from_point(cubic.eval(0));
  constexpr int kSamples = 100000;
  for (int i = 1; i <= kSamples; ++i) sampled.include(cubic.eval(static_cast<double>(i) / kSamples));
  // The true extremum lies within one sample step of a sample: |dy/dt| <= 3·20 = 60 per unit t, and at an
  // extremum the error is second order, so 60·(1e-5)² ≈ 1e-8 bounds the gap between tight and sampled.
  constexpr double kSamplingGap = 1e-7;
  CHECK(tight.contains({sampled.x0, sampled.y0}, 1e-12));
  CHECK(tight.contains({sampled.x1, sampled.y1}, 1e-12));
  CHECK(tight.y0 == Approx(sampled.y0).margin(kSamplingGap));
  CHECK(tight.y1 == Approx(sampled.y1).margin(kSamplingGap));
  CHECK(tight.y1 < 5.0);  // well inside the control box
}

TEST_CASE("transformed maps every verb exactly through the affine map", "[path]") {
  std::mt19937 rng(424242);
  std::uniform_real_distribution<double> coord(-50.0, 50.0);
  const Point quintic[] = {{1, 2}, {3, -4}, {5, 6}, {7, 0}, {8, 8}};
  const Point rational_points[] = {{9, 1}, {10, 4}};
  const double rational_weights[] = {1.5, 0.25, 2.0};
  PathBuilder builder;
  builder.move_to({0, 0})
      .line_to({1, 0})
      .quad_to({2, 3}, {3, 0})
      .cubic_to({4, 2}, {5, -2}, {6, 0})
      .conic_to({7, 3}, {8, 0}, 0.3)
      .bezier_to(quintic)
      .rational_bezier_to(rational_points, rational_weights)
      .close();
  const Path path = *builder.build();
  for (int trial = 0; trial < 20; ++trial) {
    const Affine m{coord(rng), coord(rng), coord(rng), coord(rng), coord(rng), coord(rng)};
    const Result<Path> moved = path.transformed(m);
    REQUIRE(moved.is_ok());
    REQUIRE(moved->verbs().size() == path.verbs().size());
    auto original = path.begin();
    for (const PathElement& element : *moved) {
      REQUIRE(element.points.size() == original->points.size());
      for (std::size_t i = 0; i < element.points.size(); ++i)
        CHECK(element.points[i] == m.apply(original->points[i]));
      CHECK(std::equal(element.weights.begin(), element.weights.end(), original->weights.begin(),
                       original->weights.end()));
      // Affine invariance of the curve itself (Ince, *Curves*): the image of a curve point is the transformed
      // curve's point at the same t. Both sides round at ~1e-16 relative of magnitudes up to ~50·50·2, so
      // 1e-9 absolute is generous yet far below any real discrepancy.
      if (element.is_rational() && element.points.size() > 1) {
        for (const double t : {0.1, 0.5, 0.77}) {
          const Point lhs = rational_de_casteljau(element.points, element.weights, t);
          const Point rhs = m.apply(rational_de_casteljau(original->points, original->weights, t));
          CHECK(lhs.x == Approx(rhs.x).margin(1e-9));
          CHECK(lhs.y == Approx(rhs.y).margin(1e-9));
        }
      }
      ++original;
    }
    for (const Point p : moved->points()) CHECK(moved->bounds().contains(p));
  }
  CHECK_FALSE(path.transformed(Affine{std::numeric_limits<double>::quiet_NaN(), 0, 0, 1, 0, 0}).is_ok());
  CHECK_FALSE(path.transformed(Affine::scale(1e308)).is_ok());  // 8·1e308 overflows to infinity
}

TEST_CASE("arc in centre form: exact circle conics joined to the current point", "[path][arc]") {
  const Point center{10, 20};
  constexpr double kRadius = 5.0;
  SECTION("no current point: the arc starts a contour at its start") {
    const Result<Path> path =
        PathBuilder().arc(center, kRadius, kRadius, 0, 0, 1.5 * std::numbers::pi).build();
    REQUIRE(path.is_ok());
    const std::vector<PathElement> e = elements_of(*path);
    REQUIRE(e.size() == 4);  // move + three quarter-turn conics (arc.h: at most 90 degrees each)
    CHECK(e[0].start.x == Approx(15));
    CHECK(e[0].start.y == Approx(20).margin(1e-12));
    for (std::size_t i = 1; i < e.size(); ++i) {
      CHECK(e[i].verb == PathVerb::kConic);
      for (const double t : {0.0, 0.3, 0.5, 0.9, 1.0}) {
        // Rounding of cos/sin and the homogeneous evaluation: ~1e-15 relative to the radius.
        CHECK(rational_de_casteljau(e[i].points, e[i].weights, t).distance(center) ==
              Approx(kRadius).margin(1e-12));
      }
    }
    CHECK(e.back().end.x == Approx(10).margin(1e-12));
    CHECK(e.back().end.y == Approx(15));  // angle 3π/2 on a y-down screen: above the centre
  }
  SECTION("with a current point: a line joins it to the arc's start") {
    const Result<Path> path = PathBuilder().move_to({0, 0}).arc(center, kRadius, kRadius, 0, 0, 0.5).build();
    REQUIRE(path.is_ok());
    CHECK(verbs_of(*path) == std::vector<PathVerb>{PathVerb::kMove, PathVerb::kLine, PathVerb::kConic});
  }
}
