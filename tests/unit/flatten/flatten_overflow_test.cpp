// The flattener near the ends of the double range: control points whose pairwise differences overflow are
// rejected at once (nothing appended), and a tolerance below the coordinates' resolution walks at the
// resolvable tolerance (complete polyline, kSegmentLimit) instead of failing every trial of every segment.
// Regression: fuzz/regressions/curve_spec/quadratic_control_points_1e308_flatten_54s.json.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "curvescan/curves/flatten.h"

namespace curvescan {
namespace {

TEST_CASE(
    "quadratic_control_points_1e308_flatten_54s: an extent past DBL_MAX is non-finite, appended nothing",
    "[flatten][contract][regression]") {
  // The fuzz input: Q_i - Q_0 are all finite, Q_2 - Q_1 = (-1e308, -2e308) is not. Before the fix every
  // split point was NaN and each of the 2^22 segments spent its whole trial budget (54 s).
  const std::vector<Point> ctrl{{-0.0, 0}, {1e308, 1e308}, {0, -1e308}};
  const std::vector<Point> sentinel{{7, 7}};
  std::vector<Point> out = sentinel;
  CHECK(flatten_bezier(ctrl, 0.1, out) == FlattenOutcome::kNonFinite);
  CHECK(out == sentinel);
  CHECK(flatten_rational(ctrl, std::vector<double>{1, 2, 1}, 0.1, out) == FlattenOutcome::kNonFinite);
  CHECK(out == sentinel);
  // A cubic whose first point sits between the others: only a difference not involving Q_0 overflows.
  const double big = 0.75 * std::numeric_limits<double>::max();
  const std::vector<Point> cubic{{0, 0}, {big, 1}, {-big, 2}, {1, 0}};
  CHECK(flatten_bezier(cubic, 0.1, out) == FlattenOutcome::kNonFinite);
  CHECK(out == sentinel);
}

TEST_CASE("a tolerance below the coordinates' resolution walks at the resolvable one, few points",
          "[flatten][contract][regression]") {
  // Near 1e15 one ulp is 0.125: 1e-6 cannot be certified. The curve is 128 wide and bends by 16, so at the
  // resolvable tolerance (a few ulps of 1e15, i.e. a few units) it needs a handful of segments; before the
  // fix the walk failed every trial up to kMaxFlattenSegments. 100 points is far above the handful and far
  // below the cap.
  const std::vector<Point> ctrl{{1e15, 1e15}, {1e15 + 64, 1e15 + 32}, {1e15 + 128, 1e15}};
  std::vector<Point> out;
  CHECK(flatten_bezier(ctrl, 1e-6, out) == FlattenOutcome::kSegmentLimit);
  CHECK(out.size() >= 2);
  CHECK(out.size() <= 100);
  CHECK(out.back() == ctrl.back());
  out.clear();
  CHECK(flatten_rational(ctrl, std::vector<double>{1, 3, 1}, 1e-6, out) == FlattenOutcome::kSegmentLimit);
  CHECK(out.size() <= 100);
  CHECK(out.back() == ctrl.back());
  // Every vertex stays on the curve's scale: within the hull's box.
  for (const Point p : out) {
    CHECK(p.x >= 1e15);
    CHECK(p.x <= 1e15 + 128);
  }
}

TEST_CASE("ordinary tolerances are untouched by the resolution floor", "[flatten][contract]") {
  // At coordinates ~400 the floor is ~3e-12: tolerances down to 1e-9 walk as before and certify.
  const std::vector<Point> cubic{{0, 0}, {100, 200}, {300, -100}, {400, 50}};
  for (const double tolerance : {1.0, 0.1, 1e-3, 1e-6, 1e-9}) {
    std::vector<Point> out;
    CHECK(flatten_bezier(cubic, tolerance, out) == FlattenOutcome::kOk);
  }
}

}  // namespace
}  // namespace curvescan
