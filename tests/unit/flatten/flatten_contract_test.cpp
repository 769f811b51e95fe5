// The flattener's outcomes: invalid and non-finite input are rejected with nothing appended, the segment
// limit is reported with a complete polyline, the last vertex is exactly the end point, and work stays
// bounded on input that defeats the tolerance.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "curvescan/curves/flatten.h"

namespace curvescan {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

const std::vector<Point> kCubic{{0, 0}, {100, 200}, {300, -100}, {400, 50}};

TEST_CASE("non-finite control points, weights or tolerance are rejected and nothing is appended",
          "[flatten][contract]") {
  const std::vector<Point> sentinel{{7, 7}};
  for (const double bad : {kNaN, kInf, -kInf}) {
    for (std::size_t i = 0; i < kCubic.size(); ++i) {
      std::vector<Point> ctrl = kCubic;
      ctrl[i].y = bad;
      std::vector<Point> out = sentinel;
      CHECK(flatten_bezier(ctrl, 0.1, out) == FlattenOutcome::kNonFinite);
      CHECK(out == sentinel);
      std::vector<double> weights{1, 2, 3, 1};
      CHECK(flatten_rational(ctrl, weights, 0.1, out) == FlattenOutcome::kNonFinite);
      weights[i] = bad;
      CHECK(flatten_rational(kCubic, weights, 0.1, out) == FlattenOutcome::kNonFinite);
      CHECK(out == sentinel);
    }
    std::vector<Point> out = sentinel;
    CHECK(flatten_bezier(kCubic, bad, out) == FlattenOutcome::kNonFinite);
    CHECK(flatten_rational(kCubic, std::vector<double>{1, 2, 3, 1}, bad, out) == FlattenOutcome::kNonFinite);
    CHECK(out == sentinel);
  }
}

TEST_CASE("finite coordinates whose differences overflow are rejected as non-finite", "[flatten][contract]") {
  const double big = std::numeric_limits<double>::max();
  std::vector<Point> out;
  CHECK(flatten_bezier(std::vector<Point>{{-big, 0}, {0, 1}, {big, 0}}, 0.1, out) ==
        FlattenOutcome::kNonFinite);
  CHECK(out.empty());
}

TEST_CASE("invalid input is rejected and nothing is appended", "[flatten][contract]") {
  std::vector<Point> out;
  CHECK(flatten_bezier(std::vector<Point>{}, 0.1, out) == FlattenOutcome::kInvalid);
  CHECK(flatten_bezier(std::vector<Point>{{1, 2}}, 0.1, out) == FlattenOutcome::kInvalid);
  CHECK(flatten_bezier(kCubic, 0.0, out) == FlattenOutcome::kInvalid);
  CHECK(flatten_bezier(kCubic, -1.0, out) == FlattenOutcome::kInvalid);
  CHECK(flatten_rational(kCubic, std::vector<double>{1, 1, 1}, 0.1, out) == FlattenOutcome::kInvalid);
  CHECK(flatten_rational(kCubic, std::vector<double>{1, 0, 1, 1}, 0.1, out) == FlattenOutcome::kInvalid);
  CHECK(flatten_rational(kCubic, std::vector<double>{1, -2, 1, 1}, 0.1, out) == FlattenOutcome::kInvalid);
  CHECK(out.empty());
}

TEST_CASE("a straight line is one segment — the last vertex is exactly the end point", "[flatten][contract]") {
  std::vector<Point> out;
  const std::vector<Point> line{{0.1, 0.2}, {1e3 / 3.0, 7.0 / 3.0}};
  CHECK(flatten_bezier(line, 0.1, out) == FlattenOutcome::kOk);
  REQUIRE(out.size() == 1);
  CHECK(out.back() == line.back());
  // Control points evenly on a line: still one segment (the bound is 0 up to the rounding margin).
  out.clear();
  const std::vector<Point> cubic_line{{0, 0}, {1, 2}, {2, 4}, {3, 6}};
  CHECK(flatten_bezier(cubic_line, 0.1, out) == FlattenOutcome::kOk);
  CHECK(out.size() == 1);
}

TEST_CASE("appends after existing content and ends at the exact end point, rational too",
          "[flatten][contract]") {
  // Weights whose homogeneous round trip x·w/w is inexact: the end point must be copied, not projected.
  const std::vector<Point> ctrl{{0.1, 0.7}, {100.3, 200.9}, {300.7, 0.3}};
  const std::vector<double> weights{0.3, 1.7, 0.7};
  std::vector<Point> out{{-1, -1}};
  CHECK(flatten_rational(ctrl, weights, 0.1, out) == FlattenOutcome::kOk);
  REQUIRE(out.size() > 2);
  CHECK(out.front() == Point{-1, -1});
  CHECK(out.back() == ctrl.back());
  // Vertices strictly progress along a curve without self-intersections: no duplicates.
  for (std::size_t i = 2; i < out.size(); ++i) CHECK(out[i] != out[i - 1]);
}

TEST_CASE("rational with equal weights flattens like the polynomial curve", "[flatten][contract]") {
  std::vector<Point> polynomial, rational;
  CHECK(flatten_bezier(kCubic, 0.1, polynomial) == FlattenOutcome::kOk);
  CHECK(flatten_rational(kCubic, std::vector<double>{2.5, 2.5, 2.5, 2.5}, 0.1, rational) ==
        FlattenOutcome::kOk);
  CHECK(polynomial == rational);
}

TEST_CASE("segment count grows like 1/sqrt(tolerance) on a circle", "[flatten][contract]") {
  // A quarter circle of radius r as a conic: a chord of angle a has sagitta r(1 - cos(a/2)) ~ r·a^2/8, so
  // the fewest segments are ceil((pi/2) / (2·acos(1 - tol/r))). The walk must be within one segment of it
  // plus 10 % (it accepts pieces at >= 90 % of the tolerance, i.e. >= 95 % of the longest).
  const double r = 1000.0;
  const std::vector<Point> ctrl{{r, 0}, {r, r}, {0, r}};
  const std::vector<double> weights{1.0, std::sqrt(0.5), 1.0};
  for (const double tolerance : {0.01, 0.1, 1.0}) {
    std::vector<Point> out;
    CHECK(flatten_rational(ctrl, weights, tolerance, out) == FlattenOutcome::kOk);
    const double fewest = std::ceil((std::numbers::pi / 2) / (2.0 * std::acos(1.0 - tolerance / r)));
    INFO("tolerance " << tolerance << " segments " << out.size() << " fewest " << fewest);
    CHECK(static_cast<double>(out.size()) >= fewest);
    CHECK(static_cast<double>(out.size()) <= 1.1 * fewest + 1.0);
  }
}

TEST_CASE("the segment limit stops the walk with a complete polyline", "[flatten][contract][slow]") {
  // A quarter circle of radius 1e6 at tolerance 1e-7 needs ~ (pi/2)/sqrt(8·1e-7/1e6) = 1.76e6 segments; a
  // full-turn-like cubic loop of radius 1e7 needs well over kMaxFlattenSegments = 4.2e6 at 1e-7.
  const double r = 1e7;
  const std::vector<Point> loop{{0, 0}, {r, r}, {-r, r}, {0, 0}};
  std::vector<Point> out;
  CHECK(flatten_bezier(loop, 1e-7, out) == FlattenOutcome::kSegmentLimit);
  CHECK(out.size() == kMaxFlattenSegments);
  CHECK(out.back() == loop.back());
}

TEST_CASE("a tolerance below the coordinates' resolution terminates with bounded work",
          "[flatten][contract]") {
  // Near 1e15 one ulp is 0.125: a tolerance of 1e-6 cannot be certified by any piece that is not a single
  // point. The walk must still end (t strictly increases, each step has a trial budget) and say so.
  const std::vector<Point> ctrl{{1e15, 1e15}, {1e15 + 64, 1e15 + 32}, {1e15 + 128, 1e15}};
  std::vector<Point> out;
  const FlattenOutcome outcome = flatten_bezier(ctrl, 1e-6, out);
  CHECK((outcome == FlattenOutcome::kOk || outcome == FlattenOutcome::kSegmentLimit));
  REQUIRE(!out.empty());
  CHECK(out.back() == ctrl.back());
}

}  // namespace
}  // namespace curvescan
