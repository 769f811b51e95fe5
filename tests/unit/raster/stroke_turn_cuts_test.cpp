// The stroker's cuts (geometry/stroker_flatten.cpp): a polynomial curve is cut where its tangent would
// turn by more than max_turn along a piece, judged on the piece's exact turn (turn_within), not only on its
// control polygon's cone. What the outline's bound needs (docs/stroking.md, error budget): along every
// piece, hence every chord, any two true tangents differ by at most max_turn.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "curvescan/raster/path.h"
#include "curvescan/raster/path_builder.h"
#include "geometry/stroke_contour.h"

using namespace curvescan;
using namespace curvescan::detail;

namespace {

Vec2 cubic_derivative(const Point* p, double t) {
  const double s = 1.0 - t;
  const Vec2 e0 = p[1] - p[0], e1 = p[2] - p[1], e2 = p[3] - p[2];
  return e0 * (s * s) + e1 * (2 * s * t) + e2 * (t * t);
}

// The widest angle between the piece's tangent at its start and at 2001 parameters along it (the piece's
// control points as kept for the dasher: every weight 1 for a polynomial curve).
double widest_turn(std::span<const HomogeneousPoint> control) {
  REQUIRE(control.size() == 4);
  Point p[4];
  for (int i = 0; i < 4; ++i) p[i] = {control[i].x / control[i].w, control[i].y / control[i].w};
  const Vec2 first = cubic_derivative(p, 0.0);
  double widest = 0.0;
  for (int i = 1; i <= 2000; ++i) {
    const Vec2 d = cubic_derivative(p, i / 2000.0);
    widest = std::max(widest, std::abs(std::atan2(first.cross(d), first.dot(d))));
  }
  return widest;
}

std::vector<FlatContour> flatten_cubic(const std::array<Point, 4>& p, double max_turn) {
  PathBuilder builder;
  builder.move_to(p[0]).cubic_to(p[1], p[2], p[3]);
  const Path path = *builder.build();
  StrokeCurveCuts cuts;
  cuts.max_turn = max_turn;
  cuts.min_piece_length = 0.025;
  cuts.keep_pieces = true;
  std::vector<FlatContour> out;
  REQUIRE(flatten_for_stroke(path, 0.05, cuts, out).is_ok());
  return out;
}

/// The usual cubic of a circle arc of radius `r` from angle 0 to `angle` (handles 4/3·tan(angle/4) long).
std::array<Point, 4> circle_arc(double angle, double r) {
  const double k = 4.0 / 3.0 * std::tan(angle / 4.0);
  return {Point{r, 0.0}, Point{r, r * k},
          Point{r * (std::cos(angle) + k * std::sin(angle)), r * (std::sin(angle) - k * std::cos(angle))},
          Point{r * std::cos(angle), r * std::sin(angle)}};
}

}  // namespace

TEST_CASE("stroke cuts: a circle arc turning by less than max_turn is one piece", "[stroke][cuts]") {
  // An arc of 0.9·Δ as a cubic (Δ = 0.141, the benchmark's 20 px stroke at tolerance 0.1): its control
  // polygon's last edge points 0.9·Δ away from the first, outside the cone of Δ/2 about it, so the cone
  // test alone cut it in two; its tangent turns by 0.9·Δ only.
  const double delta = 0.141, angle = 0.9 * delta, r = 100.0;
  const std::vector<FlatContour> out = flatten_cubic(circle_arc(angle, r), delta);
  REQUIRE(out.size() == 1);
  CHECK(out[0].piece_ends.size() == 1);
  CHECK(widest_turn(out[0].piece(0)) <= delta);
}

TEST_CASE("stroke cuts: a circle arc turning by 2.5 max_turn is cut into the fewest pieces",
          "[stroke][cuts]") {
  // Cut where the tangent has turned by max_turn (exact_turn_cut): three pieces, where halving made four
  // (1.25·Δ per half is still too much, so each half was halved again).
  const double delta = 0.141, angle = 2.5 * delta, r = 100.0;
  const std::vector<FlatContour> out = flatten_cubic(circle_arc(angle, r), delta);
  REQUIRE(out.size() == 1);
  CHECK(out[0].piece_ends.size() == 3);
  for (std::int32_t k_piece = 0; k_piece < 3; ++k_piece) CHECK(widest_turn(out[0].piece(k_piece)) <= delta);
}

TEST_CASE("stroke cuts: every piece of random cubics turns by at most max_turn", "[stroke][cuts]") {
  // Seeded random cubics (loops, inflections, near-cusps) at two turn bounds: along every piece the true
  // tangent stays within max_turn of its start (sampled at 2001 parameters), except on pieces shorter than
  // the piece floor (min_piece_length: cusps). Margin 1e-9 rad: the cut rule's own relative margin.
  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> coordinate(0.0, 100.0);
  int pieces = 0, checked = 0;
  for (const double max_turn : {0.141, 0.6}) {
    for (int c = 0; c < 300; ++c) {
      std::array<Point, 4> p;
      for (Point& q : p) q = {coordinate(rng), coordinate(rng)};
      const std::vector<FlatContour> out = flatten_cubic(p, max_turn);
      REQUIRE(out.size() == 1);
      for (std::size_t k = 0; k < out[0].piece_ends.size(); ++k) {
        const std::span<const HomogeneousPoint> control = out[0].piece(static_cast<std::int32_t>(k));
        double polygon = 0.0;
        for (std::size_t i = 0; i + 1 < control.size(); ++i)
          polygon += std::hypot(control[i + 1].x - control[i].x, control[i + 1].y - control[i].y);
        ++pieces;
        if (polygon <= 0.025) continue;  // the piece floor: a cusp's piece is not cut further
        ++checked;
        INFO("cubic " << c << " piece " << k << " max_turn " << max_turn);
        CHECK(widest_turn(control) <= max_turn + 1e-9);
      }
    }
  }
  CHECK(checked > 1000);
  CHECK(pieces >= checked);
}
