// The closed-form quadratic flattener (curves/src/flatten_quadratic.h): its bound is sound and equals the
// general exact bound of the split piece (no split needed), its walk keeps the contract of flatten_bezier
// on glyph-like and degenerate parabolas with no more segments than the general walk, and it hands the
// curve to the general walk where its rounding analysis does not hold.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/flatten.h"
#include "hausdorff_measure.h"
#include "sub_arc_measure.h"
// Private to curves/ (not API); reached by path, as flatness_bound_test does.
#include "../../../curves/src/flatness_bound.h"
#include "../../../curves/src/flatten_quadratic.h"

namespace curvescan {
namespace {

using testing::overshoots;
using testing::sampled_chord_distance;
using testing::sub_arc;


TEST_CASE("closed-form quadratic bound is sound and equals the general exact bound of the split piece",
          "[flatten][quadratic]") {
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> coord(-100.0, 100.0), unit(0.0, 1.0);
  int compared = 0;
  for (int i = 0; i < 3000; ++i) {
    std::vector<Point> ctrl{{coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}};
    if (i % 3 == 0) {
      // Thin parabolas, where |V(m)| is small near the vertex (the Wang branch of the bound).
      ctrl[2] = ctrl[0] + Vec2{1e-3 * coord(rng), 1e-3 * coord(rng)};
    }
    double a = unit(rng), b = unit(rng);
    if (a > b) std::swap(a, b);
    if (!(b - a > 1e-3)) continue;
    const std::vector<Point> piece = sub_arc(ctrl, a, b);
    const double closed = detail::quadratic_arc_chord_bound(ctrl[0], ctrl[1], ctrl[2], a, b);
    const double general = detail::chord_distance_bound(piece, {});
    // 20000 samples: |C''| of the piece is <= 2|D| <= 1600, so the sampled maximum of a smooth extremum
    // is low by at most 1600 / 20000^2 / 8 = 5e-7.
    const double sampled = sampled_chord_distance(piece, 20000);
    INFO("#" << i << " a " << a << " b " << b << " closed " << closed << " general " << general << " sampled "
             << sampled);
    CHECK(closed >= sampled);
    // Where the closed form trusts the chord direction (|V(m)| >= 1e-4·(|E| + |D|), flatten_quadratic.h),
    // both are exact up to their margins: the general one 1e-9 of the piece's radius (<= 300 here), the
    // closed form 2e-9·h·(|E| + |D|) (<= 1.2e-6) plus 16 ulps of 100; 1e-5 covers both with headroom.
    // The closed form takes the smaller of (B) and Wang's bound, so it may only be lower, and only when
    // the piece overshoots an end of its chord (otherwise (B) is the exact distance). Elsewhere it is
    // Wang's bound h^2|D|/4: sound (checked above) but not tight.
    const Vec2 e = ctrl[1] - ctrl[0], d = (ctrl[2] - ctrl[1]) - (ctrl[1] - ctrl[0]);
    const double speed = (e + d * (0.5 * (a + b))).length();
    if (speed < 1e-4 * (e.length() + d.length())) {
      CHECK(closed <= 0.25 * d.length() * (b - a) * (b - a) + 1e-5);
      continue;
    }
    CHECK(closed <= general + 1e-5);
    if (!overshoots(piece)) {
      CHECK(closed >= general - 1e-5);
      ++compared;
    }
  }
  CHECK(compared > 1000);  // the equality was really exercised
}

struct WalkResult {
  std::size_t segments = 0;
  double worst_ratio = 0.0;  // measured Hausdorff / tolerance
};

// Slack on "measured <= tolerance": the measurement's own floating-point noise, 1e-12 of the largest
// coordinate (as flatten_corpus_test.cpp); the flattener's margins sit inside its bound.
WalkResult check_walk(const std::vector<Point>& ctrl, double tolerance, const std::string& what) {
  std::vector<Point> out{ctrl.front()};
  INFO(what << " tolerance " << tolerance);
  REQUIRE(flatten_bezier(ctrl, tolerance, out) == FlattenOutcome::kOk);
  REQUIRE(out.back() == ctrl.back());
  double scale = 0.0;
  for (const Point& p : ctrl) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  const double slack = 1e-12 * scale;
  const testing::Measurement m = testing::measure_bezier(ctrl, tolerance, out);
  INFO("segments " << out.size() - 1 << " curve->polyline " << m.curve_to_polyline << " polyline->curve "
                   << m.polyline_to_curve);
  CHECK(m.curve_to_polyline <= tolerance + slack);
  CHECK(m.polyline_to_curve <= tolerance + slack);
  CHECK(m.vertex_to_curve <= tolerance / 100.0 + slack);
  return {out.size() - 1, m.hausdorff() / tolerance};
}

/// The same curve as a cubic (degree elevation, Ince, *Curves*): flatten_bezier walks it with the general
/// exact bound, the reference the closed form is held to.
std::vector<Point> elevated(const std::vector<Point>& q) {
  return {q[0], q[0] + (q[1] - q[0]) * (2.0 / 3.0), q[2] + (q[1] - q[2]) * (2.0 / 3.0), q[2]};
}

TEST_CASE("glyph-like quadratics: within tolerance, no more segments than the general walk",
          "[flatten][quadratic]") {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const double size : {4.0, 30.0, 500.0}) {
    std::size_t closed_segments = 0, general_segments = 0;
    double worst = 0.0;
    for (int i = 0; i < 300; ++i) {
      const double tolerance = std::array{0.01, 0.1, 0.25, 1.0}[static_cast<std::size_t>(i) % 4];
      const Point p0{size * unit(rng), size * unit(rng)};
      const std::vector<Point> quad{p0, p0 + Vec2{size * unit(rng), size * unit(rng)},
                                    p0 + Vec2{size * unit(rng), -size * unit(rng)}};
      const WalkResult r = check_walk(quad, tolerance, "quadratic in a box of " + std::to_string(size));
      closed_segments += r.segments;
      worst = std::max(worst, r.worst_ratio);
      std::vector<Point> reference;
      REQUIRE(flatten_bezier(elevated(quad), tolerance, reference) == FlattenOutcome::kOk);
      general_segments += reference.size();
    }
    INFO("box " << size << " closed form " << closed_segments << " general walk " << general_segments);
    CHECK(closed_segments <= general_segments);
    // Pieces aim at 99.5 % of the tolerance: the worst one must use most of it (not a uselessly short walk).
    CHECK(worst >= 0.9);
  }
}

TEST_CASE("degenerate and extreme quadratics keep the contract", "[flatten][quadratic][pathological]") {
  const std::vector<std::pair<std::string, std::vector<Point>>> cases = {
      {"collinear, doubling back", {{0, 0}, {300, 0}, {-100, 0}}},
      {"collinear, back to the start", {{0, 0}, {100, 50}, {0, 0}}},
      {"first handle coincident", {{0, 0}, {0, 0}, {200, 100}}},
      {"thin parabola, sharp vertex", {{0, 0}, {1000, 1e-3}, {0, 2e-3}}},
      {"middle point far away", {{0, 0}, {1e5, 0}, {0, 1}}},
      {"line with 1e-14 noise", {{0, 0}, {100, 1e-14}, {200, 0}}},
      {"tiny 1e-6", {{0, 0}, {3e-6, 1e-6}, {1e-6, 0}}},
      {"huge 1e6", {{0, 0}, {3e6, 1e6}, {1e6, 0}}},
      {"far from the origin", {{1e6, 1e6}, {1e6 + 300, 1e6 + 100}, {1e6 + 100, 1e6}}},
  };
  for (const auto& [name, ctrl] : cases) {
    for (const double tolerance : {0.01, 0.1, 0.25, 1.0}) check_walk(ctrl, tolerance, name);
  }
}

TEST_CASE("the general walk takes quadratics outside the closed form's rounding analysis",
          "[flatten][quadratic]") {
  std::vector<Point> out;
  // Near 1e15 one ulp is 0.125: 16 ulps are far above 1.6e-5 of a 1e-6 tolerance.
  const std::vector<Point> coarse{{1e15, 1e15}, {1e15 + 64, 1e15 + 32}, {1e15 + 128, 1e15}};
  CHECK_FALSE(detail::flatten_quadratic(coarse, 1e-6, out).has_value());
  // Coordinates beyond 1e100: squares would overflow.
  const std::vector<Point> vast{{0, 0}, {3e120, 1e120}, {1e120, 0}};
  CHECK_FALSE(detail::flatten_quadratic(vast, 1e118, out).has_value());
  CHECK(out.empty());  // nothing appended when declining
  // ... and flatten_bezier still flattens them through the general walk.
  CHECK(flatten_bezier(vast, 1e118, out) == FlattenOutcome::kOk);
  CHECK(out.back() == vast.back());
  // An ordinary quadratic is taken.
  out.clear();
  const std::vector<Point> ordinary{{0, 0}, {30, 40}, {60, 0}};
  CHECK(detail::flatten_quadratic(ordinary, 0.1, out) == FlattenOutcome::kOk);
  CHECK(out.back() == ordinary.back());
}

}  // namespace
}  // namespace curvescan
