// The conic flattener's O(1) bound (curves/src/flatten_conic.h): sound, equal to the general exact bound
// of the split piece where it claims exactness, and the walk keeps flatten_rational's contract on arcs and
// sharp conics; it hands the curve to the general walk where its rounding analysis does not hold.
#include <algorithm>
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/curves/rational_bezier.h"
#include "hausdorff_measure.h"
// Private to curves/ (not API); reached by path, as flatness_bound_test does.
#include "../../../curves/src/flatness_bound.h"
#include "../../../curves/src/flatten_conic.h"
#include "../../../curves/src/flatten_split.h"

namespace curvescan {
namespace {

struct H {
  double x, y, w;
};

/// The sub-arc [a, b] of the conic by two homogeneous de Casteljau splits (the general walk's way).
void sub_arc(const std::vector<Point>& ctrl, const std::vector<double>& weights, double a, double b,
             std::vector<Point>& points, std::vector<double>& piece_weights) {
  std::vector<H> h(3), right(3), piece(3), scratch(3);
  for (std::size_t i = 0; i < 3; ++i) h[i] = {ctrl[i].x * weights[i], ctrl[i].y * weights[i], weights[i]};
  auto lerp_fn = [](H p, H q, double u) {
    return H{p.x + (q.x - p.x) * u, p.y + (q.y - p.y) * u, p.w + (q.w - p.w) * u};
  };
  detail::split_bezier<H>(h, a, {}, right, scratch, lerp_fn);
  detail::split_bezier<H>(right, (b - a) / (1.0 - a), piece, {}, scratch, lerp_fn);
  points.resize(3);
  piece_weights.resize(3);
  for (std::size_t i = 0; i < 3; ++i) {
    points[i] = {piece[i].x / piece[i].w, piece[i].y / piece[i].w};
    piece_weights[i] = piece[i].w;
  }
}

TEST_CASE("conic bound is sound and equals the general exact bound of the split piece", "[flatten][conic]") {
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> coord(-100.0, 100.0), unit(0.0, 1.0);
  std::uniform_real_distribution<double> log_weight(std::log(0.05), std::log(20.0));
  int compared = 0;
  for (int i = 0; i < 2000; ++i) {
    const std::vector<Point> ctrl{
        {coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}};
    const std::vector<double> weights{std::exp(log_weight(rng)), std::exp(log_weight(rng)),
                                      std::exp(log_weight(rng))};
    double a = unit(rng), b = unit(rng);
    if (a > b) std::swap(a, b);
    if (!(b - a > 1e-3)) continue;
    std::vector<Point> points;
    std::vector<double> piece_weights;
    sub_arc(ctrl, weights, a, b, points, piece_weights);
    const double closed = detail::conic_arc_chord_bound(ctrl, weights, a, b);
    const double general = detail::chord_distance_bound(points, piece_weights);
    // 20000 samples of the whole conic's parameter mapped onto [a, b]: soundness is strict (a sampled
    // distance can only be lower than the true maximum).
    double sampled = 0.0;
    for (int k = 0; k <= 20000; ++k) {
      const Point p = rational_de_casteljau(ctrl, weights, a + (b - a) * k / 20000.0);
      sampled = std::max(sampled, testing::point_segment_distance(p, points.front(), points.back()));
    }
    INFO("#" << i << " a " << a << " b " << b << " closed " << closed << " general " << general << " sampled "
             << sampled);
    CHECK(closed >= sampled);
    // Where the closed form claims exactness (chord trusted, no overshoot: flatten_conic.h (i)-(iii)) it
    // must equal the general exact bound up to both margins: 1e-9 of R (<= 300 here) each, plus 16 ulps of
    // 100 times R/L <= 1e4: 1e-5 + 5e-9 covers it with headroom.
    const Vec2 chord = points[2] - points[0], handle = points[1] - points[0];
    const double length = chord.length(), radius = std::max(length, handle.length());
    const double along = chord.dot(handle) / length;
    if (length >= 1e-4 * radius && along >= 0.0 && along <= length) {
      CHECK(closed == Approx(general).margin(1e-5));
      ++compared;
    }
  }
  CHECK(compared > 500);  // the equality was really exercised
}

double measured_ratio(const std::vector<Point>& ctrl, const std::vector<double>& weights, double tolerance,
                      std::size_t& segments) {
  std::vector<Point> out{ctrl.front()};
  REQUIRE(flatten_rational(ctrl, weights, tolerance, out) == FlattenOutcome::kOk);
  REQUIRE(out.back() == ctrl.back());
  segments = out.size() - 1;
  double scale = 0.0;
  for (const Point& p : ctrl) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  // Slack: the measurement's floating-point noise, 1e-12 of the largest coordinate (as
  // flatten_corpus_test.cpp); the flattener's margins sit inside its bound.
  const double slack = 1e-12 * scale;
  const testing::Measurement m = testing::measure_rational(ctrl, weights, tolerance, out);
  INFO("segments " << segments << " curve->polyline " << m.curve_to_polyline << " polyline->curve "
                   << m.polyline_to_curve);
  CHECK(m.curve_to_polyline <= tolerance + slack);
  CHECK(m.polyline_to_curve <= tolerance + slack);
  CHECK(m.vertex_to_curve <= tolerance / 100.0 + slack);
  return m.hausdorff() / tolerance;
}

TEST_CASE("conic walk: arcs within tolerance and near the fewest segments", "[flatten][conic]") {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> angle(0.01, 0.99 * std::numbers::pi);
  std::uniform_real_distribution<double> log_radius(std::log(0.5), std::log(5000.0));
  for (int i = 0; i < 200; ++i) {
    const double tolerance = std::array{0.01, 0.1, 0.25, 1.0}[static_cast<std::size_t>(i) % 4];
    const double theta = angle(rng), radius = std::exp(log_radius(rng)), start = 2.0 * angle(rng);
    const Point center{300.0, -200.0};
    auto on_circle = [&](double a, double r) { return center + Vec2{std::cos(a), std::sin(a)} * r; };
    const std::vector<Point> arc{on_circle(start, radius),
                                 on_circle(start + theta / 2, radius / std::cos(theta / 2)),
                                 on_circle(start + theta, radius)};
    INFO("arc #" << i << " theta " << theta << " radius " << radius << " tolerance " << tolerance);
    std::size_t segments = 0;
    measured_ratio(arc, {1.0, std::cos(theta / 2), 1.0}, tolerance, segments);
    // Fewest segments of a circular arc: chords of angle 2·acos(1 - tol/r) (sagitta = tol). Pieces are
    // accepted at >= 90 % of the tolerance (>= 95 % of the longest), hence 10 % + 1.
    const double fewest =
        tolerance >= radius ? 1.0 : std::ceil(theta / (2.0 * std::acos(1.0 - tolerance / radius)));
    CHECK(static_cast<double>(segments) <= 1.1 * fewest + 1.0);
  }
}

TEST_CASE("sharp and flat conics keep the contract", "[flatten][conic][pathological]") {
  const std::vector<Point> ctrl{{0, 0}, {100, 100}, {200, 0}};
  for (const double w : {1e-6, 0.05, 0.7, 1.5, 8.0, 1e3, 1e6}) {
    for (const double tolerance : {0.01, 0.1, 1.0}) {
      INFO("middle weight " << w << " tolerance " << tolerance);
      std::size_t segments = 0;
      measured_ratio(ctrl, {1.0, w, 1.0}, tolerance, segments);
      measured_ratio(ctrl, {0.3, w, 2.0}, tolerance, segments);
    }
  }
  std::size_t segments = 0;
  measured_ratio({{0, 0}, {100, 100}, {0, 0}}, {1.0, 2.0, 1.0}, 0.1, segments);   // closed (chord 0)
  measured_ratio({{0, 0}, {300, 0}, {-100, 0}}, {1.0, 2.0, 0.5}, 0.1, segments);  // collinear, doubling back
}

TEST_CASE("the general walk takes conics outside the closed form's rounding analysis", "[flatten][conic]") {
  std::vector<Point> out;
  const std::vector<double> weights{1.0, 0.5, 1.0};
  // Near 1e15 one ulp is 0.125: 16 ulps are far above 1.6e-5 of a 1e-6 tolerance.
  const std::vector<Point> coarse{{1e15, 1e15}, {1e15 + 64, 1e15 + 32}, {1e15 + 128, 1e15}};
  CHECK_FALSE(detail::flatten_conic(coarse, weights, 1e-6, out).has_value());
  // Weights 1e-120 apart: their products would underflow.
  CHECK_FALSE(detail::flatten_conic(std::vector<Point>{{0, 0}, {1, 1}, {2, 0}},
                                    std::vector<double>{1.0, 1e-120, 1.0}, 0.1, out)
                  .has_value());
  CHECK(out.empty());  // nothing appended when declining
  const std::vector<Point> ordinary{{0, 0}, {30, 40}, {60, 0}};
  CHECK(detail::flatten_conic(ordinary, weights, 0.1, out) == FlattenOutcome::kOk);
  CHECK(out.back() == ordinary.back());
}

}  // namespace
}  // namespace curvescan
