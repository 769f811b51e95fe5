// The flatness bound on its own: it is an upper bound of the densely measured chord distance (sound), it
// never exceeds the plain convex-hull bound (the reference beside it), and for cubics and conics it is
// exact up to the rounding margin (tight) — the property that lets the flattener approach the optimum.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

// The bound is private to curves/ (it is not API); the test reaches it by path, as the flattener does.
#include "../../../curves/src/flatness_bound.h"
#include "hausdorff_measure.h"

namespace curvescan {
namespace {

/// Hausdorff distance between the curve and its chord, measured on `count` samples (exact point-segment
/// distances one way; the other way the chord's points are within max|d| of the curve, see the proof in
/// flatness_bound.h, so sampling the curve side suffices for a lower estimate of the bound's target).
template <class Eval>
double sampled_chord_distance(Eval eval, Point a, Point b, int count) {
  double worst = 0.0;
  for (int i = 0; i <= count; ++i) {
    worst = std::max(worst, testing::point_segment_distance(eval(static_cast<double>(i) / count), a, b));
  }
  return worst;
}

TEST_CASE("bound >= sampled distance, <= hull bound, and exact for degree <= 3", "[flatten][bound]") {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> coord(-100.0, 100.0);
  for (int i = 0; i < 3000; ++i) {
    const std::size_t degree = 1 + static_cast<std::size_t>(i % 6);
    std::vector<Point> ctrl(degree + 1);
    for (Point& p : ctrl) p = {coord(rng), coord(rng)};
    const double bound = detail::chord_distance_bound(ctrl, {});
    const double hull = detail::chord_distance_hull_bound(ctrl);
    // 20000 samples: |C''| <= 6·7·400 = 16800 for these sizes, so the sampled maximum of a smooth
    // extremum is low by at most 16800 / 20000^2 / 8 = 5e-6 (hausdorff_measure.h).
    const double sampled = sampled_chord_distance([&](double t) { return de_casteljau(ctrl, t); },
                                                  ctrl.front(), ctrl.back(), 20000);
    INFO("degree " << degree << " bound " << bound << " hull " << hull << " sampled " << sampled);
    CHECK(bound >= sampled);
    // Same frame, same margin: the exact range can only shrink the hull.
    CHECK(bound <= hull);
    if (degree <= 3) {
      // sqrt(max|d|^2 + max over^2) exceeds the true distance only when the curve overshoots an end of
      // the chord AND bulges sideways; the exactness claim is for max|d| and max over separately, so
      // compare with the sampled distance only when there is no overshoot (the common case).
      bool overshoots = false;
      const Vec2 chord = ctrl.back() - ctrl.front();
      for (int k = 0; k <= 200; ++k) {
        const double s = (de_casteljau(ctrl, k / 200.0) - ctrl.front()).dot(chord) / chord.length_squared();
        overshoots = overshoots || s < 0.0 || s > 1.0;
      }
      // 1e-4 absolute: the sampling resolution above (5e-6) plus the 1e-9 relative margin, with headroom.
      if (!overshoots) CHECK(bound <= sampled + 1e-4);
    }
  }
}

TEST_CASE("rational bound >= sampled distance — exact for conics", "[flatten][bound]") {
  std::mt19937_64 rng(1234);
  std::uniform_real_distribution<double> coord(-100.0, 100.0);
  std::uniform_real_distribution<double> log_weight(std::log(0.05), std::log(20.0));
  for (int i = 0; i < 2000; ++i) {
    const std::size_t degree = 1 + static_cast<std::size_t>(i % 4);
    std::vector<Point> ctrl(degree + 1);
    std::vector<double> weights(degree + 1);
    for (Point& p : ctrl) p = {coord(rng), coord(rng)};
    for (double& w : weights) w = std::exp(log_weight(rng));
    const double bound = detail::chord_distance_bound(ctrl, weights);
    // 20000 samples: the weights are within a factor 400 of each other, second derivatives stay below
    // ~1e8 here; 1e8 / 20000^2 / 8 = 0.03, so only the soundness check is strict and the tightness check
    // below allows that resolution.
    const double sampled = sampled_chord_distance(
        [&](double t) { return rational_de_casteljau(ctrl, weights, t); }, ctrl.front(), ctrl.back(), 20000);
    INFO("degree " << degree << " bound " << bound << " sampled " << sampled);
    CHECK(bound >= sampled);
    if (degree == 2) {
      bool overshoots = false;
      const Vec2 chord = ctrl.back() - ctrl.front();
      for (int k = 0; k <= 2000; ++k) {
        const Point p = rational_de_casteljau(ctrl, weights, k / 2000.0);
        const double s = (p - ctrl.front()).dot(chord) / chord.length_squared();
        overshoots = overshoots || s < 0.0 || s > 1.0;
      }
      if (!overshoots) CHECK(bound <= sampled + 0.05);
    }
  }
}

TEST_CASE("bound on degenerate pieces", "[flatten][bound]") {
  // Coincident points: zero. A closed loop (chord of length 0): the radius bound max|Q_i - Q_0|.
  CHECK(detail::chord_distance_bound(std::vector<Point>{{3, 4}, {3, 4}, {3, 4}}, {}) == 0.0);
  const double loop = detail::chord_distance_bound(std::vector<Point>{{0, 0}, {30, 40}, {0, 0}}, {});
  CHECK(loop >= 25.0);                 // the curve reaches (15, 20), 25 from the chord (a point)
  CHECK(loop <= 50.0 * (1.0 + 1e-6));  // radius bound: |(30, 40)| = 50, plus the 1e-9 margin
  // NaN in, NaN out.
  CHECK(std::isnan(detail::chord_distance_bound(std::vector<Point>{{0, 0}, {std::nan(""), 1}, {2, 0}}, {})));
}

}  // namespace
}  // namespace curvescan
