// The closed-form cubic flattener (curves/src/flatten_cubic.h): its bound is sound (never below the
// densely sampled distance, never below the general exact bound of the split piece) and nearly tight
// (within the 1.174 worst case of its across-chord term where it trusts the chord), and its walk keeps the
// contract of flatten_bezier — zero violations against dense sampling on random, S-shaped, cusped,
// near-degenerate, huge and tiny cubics — with nearly the segments of a walk on the exact bound.
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
#include "../../../curves/src/flatten_cubic.h"
#include "../../../curves/src/flatten_step_search.h"

namespace curvescan {
namespace {

using testing::overshoots;
using testing::sampled_chord_distance;
using testing::sub_arc;


TEST_CASE("closed-form cubic bound is sound and within its worst-case factor of the exact bound",
          "[flatten][cubic]") {
  std::mt19937_64 rng(2027);
  std::uniform_real_distribution<double> coord(-100.0, 100.0), unit(0.0, 1.0);
  int compared = 0;
  double worst_ratio = 0.0;
  for (int i = 0; i < 3000; ++i) {
    std::vector<Point> ctrl{{coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)},
                            {coord(rng), coord(rng)}};
    if (i % 4 == 0) ctrl[3] = ctrl[0] + (ctrl[1] - ctrl[2]);  // a cusp at t = 1/2
    if (i % 4 == 1) ctrl[3] = ctrl[0] + Vec2{1e-3 * coord(rng), 1e-3 * coord(rng)};  // a nearly closed loop
    double a = unit(rng), b = unit(rng);
    if (a > b) std::swap(a, b);
    if (i % 3 == 0) b = a + (b - a) * 0.05;  // short pieces, the walk's usual case
    if (!(b - a > 1e-4)) continue;
    const std::vector<Point> piece = sub_arc(ctrl, a, b);
    const double closed = detail::cubic_arc_chord_bound(ctrl[0], ctrl[1], ctrl[2], ctrl[3], a, b);
    const double general = detail::chord_distance_bound(piece, {});
    // 20000 samples: |C''| of the piece is <= 6·max|second difference| <= 6·800 = 4800, so a smooth
    // maximum is sampled low by at most 4800 / 20000^2 / 8 = 1.5e-6.
    const double sampled = sampled_chord_distance(piece, 20000);
    INFO("#" << i << " a " << a << " b " << b << " closed " << closed << " general " << general << " sampled "
             << sampled);
    CHECK(closed >= sampled);
    // The general bound is the exact distance plus 1e-9 of the piece's radius (<= 600 here), so a sound
    // bound is never below it by more than that margin; 1e-5 is far above it and far below any tolerance.
    CHECK(closed >= general - 1e-5);
    // Tightness where the closed form uses the chord frame, the piece does not overshoot (then the general
    // bound is the exact max|d|) and the closed form's along bracket c = 3h^2|u·K(m)| + h^3|u·J|/2 stays
    // below L (then its overshoot term is 0, flatten_cubic.h (ii)): the across term is at most 1.174 times
    // the exact max|d| (the worst case over the ratio of u x B'' at the two ends, (i)). Long pieces with
    // a bulge larger than their chord get a spurious overshoot, sound but looser; the walk's pieces are
    // short. 1e-5 covers both margins.
    const double h = b - a;
    const Vec2 d0 = (ctrl[0] - ctrl[1]) + (ctrl[2] - ctrl[1]), d1 = (ctrl[1] - ctrl[2]) + (ctrl[3] - ctrl[2]);
    const Vec2 k = d0 + (d1 - d0) * (0.5 * (a + b));
    const Vec2 chord_vector = piece.back() - piece.front();
    const double chord = chord_vector.length();
    const Vec2 u = chord_vector / chord;
    const double bulge = 3.0 * h * h * std::abs(u.dot(k)) + 0.5 * h * h * h * std::abs(u.dot(d1 - d0));
    const double scale = 3.0 * ((ctrl[1] - ctrl[0]).length() + (ctrl[2] - ctrl[1]).length() +
                                (ctrl[3] - ctrl[2]).length());
    if (chord >= 1e-3 * h * scale && bulge < chord && !overshoots(piece)) {
      CHECK(closed <= 1.175 * general + 1e-5);
      if (general > 1e-3) worst_ratio = std::max(worst_ratio, closed / general);
      ++compared;
    }
  }
  INFO("worst closed / general " << worst_ratio);
  CHECK(compared > 1000);  // the comparison was really exercised
  CHECK(worst_ratio > 1.0);  // and the closed form is a different (looser) number, not the same code
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

/// The reference: the general walk's steps (flatten.cpp) on the exact bound of the de Casteljau-split
/// piece, with the same step search. Its segment count is what the closed form is compared with.
std::size_t exact_bound_walk_segments(const std::vector<Point>& ctrl, double tolerance) {
  double t0 = 0.0, guess = 1.0;
  for (std::size_t segments = 1;; ++segments) {
    detail::StepSearch search(guess, tolerance);
    for (bool done = false; !done;) {
      const double u = search.length();
      const double t1 = u >= 1.0 ? 1.0 : t0 + u * (1.0 - t0);
      done = search.record(detail::chord_distance_bound(sub_arc(ctrl, t0, t1), {}));
    }
    const double u = search.accepted();
    const double t1 = t0 + u * (1.0 - t0);
    if (u >= 1.0 || !(t1 < 1.0)) return segments;
    guess = (t1 - t0) * detail::StepSearch::predicted_growth(search.accepted_error(), tolerance) / (1.0 - t1);
    t0 = std::max(t1, std::nextafter(t0, 2.0));
  }
}

TEST_CASE("seeded random, S-shaped and cusped cubics: within tolerance, segments near the exact-bound walk",
          "[flatten][cubic]") {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> coord(0.0, 512.0), unit(0.0, 1.0);
  for (int family = 0; family < 3; ++family) {
    std::size_t closed_segments = 0, exact_segments = 0;
    double worst = 0.0;
    for (int i = 0; i < 120; ++i) {
      const double tolerance = std::array{0.01, 0.1, 0.25, 1.0}[static_cast<std::size_t>(i) % 4];
      std::vector<Point> ctrl;
      if (family == 0) {
        ctrl = {{coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}};
      } else if (family == 1) {
        const double w = 50.0 + 450.0 * unit(rng), h = 20.0 + 230.0 * unit(rng);
        ctrl = {{0, 0}, {w * unit(rng), h}, {w - w * unit(rng), -h}, {w, 0}};
      } else {
        const Point p0{coord(rng), coord(rng)}, p1{coord(rng), coord(rng)}, p2{coord(rng), coord(rng)};
        ctrl = {p0, p1, p2, p0 + (p1 - p2)};  // C'(1/2) = 0: a cusp
      }
      const WalkResult r = check_walk(ctrl, tolerance, "family " + std::to_string(family) + " #" + std::to_string(i));
      closed_segments += r.segments;
      worst = std::max(worst, r.worst_ratio);
      exact_segments += exact_bound_walk_segments(ctrl, tolerance);
    }
    INFO("family " << family << " closed form " << closed_segments << " exact-bound walk " << exact_segments);
    // The goal of the closed form: at most 10 % more segments than the exact bound (measured +0.5..2 %).
    CHECK(closed_segments <= exact_segments * 11 / 10);
    // The walk uses most of the tolerance somewhere (not a uselessly short walk).
    CHECK(worst >= 0.9);
  }
}

TEST_CASE("near-degenerate, huge and tiny cubics keep the contract", "[flatten][cubic][pathological]") {
  const std::vector<std::pair<std::string, std::vector<Point>>> cases = {
      {"collinear, doubling back", {{0, 0}, {300, 0}, {-100, 0}, {200, 0}}},
      {"closed loop", {{0, 0}, {300, 200}, {-300, 200}, {0, 0}}},
      {"nearly closed loop", {{0, 0}, {300, 200}, {-300, 200}, {1e-9, 0}}},
      {"both handles coincident with the ends", {{0, 0}, {0, 0}, {200, 100}, {200, 100}}},
      {"coincident handles", {{0, 0}, {100, 100}, {100, 100}, {200, 0}}},
      {"all points coincident but one", {{5, 5}, {5, 5}, {5, 5}, {300, 7}}},
      {"cusp at an end", {{0, 0}, {0, 0}, {100, 200}, {200, 0}}},
      {"nearly a cusp", {{0, 0}, {200, 200}, {0, 200 + 1e-7}, {200, 0}}},
      {"inflection, nearly straight", {{0, 0}, {100, 1e-3}, {200, -1e-3}, {300, 0}}},
      {"line with 1e-14 noise", {{0, 0}, {100, 1e-14}, {200, -1e-14}, {300, 0}}},
      {"middle points far away", {{0, 0}, {1e5, 0}, {-1e5, 1}, {0, 1}}},
      {"tiny 1e-6", {{0, 0}, {3e-6, 1e-6}, {-1e-6, 2e-6}, {1e-6, 0}}},
      {"far from the origin", {{1e6, 1e6}, {1e6 + 300, 1e6 + 100}, {1e6 - 100, 1e6 + 200}, {1e6 + 100, 1e6}}},
  };
  for (const auto& [name, ctrl] : cases) {
    for (const double tolerance : {0.01, 0.1, 0.25, 1.0}) check_walk(ctrl, tolerance, name);
  }
  // 1e9 coordinates: at tolerance 1e3 the closed form takes it (16 ulps of 3e9 = 1.1e-5 <= 1.6e-5 of 1e3),
  // at 10 the general walk (1.1e-5 > 1.6e-4). Finer tolerances would need ~1e5+ segments, too many for the
  // dense measurement's budget; the rounding analysis is relative, so the scale is what is tested.
  std::vector<Point> out;
  const std::vector<Point> huge{{0, 0}, {3e9, 1e9}, {-1e9, 2e9}, {1e9, 0}};
  REQUIRE(detail::flatten_cubic(huge, 1e3, out).has_value());
  check_walk(huge, 1e3, "huge 1e9, closed form");
  check_walk(huge, 1e4, "huge 1e9, closed form, coarse");
  check_walk(huge, 10.0, "huge 1e9, tolerance 10");
}

TEST_CASE("the general walk takes cubics outside the closed form's rounding analysis", "[flatten][cubic]") {
  std::vector<Point> out;
  // Near 1e15 one ulp is 0.125: 16 ulps are far above 1.6e-5 of a 1e-6 tolerance.
  const std::vector<Point> coarse{{1e15, 1e15}, {1e15 + 64, 1e15 + 32}, {1e15 + 96, 1e15 - 32}, {1e15 + 128, 1e15}};
  CHECK_FALSE(detail::flatten_cubic(coarse, 1e-6, out).has_value());
  // Coordinates beyond 1e100: squares would overflow.
  const std::vector<Point> vast{{0, 0}, {3e120, 1e120}, {-1e120, 2e120}, {1e120, 0}};
  CHECK_FALSE(detail::flatten_cubic(vast, 1e118, out).has_value());
  CHECK(out.empty());  // nothing appended when declining
  // ... and flatten_bezier still flattens them through the general walk.
  CHECK(flatten_bezier(vast, 1e118, out) == FlattenOutcome::kOk);
  CHECK(out.back() == vast.back());
  // An ordinary cubic is taken, and its vertices are de Casteljau points of the original control points.
  out.clear();
  const std::vector<Point> ordinary{{0, 0}, {30, 40}, {60, -40}, {90, 0}};
  REQUIRE(detail::flatten_cubic(ordinary, 0.1, out) == FlattenOutcome::kOk);
  CHECK(out.back() == ordinary.back());
  CHECK(out.size() > 2);
}

TEST_CASE("the cubic walk honours max_segments and NaN", "[flatten][cubic]") {
  const std::vector<Point> ctrl{{0, 0}, {300, 400}, {600, -400}, {900, 0}};
  std::vector<Point> out;
  CHECK(flatten_bezier(ctrl, 0.01, out, 3) == FlattenOutcome::kSegmentLimit);
  CHECK(out.size() == 3);  // two vertices, then the end point
  CHECK(out.back() == ctrl.back());
  CHECK(std::isnan(detail::cubic_arc_chord_bound(ctrl[0], {std::nan(""), 0}, ctrl[2], ctrl[3], 0.0, 0.5)));
}

}  // namespace
}  // namespace curvescan
