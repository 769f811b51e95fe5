// flatten_visible (raster/scan/curve_clip_cull.h): curves whose hull misses the clip box become one chord
// with the same coverage, huge curves crossing the box render as the plain flattening does with a bounded
// number of edges. Regressions:
// fuzz/regressions/svg_path_data/cubic_control_point_6e40_flattened_before_clip_ timeout and
// raster_stroke/ellipse_arcs_4e167_tall_flatten_timeout (flattened to the 2^22 cap before the clip).
#include "scan/curve_clip_cull.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"
#include "scan/path_edges.h"

using namespace curvescan;

namespace {

constexpr int kSize = 32;
const Rect kBox{0.0, 0.0, kSize, kSize};
const IntRect kClip{0, 0, kSize, kSize};

// Coverage of every pixel of kClip, 0..255.
class CoverageGrid final : public SpanSink {
 public:
  std::vector<int> cells = std::vector<int>(kSize * kSize, 0);
  void blend(std::span<const Span> spans) override {
    for (const Span& s : spans) {
      for (int x = s.x; x < s.x + s.len; ++x) cells[static_cast<std::size_t>(s.y * kSize + x)] = s.coverage;
    }
  }
};

// The closed contour: the curve from its start to its end, then the straight line back.
std::vector<int> fill_coverage(Point start, const std::vector<Point>& polyline) {
  Rasterizer rasterizer(kClip);
  Point current = start;
  for (const Point p : polyline) {
    rasterizer.add_line(current, p);
    current = p;
  }
  rasterizer.add_line(current, start);
  CoverageGrid grid;
  rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, grid);
  return grid.cells;
}

PathElement curve_element(const std::vector<Point>& ctrl, const std::vector<double>& weights = {}) {
  PathElement element;
  element.verb = weights.empty() ? PathVerb::kCubic : PathVerb::kConic;
  element.points = ctrl;
  element.weights = weights;
  element.start = ctrl.front();
  element.end = ctrl.back();
  return element;
}

int max_difference(const std::vector<int>& a, const std::vector<int>& b) {
  int worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

}  // namespace

TEST_CASE("a curve whose hull misses the box is one chord with the same coverage", "[raster][cull]") {
  // The contour (10, 50) -> (40, 50) -> a cubic bulging far to the right of the box (hull x >= 40) ->
  // (40, -20) -> (10, -20) -> back up x = 10: the fill covers x in [10, 32] of the box either way.
  const std::vector<Point> cubic{{40, 50}, {1e6, 60}, {1e6, -20}, {40, -20}};
  const PathElement element = curve_element(cubic);
  std::vector<Point> plain{{40, 50}};
  REQUIRE(flatten_bezier(cubic, 0.1, plain) == FlattenOutcome::kOk);
  CHECK(plain.size() > 10);  // the plain flattening of the bulge has many edges: the test means something
  std::vector<Point> culled{{40, 50}};
  detail::CullStats stats;
  REQUIRE(detail::flatten_visible(element, 0.1, kBox, culled, kMaxFlattenSegments, &stats) ==
          FlattenOutcome::kOk);
  CHECK(culled.size() == 2);  // O(1): the chord
  CHECK(culled.back() == cubic.back());
  CHECK(stats.chorded == 1);
  CHECK(stats.flattened == 0);
  plain.push_back({10, -20});
  culled.push_back({10, -20});
  // The contours differ only outside the box. Their clipped edges enter the exact area sums in a different
  // order: at most one level of 255 from double rounding.
  const std::vector<int> expected = fill_coverage({10, 50}, plain);
  const std::vector<int> actual = fill_coverage({10, 50}, culled);
  CHECK(max_difference(expected, actual) <= 1);
  int covered = 0;
  for (const int c : actual) covered += c == 255 ? 1 : 0;
  CHECK(covered == 22 * kSize);  // x in [10, 32): the test is not vacuous
}

TEST_CASE("a huge curve crossing the box renders as its plain flattening with few edges", "[raster][cull]") {
  // Reference: the plain flattening of the whole curve at the same tolerance (affordable at 1e7).
  struct Case {
    const char* name;
    std::vector<Point> ctrl;
    std::vector<double> weights;
  };
  const std::vector<Case> cases{
      {"cubic loop 1e7 wide, both legs crossing the box", {{0, 40}, {5e6, -5e6}, {-5e6, -5e6}, {32, 40}}, {}},
      // A quarter circle of radius 1e7 (weight cos 45°) starting inside the box at (16, 16), centred at
      // (16 - 1e7, 16): only its first ~20 px are visible.
      {"quarter circle of radius 1e7 starting in the box",
       {{16, 16}, {16, 16 - 1e7}, {16 - 1e7, 16 - 1e7}},
       {1.0, std::sqrt(0.5), 1.0}},
  };
  for (const Case& c : cases) {
    INFO(c.name);
    const PathElement element = curve_element(c.ctrl, c.weights);
    std::vector<Point> plain, culled;
    const FlattenOutcome plain_outcome = c.weights.empty() ? flatten_bezier(c.ctrl, 0.1, plain)
                                                           : flatten_rational(c.ctrl, c.weights, 0.1, plain);
    REQUIRE(plain_outcome == FlattenOutcome::kOk);
    detail::CullStats stats;
    REQUIRE(detail::flatten_visible(element, 0.1, kBox, culled, kMaxFlattenSegments, &stats) ==
            FlattenOutcome::kOk);
    CHECK(culled.back() == c.ctrl.back());
    INFO("plain " << plain.size() << " culled " << culled.size() << " halved " << stats.halved);
    CHECK(stats.halved > 0);
    CHECK(stats.chorded > 0);
    // Bounded: the visible pieces are two nearly straight legs; a few edges per halving level cut.
    CHECK(culled.size() <= 200);
    CHECK(plain.size() >= 10 * culled.size());
    // Both polylines are within 0.1 px of the curve (flatten.h), so a boundary moves by at most 0.2 px
    // between them: at most 0.2 of a pixel's area, 51/255, plus one level of rounding.
    const std::vector<int> expected = fill_coverage(c.ctrl.front(), plain);
    const std::vector<int> actual = fill_coverage(c.ctrl.front(), culled);
    CHECK(max_difference(expected, actual) <= 52);
    int sum_expected = 0, sum_actual = 0;
    for (std::size_t i = 0; i < expected.size(); ++i) {
      sum_expected += expected[i];
      sum_actual += actual[i];
    }
    CHECK(sum_expected > 0);
    // Total area: the boundary inside the box is two legs of length < 2·45 px, each moved by <= 0.2 px.
    CHECK(std::abs(sum_expected - sum_actual) <= static_cast<int>(2 * 45 * 0.2 * 255) + 1);
  }
}

TEST_CASE("cubic_control_point_6e40_flattened_before_clip_timeout: add_path_edges stays small",
          "[raster][cull]") {
  // A cubic with a control point 6.7e40 away filled on a 32 x 32 clip: before, it was flattened towards
  // the 2^22-segment cap (2.75 s at -O2). add_path_edges culls against the rasterizer's clip box.
  const Path cubic = *PathBuilder()
                          .move_to({8.5, 0.5})
                          .line_to({56.5, 0.5})
                          .cubic_to({6.0, 6.7e40}, {36.0, 56.5}, {0.5, 40.0})
                          .close()
                          .build();
  // An arc-like conic 8e167 tall and 4 wide (the ellipse_arcs_4e167 input), and a curve wholly outside.
  const Path conic = *PathBuilder().move_to({10, 10}).conic_to({12, 8e167}, {14, 10}, 0.5).close().build();
  const Path far_away =
      *PathBuilder().move_to({1e12, 0}).cubic_to({2e12, 5e11}, {3e12, -5e11}, {1e12, 1}).close().build();
  for (const Path* path : {&cubic, &conic, &far_away}) {
    Rasterizer rasterizer(kClip);
    std::vector<Point> polyline;
    const std::size_t edges = detail::add_path_edges(*path, 0.1, rasterizer, polyline);
    INFO("edges " << edges);
    // A few edges per halving level for each visible crossing; ~140 levels from 1e40 to 1e-2 (and ~560
    // from 1e167): 4096 is generous and far below the millions before.
    CHECK(edges <= 4096);
  }
  Rasterizer rasterizer(kClip);
  std::vector<Point> polyline;
  CHECK(detail::add_path_edges(far_away, 0.1, rasterizer, polyline) == 2);  // the chord and the close
}

TEST_CASE("a huge curve with weights too far apart to scale is left whole, never NaN", "[raster][cull]") {
  // 1e-310 / 1 is subnormal: scaled homogeneous points would lose the weight and project to NaN. The
  // cull hands the curve to the flattener whole; whatever it reports, no vertex is NaN.
  const std::vector<Point> ctrl{{0, 16}, {1e12, -1e12}, {32, 16}};
  const std::vector<double> weights{1.0, 1e-310, 1.0};
  std::vector<Point> out;
  detail::CullStats stats;
  detail::flatten_visible(curve_element(ctrl, weights), 0.1, kBox, out, kMaxFlattenSegments, &stats);
  CHECK(stats.halved == 0);
  CHECK(stats.flattened == 1);
  for (const Point p : out) CHECK(p.is_finite());
}
