// The flattener's contract on a seeded random corpus and on pathological curves: the measured Hausdorff
// distance between curve and polyline never exceeds the tolerance, every vertex is on the curve, and the
// last vertex is exactly the end point. Measurement method and its resolution: hausdorff_measure.h.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "hausdorff_measure.h"

namespace curvescan {
namespace {

constexpr std::array<double, 4> kTolerances = {0.01, 0.1, 0.25, 1.0};

// Slack on "measured <= tolerance": the measurement's own floating-point noise, a few ulps of the
// coordinates (1e-12 relative is ~5000 ulps, far above it). The flattener keeps 1e-9 of each piece's
// size as margin inside the bound, so a real violation would not hide in this slack.
double slack(std::span<const Point> ctrl) {
  double scale = 0.0;
  for (const Point& p : ctrl) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  return 1e-12 * scale;
}

struct Checked {
  double ratio = 0.0;  // measured Hausdorff / tolerance
  std::size_t segments = 0;
};

Checked check_bezier(const std::vector<Point>& ctrl, double tolerance, const std::string& what) {
  std::vector<Point> out{ctrl.front()};
  const FlattenOutcome outcome = flatten_bezier(ctrl, tolerance, out);
  INFO(what << " degree " << ctrl.size() - 1 << " tolerance " << tolerance << " segments " << out.size() - 1);
  REQUIRE(outcome == FlattenOutcome::kOk);
  REQUIRE(out.back() == ctrl.back());
  const testing::Measurement m = testing::measure_bezier(ctrl, tolerance, out);
  INFO("curve->polyline " << m.curve_to_polyline << " polyline->curve " << m.polyline_to_curve);
  CHECK(m.curve_to_polyline <= tolerance + slack(ctrl));
  CHECK(m.polyline_to_curve <= tolerance + slack(ctrl));
  // Vertices are de Casteljau points: their distance is only the measurement's sagitta (<= tol/1000 twice).
  CHECK(m.vertex_to_curve <= tolerance / 100.0 + slack(ctrl));
  return {m.hausdorff() / tolerance, out.size() - 1};
}

Checked check_rational(const std::vector<Point>& ctrl, const std::vector<double>& weights, double tolerance,
                       const std::string& what) {
  std::vector<Point> out{ctrl.front()};
  const FlattenOutcome outcome = flatten_rational(ctrl, weights, tolerance, out);
  INFO(what << " degree " << ctrl.size() - 1 << " tolerance " << tolerance << " segments " << out.size() - 1);
  REQUIRE(outcome == FlattenOutcome::kOk);
  REQUIRE(out.back() == ctrl.back());
  const testing::Measurement m = testing::measure_rational(ctrl, weights, tolerance, out);
  INFO("curve->polyline " << m.curve_to_polyline << " polyline->curve " << m.polyline_to_curve);
  CHECK(m.curve_to_polyline <= tolerance + slack(ctrl));
  CHECK(m.polyline_to_curve <= tolerance + slack(ctrl));
  CHECK(m.vertex_to_curve <= tolerance / 100.0 + slack(ctrl));
  return {m.hausdorff() / tolerance, out.size() - 1};
}

std::vector<Point> random_points(std::mt19937_64& rng, std::size_t count, double box) {
  std::uniform_real_distribution<double> coord(0.0, box);
  std::vector<Point> points(count);
  for (Point& p : points) p = {coord(rng), coord(rng)};
  return points;
}

TEST_CASE("random polynomial Béziers of degree 1-7 stay within tolerance", "[flatten][corpus]") {
  std::mt19937_64 rng(20261121);
  double ratio_sum = 0.0;
  int cubics = 0;
  for (int i = 0; i < 1400; ++i) {
    const std::size_t degree = 1 + static_cast<std::size_t>(i % 7);
    const double tolerance = kTolerances[static_cast<std::size_t>(i / 7) % kTolerances.size()];
    const Checked c =
        check_bezier(random_points(rng, degree + 1, 512.0), tolerance, "random #" + std::to_string(i));
    if (degree == 3) {
      ratio_sum += c.ratio;
      ++cubics;
    }
  }
  // Not vacuous: the measurement sees errors at the scale of the tolerance, and the flattener spends its
  // budget (it accepts pieces at >= 90 % of the tolerance when it can; the last piece of a curve is shorter).
  CHECK(ratio_sum / cubics > 0.75);
}

TEST_CASE("random rational Béziers of degree 2-4 with positive weights stay within tolerance",
          "[flatten][corpus]") {
  std::mt19937_64 rng(4242);
  std::uniform_real_distribution<double> log_weight(std::log(0.05), std::log(20.0));
  for (int i = 0; i < 360; ++i) {
    const std::size_t degree = 2 + static_cast<std::size_t>(i % 3);
    const double tolerance = kTolerances[static_cast<std::size_t>(i / 3) % kTolerances.size()];
    std::vector<double> weights(degree + 1);
    for (double& w : weights) w = std::exp(log_weight(rng));
    check_rational(random_points(rng, degree + 1, 512.0), weights, tolerance,
                   "rational #" + std::to_string(i));
  }
}

TEST_CASE("conics: circular arcs of every opening and size, parabolas, hyperbolas", "[flatten][corpus]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> angle(0.01, 0.99 * std::numbers::pi);
  std::uniform_real_distribution<double> log_radius(std::log(0.5), std::log(5000.0));
  std::uniform_real_distribution<double> conic_weight(0.05, 8.0);
  for (int i = 0; i < 400; ++i) {
    const double tolerance = kTolerances[static_cast<std::size_t>(i) % kTolerances.size()];
    // A circular arc of opening theta as a rational quadratic: end points on the circle, middle point at
    // the intersection of the end tangents, middle weight cos(theta/2) (Umetani, *Parametric Curve*, §4.1).
    const double theta = angle(rng), radius = std::exp(log_radius(rng)), start = angle(rng) * 2.0;
    const Point center{256.0, 256.0};
    auto on_circle = [&](double a, double r) { return center + Vec2{std::cos(a), std::sin(a)} * r; };
    const std::vector<Point> arc{on_circle(start, radius),
                                 on_circle(start + theta / 2, radius / std::cos(theta / 2)),
                                 on_circle(start + theta, radius)};
    check_rational(arc, {1.0, std::cos(theta / 2), 1.0}, tolerance, "arc #" + std::to_string(i));
    const std::vector<Point> conic = random_points(rng, 3, 512.0);
    check_rational(conic, {1.0, conic_weight(rng), 1.0}, tolerance, "conic #" + std::to_string(i));
  }
}

TEST_CASE("pathological polynomial curves stay within tolerance", "[flatten][pathological]") {
  const double noise = 1e-14;
  const std::vector<std::pair<std::string, std::vector<Point>>> cases = {
      // C'(1/2) = (P3 + P2 - P1 - P0)·3/4 = 0: a cusp.
      {"cusp", {{0, 0}, {200, 200}, {0, 200}, {200, 0}}},
      {"loop", {{0, 0}, {300, 300}, {-100, 300}, {200, 0}}},
      {"closed loop, degenerate chord", {{0, 0}, {300, 300}, {-300, 300}, {0, 0}}},
      {"all points coincide", {{5, 5}, {5, 5}, {5, 5}, {5, 5}}},
      {"coincident inner points", {{0, 0}, {100, 50}, {100, 50}, {200, 0}}},
      {"coincident end handles", {{0, 0}, {0, 0}, {200, 100}, {200, 100}}},
      {"collinear, doubling back", {{0, 0}, {300, 0}, {-100, 0}, {200, 0}}},
      {"collinear, doubling back to the start", {{0, 0}, {100, 0}, {100, 0}, {0, 0}}},
      {"collinear, diagonal overshoot", {{0, 0}, {400, 400}, {-200, -200}, {100, 100}}},
      {"line with 1e-14 noise", {{0, 0}, {100, noise}, {200, -noise}, {300, 0}}},
      {"point with 1e-14 noise", {{1, 1}, {1 + noise, 1}, {1, 1 - noise}, {1, 1}}},
      {"tiny 1e-6 cubic", {{0, 0}, {3e-6, 1e-6}, {-1e-6, 2e-6}, {1e-6, 0}}},
      {"huge 1e6 cubic", {{0, 0}, {3e6, 1e6}, {-1e6, 2e6}, {1e6, 0}}},
      {"far from the origin", {{1e6, 1e6}, {1e6 + 300, 1e6 + 100}, {1e6 - 100, 1e6 + 200}, {1e6 + 100, 1e6}}},
      {"degree 7 zigzag",
       {{0, 0}, {50, 400}, {100, -400}, {150, 400}, {200, -400}, {250, 400}, {300, -400}, {350, 0}}},
      {"quadratic cusp-like (middle point far away)", {{0, 0}, {1e5, 0}, {0, 1}}},
  };
  for (const auto& [name, ctrl] : cases) {
    for (const double tolerance : kTolerances) check_bezier(ctrl, tolerance, name);
  }
}

TEST_CASE("tiny and huge tolerances relative to the curve", "[flatten][pathological]") {
  const std::vector<Point> tiny{{0, 0}, {3e-6, 1e-6}, {-1e-6, 2e-6}, {1e-6, 0}};
  check_bezier(tiny, 1e-9, "tiny cubic at 1e-9");
  const std::vector<Point> unit{{0, 0}, {1, 1}, {2, -1}, {3, 0}};
  check_bezier(unit, 1e-7, "unit cubic at 1e-7");
  check_bezier(unit, 1e6, "unit cubic at 1e6");
}

TEST_CASE("pathological rational curves stay within tolerance", "[flatten][pathological]") {
  const std::vector<Point> half_circle_ctrl{{0, 0}, {0, 100}, {200, 100}, {200, 0}};
  // A NURBS-style semicircle as a rational cubic, weights (1, 1/3, 1/3, 1).
  check_rational(half_circle_ctrl, {1.0, 1.0 / 3.0, 1.0 / 3.0, 1.0}, 0.1, "rational cubic semicircle");
  check_rational({{0, 0}, {100, 100}, {200, 0}}, {1.0, 1e-6, 1.0}, 0.1, "nearly flat conic (w = 1e-6)");
  check_rational({{0, 0}, {100, 100}, {200, 0}}, {1.0, 1e6, 1.0}, 0.1, "sharp hyperbola (w = 1e6)");
  check_rational({{0, 0}, {100, 100}, {200, 0}}, {1e-200, 1e-200, 2e-200}, 0.1, "tiny weights");
  check_rational({{0, 0}, {100, 100}, {100, 100}, {0, 0}}, {1.0, 3.0, 0.5, 2.0}, 0.25,
                 "closed rational loop");
}

}  // namespace
}  // namespace curvescan
