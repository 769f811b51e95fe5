// Cubics in Wang's uniform steps (curves/src/flatten_cubic_uniform.h; docs/flattening.md §1e):
//  - the contract of flatten_bezier (detail::flatten_cubic_uniform called directly), measured by the
//    independent Hausdorff measurement (hausdorff_measure.h), on every curve the plan takes uniformly —
//    circle arcs of every radius and rotation, random cubics, short pieces, near-degenerate cubics — at
//    four tolerances and from 1e-3 to 1e5 px scales: within tolerance both ways, every vertex B(i/n), the
//    last exactly P3;
//  - the count is Wang's closed form and is not padded: on degree-elevated parabolas (where the bound is
//    the exact sagitta) n - 1 uniform steps measure above the tolerance;
//  - the choice: circle arcs go uniform with at most one segment more than the adaptive walk, cusps and
//    curves of very uneven speed go to the walk, and wherever the plan is uniform the count stays within
//    the allowance of the walk's;
//  - flatten_bezier dispatches to it: a curve the plan takes gets exactly the uniform polyline, any other
//    exactly the adaptive walk's (detail::flatten_cubic), and a cap below n the walk's kSegmentLimit;
//  - extreme inputs: huge and tiny coordinates, tolerances near the resolution, NaN and infinities, a
//    segment cap below n — no NaN vertex, and the walk takes what the closed form cannot certify.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/flatten.h"
#include "hausdorff_measure.h"
// Private to curves/ (not API); reached by path, as flatten_cubic_test does.
#include "../../../curves/src/flatten_cubic.h"
#include "../../../curves/src/flatten_cubic_uniform.h"

namespace curvescan {
namespace {

using Cubic = std::vector<Point>;

// A circular arc of `radius` about `centre` from angle a0 spanning `sweep` (<= π/2) as the usual cubic
// (handles 4/3·tan(sweep/4)·radius along the end tangents).
Cubic circle_arc(Point centre, double radius, double a0, double sweep) {
  const double k = 4.0 / 3.0 * std::tan(sweep / 4.0) * radius;
  const double a1 = a0 + sweep;
  const Point p0{centre.x + radius * std::cos(a0), centre.y + radius * std::sin(a0)};
  const Point p3{centre.x + radius * std::cos(a1), centre.y + radius * std::sin(a1)};
  const Point p1{p0.x - k * std::sin(a0), p0.y + k * std::cos(a0)};
  const Point p2{p3.x + k * std::sin(a1), p3.y - k * std::cos(a1)};
  return {p0, p1, p2, p3};
}

// When the plan is uniform: flattens with detail::flatten_cubic_uniform and checks the polyline is the
// plan's n steps at B(i/n), NaN-free and within tolerance by measurement. Otherwise measures
// flatten_bezier's polyline (the walk). Returns whether the plan was uniform.
bool check_curve(const Cubic& ctrl, double tolerance) {
  const detail::CubicUniformPlan plan = detail::plan_cubic_uniform(ctrl, tolerance);
  std::vector<Point> out{ctrl.front()};
  const std::optional<FlattenOutcome> uniform = detail::flatten_cubic_uniform(ctrl, tolerance, out);
  REQUIRE(uniform.has_value() == plan.uniform);
  if (uniform) {
    REQUIRE(*uniform == FlattenOutcome::kOk);
  } else {
    REQUIRE(out.size() == 1);  // nothing appended when the plan declines
    REQUIRE(flatten_bezier(ctrl, tolerance, out) == FlattenOutcome::kOk);
  }
  REQUIRE(out.back() == ctrl.back());
  for (const Point p : out) REQUIRE((std::isfinite(p.x) && std::isfinite(p.y)));
  double extent = 0.0;
  for (const Point p : ctrl) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
  const testing::Measurement m = testing::measure_bezier(ctrl, tolerance, out);
  // Slack: the measurement's own rounding, 1e-12 of the largest coordinate (as the other flatten tests);
  // the flattener's own margins sit inside its bound.
  const double slack = 1e-12 * extent;
  INFO("tolerance " << tolerance << " segments " << out.size() - 1 << " plan " << plan.steps << " uniform "
                    << plan.uniform << " estimate " << plan.fewest_estimate);
  CHECK(m.curve_to_polyline <= tolerance + slack);
  CHECK(m.polyline_to_curve <= tolerance + slack);
  if (!uniform) return false;
  REQUIRE(out.size() - 1 == plan.steps);
  for (std::size_t i = 1; i + 1 < out.size(); ++i) {
    const Point expected = de_casteljau(ctrl, static_cast<double>(i) / static_cast<double>(plan.steps));
    // A few ulps of the coordinates: the two evaluations round differently.
    CHECK(out[i].distance(expected) <= 1e-13 * std::max(extent, 1.0) + 1e-300);
  }
  return true;
}

TEST_CASE("uniform cubic steps keep the tolerance on every curve the plan takes", "[flatten][cubic]") {
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int uniform = 0, total = 0;
  for (const double scale : {1e-3, 1.0, 30.0, 1e5}) {
    for (const double tolerance : {0.01, 0.1, 0.25, 1.0}) {
      const double tol = tolerance * std::min(1.0, scale);  // tiny scales get tolerances to match
      for (int trial = 0; trial < 25; ++trial) {
        // Circle arcs (the plan's main customers: fills of circles, rounded rectangles).
        const double radius = scale * (0.5 + 500.0 * unit(rng) * unit(rng));
        const Cubic arc =
            circle_arc({scale * unit(rng), scale * unit(rng)}, radius, 2.0 * std::numbers::pi * unit(rng),
                       std::numbers::pi / 2.0 * (0.1 + 0.9 * unit(rng)));
        uniform += check_curve(arc, tol);
        // Random cubics in a box, and short pieces of them (a stroke's narrow pieces).
        Cubic random(4);
        for (Point& p : random) p = {scale * 100.0 * unit(rng), scale * 100.0 * unit(rng)};
        uniform += check_curve(random, tol);
        const double a = 0.9 * unit(rng), b = a + 0.1 * unit(rng);
        const Bezier sub = Bezier(random).subsegment(a, b);
        uniform += check_curve(Cubic(sub.points().begin(), sub.points().end()), tol);
        total += 3;
      }
    }
  }
  INFO("uniform " << uniform << " of " << total);
  CHECK(uniform > total / 3);  // the cases exercise the uniform steps, not only the walk
}

TEST_CASE("uniform cubic steps on near-degenerate cubics", "[flatten][cubic]") {
  const double tolerances[] = {0.01, 0.1, 0.25, 1.0};
  const Cubic cases[] = {
      {{0, 0}, {0, 0}, {50, 50}, {100, 0}},              // coincident first handle (V(0) = 0)
      {{0, 0}, {50, 50}, {100, 0}, {100, 0}},            // coincident last handle
      {{0, 0}, {0, 0}, {100, 0}, {100, 0}},              // a line with both handles on the ends
      {{0, 0}, {100, 0}, {-50, 0}, {50, 0}},             // collinear, back-tracking
      {{0, 0}, {100, 100}, {0, 100}, {100, 0}},          // a cusp-like crossing
      {{0, 0}, {100, 100}, {-100, 100}, {0, 0}},         // closed loop
      {{0, 0}, {1e-14, 1e-14}, {2e-14, 0}, {3e-14, 0}},  // below every tolerance
      {{0, 0}, {33, 1e-13}, {66, -1e-13}, {100, 0}},     // straight up to noise
      {{1e6, 1e6}, {1e6 + 30, 1e6 + 60}, {1e6 + 70, 1e6 - 20}, {1e6 + 100, 1e6}},  // far from the origin
      {{0, 0}, {0.5, 0}, {1, 0.5}, {1, 1}},                                        // small
  };
  for (const Cubic& ctrl : cases) {
    for (const double tolerance : tolerances) check_curve(ctrl, tolerance);
  }
}

TEST_CASE("uniform cubic step count is Wang's closed form and is not padded", "[flatten][cubic]") {
  // A parabola degree-elevated to a cubic: K = B''/6 is constant, so Wang's bound 3/4·h²·|K| is the
  // exact sagitta of every step's middle, and n - 1 uniform steps must exceed the tolerance.
  for (const double height : {3.0, 17.0, 250.0}) {
    const Point q0{0, 0}, q1{10, height}, q2{20, 0};
    const Cubic ctrl{q0, lerp(q0, q1, 2.0 / 3.0), lerp(q2, q1, 2.0 / 3.0), q2};
    const double tolerance = 0.1;
    const detail::CubicUniformPlan plan = detail::plan_cubic_uniform(ctrl, tolerance);
    // Wang: n = ceil(sqrt(3/4·max(|D0|, |D1|)/τ)), |D0| = |D1| = 2·height/3 here.
    const double exact = std::sqrt(0.75 * (2.0 * height / 3.0) / tolerance);
    INFO("height " << height << " steps " << plan.steps << " exact " << exact);
    REQUIRE(plan.steps == static_cast<std::size_t>(std::ceil(exact)));
    const std::size_t fewer = plan.steps - 1;
    std::vector<Point> coarse{ctrl.front()};
    for (std::size_t i = 1; i <= fewer; ++i)
      coarse.push_back(de_casteljau(ctrl, static_cast<double>(i) / static_cast<double>(fewer)));
    const testing::Measurement m = testing::measure_bezier(ctrl, tolerance, coarse);
    // The bound is attained at each step's middle; (3/4·|K|)/(n-1)² is well above τ for these heights
    // (exact is at least 0.3 above an integer), far beyond the measurement's resolution.
    CHECK(m.curve_to_polyline > tolerance * 1.001);
  }
}

// The plan's estimate as first written: Simpson's rule on sqrt(|V × K|/|V|) at t = 0, 1/2, 1, every sample
// by the same de Casteljau lerps of the first differences (V) and K = D0 + (D1 - D0)·t. The plan takes
// the end samples without the lerps; this holds that to the same doubles.
double reference_fewest_estimate(const Cubic& c, double tolerance) {
  const Vec2 e0 = c[1] - c[0], e1 = c[2] - c[1], e2 = c[3] - c[2];
  const Vec2 d0 = e1 - e0, d1 = e2 - e1, j = d1 - d0;
  const auto lerp_vec = [](Vec2 a, Vec2 b, double t) { return a + (b - a) * t; };
  const auto rate = [&](double t) {
    const Vec2 v = lerp_vec(lerp_vec(e0, e1, t), lerp_vec(e1, e2, t), t);
    const double speed = std::sqrt(v.length_squared());
    if (!(speed > 0.0)) return 0.0;
    return std::sqrt(std::abs(v.cross(d0 + j * t)) / speed);
  };
  return (rate(0.0) + 4.0 * rate(0.5) + rate(1.0)) / 6.0 * std::sqrt(0.75 / tolerance);
}

TEST_CASE("uniform cubic plan's end samples equal the lerped ones, bit for bit", "[flatten][cubic]") {
  // Random cubics (nearly all declined), their short sub-arcs and circle arcs (nearly all taken), and
  // curves with a zero first difference at an end (the rate there is 0): the same estimate, so the same
  // choice, exactly.
  std::mt19937_64 rng(20261128);
  std::uniform_real_distribution<double> coordinate(-300.0, 300.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Cubic> curves;
  for (int i = 0; i < 2000; ++i) {
    const Cubic whole{{coordinate(rng), coordinate(rng)},
                      {coordinate(rng), coordinate(rng)},
                      {coordinate(rng), coordinate(rng)},
                      {coordinate(rng), coordinate(rng)}};
    curves.push_back(whole);
    const double a = unit(rng), b = std::min(1.0, a + 0.05 + 0.2 * unit(rng));
    const Bezier sub = Bezier(whole).subsegment(a, b);
    curves.emplace_back(sub.points().begin(), sub.points().end());
    curves.push_back(circle_arc({coordinate(rng), coordinate(rng)}, 1.0 + 500.0 * unit(rng), 6.3 * unit(rng),
                                0.1 + 1.47 * unit(rng)));
  }
  curves.push_back({{0, 0}, {0, 0}, {50, 80}, {100, 0}});
  curves.push_back({{0, 0}, {50, 80}, {100, 0}, {100, 0}});
  std::size_t compared = 0;
  for (const Cubic& c : curves) {
    for (const double tolerance : {0.01, 0.1, 0.25}) {
      const detail::CubicUniformPlan plan = detail::plan_cubic_uniform(c, tolerance);
      if (plan.steps <= 2) continue;  // no estimate there
      const double reference = reference_fewest_estimate(c, tolerance);
      INFO("P0 " << c[0].x << "," << c[0].y << " tolerance " << tolerance);
      REQUIRE(plan.fewest_estimate == reference);
      REQUIRE(plan.uniform == (static_cast<double>(plan.steps) <= 1.12 * reference + 1.0));
      // flatten_bezier's form, given the largest |coordinate| it has already taken: the same plan.
      double largest = 0.0;
      for (const Point p : c) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
      const detail::CubicUniformPlan given = detail::plan_cubic_uniform(c, tolerance, largest);
      REQUIRE(given.steps == plan.steps);
      REQUIRE(given.fewest_estimate == plan.fewest_estimate);
      REQUIRE(given.uniform == plan.uniform);
      ++compared;
    }
  }
  CHECK(compared > 10000);
}

TEST_CASE("uniform cubic steps are chosen where they are near the fewest", "[flatten][cubic]") {
  // Quarter circles of radius 5-1000 at 0.1 px: uniform, within 6 % (plus one) of the walk's segments.
  // Wang's bound is 3/4·|K| ~ 0.345·r·h² on a quarter circle against its sagitta (π/2)²/8·r·h² ~ 0.308·r·h²,
  // so about sqrt(1.12) = 1.06 times the segments, and the walk itself is a few % above the fewest.
  for (const double radius : {1.0, 5.0, 20.0, 100.0, 250.0, 1000.0}) {
    const Cubic arc = circle_arc({300, 300}, radius, 0.3, std::numbers::pi / 2.0);
    const detail::CubicUniformPlan plan = detail::plan_cubic_uniform(arc, 0.1);
    std::vector<Point> walk;
    REQUIRE(detail::flatten_cubic(arc, 0.1, walk).has_value());
    INFO("radius " << radius << " uniform steps " << plan.steps << " walk " << walk.size());
    // Two steps or fewer (radius 1 at 0.1 px) are left to the walk, which often needs one.
    CHECK(plan.uniform == (plan.steps > 2));
    CHECK(static_cast<double>(plan.steps) <= 1.06 * static_cast<double>(walk.size()) + 1.0);
  }
  // A cusp (the hodograph through 0 mid-curve) and a curve whose speed changes 50-fold: the walk.
  CHECK_FALSE(detail::plan_cubic_uniform(Cubic{{0, 0}, {100, 100}, {0, 100}, {100, 0}}, 0.1).uniform);
  CHECK_FALSE(detail::plan_cubic_uniform(Cubic{{0, 0}, {1, 1}, {2, 3}, {200, 100}}, 0.1).uniform);
  // Wherever the plan is uniform, the count stays within the allowance (1.12×, plus one) of the
  // estimate, which tracks the walk: at most 1.2× the walk's segments plus two, on short sub-arcs of random
  // cubics (a stroke's pieces; whole random cubics are nearly all left to the walk).
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(0.0, 200.0);
  int uniform = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Bezier whole({{coordinate(rng), coordinate(rng)},
                        {coordinate(rng), coordinate(rng)},
                        {coordinate(rng), coordinate(rng)},
                        {coordinate(rng), coordinate(rng)}});
    const double a = 0.8 * coordinate(rng) / 200.0;
    const Bezier sub = whole.subsegment(a, a + 0.2);
    const Cubic ctrl(sub.points().begin(), sub.points().end());
    const detail::CubicUniformPlan plan = detail::plan_cubic_uniform(ctrl, 0.1);
    if (!plan.uniform) continue;
    ++uniform;
    std::vector<Point> walk;
    REQUIRE(detail::flatten_cubic(ctrl, 0.1, walk).has_value());
    INFO("trial " << trial << " uniform " << plan.steps << " walk " << walk.size());
    CHECK(static_cast<double>(plan.steps) <= 1.2 * static_cast<double>(walk.size()) + 2.0);
  }
  CHECK(uniform > 50);
}

TEST_CASE("flatten_bezier takes the cubics the uniform plan accepts in uniform steps, the rest by the walk",
          "[flatten][cubic]") {
  // The dispatch itself (flatten.cpp): flatten_bezier's polyline is, bit for bit, the uniform steps'
  // where the plan is uniform and the cubic walk's where it is not.
  const Cubic quarter = circle_arc({300, 300}, 40.0, 0.3, std::numbers::pi / 2.0);  // a circle's cubic
  const Cubic cusp{{0, 0}, {100, 100}, {0, 100}, {100, 0}};                         // uneven speed
  for (const Cubic& ctrl : {quarter, cusp}) {
    const detail::CubicUniformPlan plan = detail::plan_cubic_uniform(ctrl, 0.1);
    std::vector<Point> expected{ctrl.front()};
    if (plan.uniform) {
      REQUIRE(detail::flatten_cubic_uniform(ctrl, 0.1, expected).has_value());
    } else {
      REQUIRE(detail::flatten_cubic(ctrl, 0.1, expected).has_value());
    }
    std::vector<Point> actual{ctrl.front()};
    REQUIRE(flatten_bezier(ctrl, 0.1, actual) == FlattenOutcome::kOk);
    INFO("uniform " << plan.uniform << " steps " << plan.steps << " segments " << actual.size() - 1);
    CHECK(actual == expected);
  }
  CHECK(detail::plan_cubic_uniform(quarter, 0.1).uniform);
  CHECK_FALSE(detail::plan_cubic_uniform(cusp, 0.1).uniform);
  // The walk's polyline differs from the uniform one on the quarter circle (else the check above proves
  // nothing about the dispatch).
  std::vector<Point> walk{quarter.front()};
  REQUIRE(detail::flatten_cubic(quarter, 0.1, walk).has_value());
  std::vector<Point> dispatched{quarter.front()};
  REQUIRE(flatten_bezier(quarter, 0.1, dispatched) == FlattenOutcome::kOk);
  CHECK(walk != dispatched);
  // A cap below the uniform count: the walk takes the curve and reports the cap.
  std::vector<Point> capped{quarter.front()};
  CHECK(flatten_bezier(quarter, 0.1, capped, 3) == FlattenOutcome::kSegmentLimit);
  CHECK(capped.back() == quarter.back());
}

TEST_CASE("uniform cubic steps at extreme inputs", "[flatten][cubic]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Point> out;
  // Not finite: no plan (flatten_bezier rejects these before the plan; the plan alone stays empty too).
  CHECK(detail::plan_cubic_uniform(Cubic{{0, 0}, {nan, 1}, {2, 0}, {3, 0}}, 0.1).steps == 0);
  CHECK(detail::plan_cubic_uniform(Cubic{{0, 0}, {1, inf}, {2, 0}, {3, 0}}, 0.1).steps == 0);
  CHECK(detail::plan_cubic_uniform(Cubic{{0, 0}, {1, 1}, {2, 0}, {3, 0}}, nan).steps == 0);
  CHECK_FALSE(detail::flatten_cubic_uniform(Cubic{{0, 0}, {1, 1}, {2, 0}, {3, 0}}, nan, out).has_value());
  // Beyond 1e100 and near the coordinates' resolution: the walk's business (kSegmentLimit there).
  CHECK_FALSE(detail::flatten_cubic_uniform(Cubic{{0, 0}, {1e120, 1e120}, {2e120, 0}, {3e120, 0}}, 1e110, out)
                  .has_value());
  CHECK_FALSE(
      detail::flatten_cubic_uniform(Cubic{{1e9, 0}, {1e9 + 5, 5}, {1e9 + 10, 0}, {1e9 + 15, 3}}, 1e-9, out)
          .has_value());
  CHECK(out.empty());
  // A cap below n: nothing appended, the walk reports the cap.
  const Cubic circle = circle_arc({0, 0}, 1000.0, 0.0, std::numbers::pi / 2.0);
  const detail::CubicUniformPlan plan = detail::plan_cubic_uniform(circle, 0.1);
  REQUIRE(plan.uniform);
  REQUIRE(plan.steps > 10);
  CHECK_FALSE(detail::flatten_cubic_uniform(circle, 0.1, out, 10).has_value());
  CHECK(out.empty());
  // Huge and tiny scales at proportional tolerances: within tolerance, no NaN.
  for (const double scale : {1e-9, 1e-6, 1e6, 1e9}) {
    const Cubic arc = circle_arc({scale, -scale}, 300.0 * scale, 1.0, 1.2);
    CHECK(check_curve(arc, 0.1 * scale));
  }
}

}  // namespace
}  // namespace curvescan
