// Named cases of the rasterizer, each pinning one promised property: overlapping geometry follows the
// winding rule (not the sum of edge contributions), huge coordinates keep their winding, degenerate input
// yields nothing, and a million edges work.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "coverage_mask.h"
#include "exact_coverage.h"
#include "polygon_scenes.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

Contour rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

bool all_zero(const CoverageMask& m) {
  return std::all_of(m.values.begin(), m.values.end(), [](std::uint8_t v) { return v == 0; });
}

/// Spans received by the sink: degenerate input must not even produce empty spans.
long span_count(const Shape& shape, int size, FillRule rule, Antialias aa = Antialias::kExact) {
  CoverageMask mask(size, size);
  Rasterizer r(IntRect{0, 0, size, size});
  add_shape(r, shape);
  MaskSink sink(mask);
  r.rasterize(rule, aa, sink);
  return sink.span_count + sink.violations;
}

}  // namespace

TEST_CASE("a contour drawn twice fills like once under nonzero and not at all under even-odd", "[named]") {
  std::mt19937 rng(5);
  for (int scene = 0; scene < 20; ++scene) {
    // A simple polygon and a self-intersecting star: the winding is 1 (or 2 in the star's core) once,
    // 2 (or 4) twice.
    const Contour simple = random_simple_polygon(rng, {16.3, 15.8}, 1.0, 14.0, 12);
    const Contour crossing = star_polygon({16.1, 16.4}, 13.7, 7, 3, 0.1 * scene);
    for (const Contour& c : {simple, crossing}) {
      const CoverageMask once = render_curvescan({c}, 32, 32, FillRule::kNonZero);
      const CoverageMask twice = render_curvescan({c, c}, 32, 32, FillRule::kNonZero);
      REQUIRE(max_abs_diff(once, twice) == 0);
      REQUIRE(all_zero(render_curvescan({c, c}, 32, 32, FillRule::kEvenOdd)));
      // Drawn again the other way round, the windings cancel: nothing under either rule.
      Contour reversed = c;
      std::reverse(reversed.begin(), reversed.end());
      REQUIRE(all_zero(render_curvescan({c, reversed}, 32, 32, FillRule::kNonZero)));
      REQUIRE(all_zero(render_curvescan({c, reversed}, 32, 32, FillRule::kEvenOdd)));
      // Aliased mode follows the same rule.
      REQUIRE(max_abs_diff(render_curvescan({c}, 32, 32, FillRule::kNonZero, Antialias::kNone),
                           render_curvescan({c, c}, 32, 32, FillRule::kNonZero, Antialias::kNone)) == 0);
      REQUIRE(all_zero(render_curvescan({c, c}, 32, 32, FillRule::kEvenOdd, Antialias::kNone)));
    }
  }
}

TEST_CASE("two parts overlapping inside a pixel, each covering half, do not fill it", "[named]") {
  // Pixel (1, 1). A = its left half, B = the middle half: union 3/4, overlap 1/4.
  const Contour a = rectangle(1.0, 1.0, 1.5, 2.0);
  const Contour b = rectangle(1.25, 1.0, 1.75, 2.0);
  // round(0.75·255) = 191 (a sum of edge contributions would give 1.0 -> 255).
  CHECK(render_curvescan({a, b}, 4, 4, FillRule::kNonZero).at(1, 1) == 191);
  // Even-odd: the overlap is a hole, 1/2 left -> 128.
  CHECK(render_curvescan({a, b}, 4, 4, FillRule::kEvenOdd).at(1, 1) == 128);
  // The same half twice: 1/2 -> 128 under nonzero, nothing under even-odd.
  CHECK(render_curvescan({a, a}, 4, 4, FillRule::kNonZero).at(1, 1) == 128);
  CHECK(render_curvescan({a, a}, 4, 4, FillRule::kEvenOdd).at(1, 1) == 0);
  // Slanted halves (triangles) overlapping in a pixel: compare with the exact rule-resolved area.
  const Contour t1{{2.0, 2.0}, {3.0, 2.0}, {2.0, 3.0}};
  const Contour t2{{2.0, 2.0}, {3.0, 3.0}, {2.0, 3.0}};
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const CoverageMask m = render_curvescan({t1, t2}, 4, 4, rule);
    CHECK(max_error_vs_exact(m, rule_resolved_coverage({t1, t2}, 4, 4, rule)) <= 0.5 + 1e-9);
  }
  // Union of t1 and t2 is 3/4 of the pixel under nonzero.
  CHECK(render_curvescan({t1, t2}, 4, 4, FillRule::kNonZero).at(2, 2) == 191);
}

TEST_CASE("coordinates at +-1e9 keep their winding and do not overflow", "[named]") {
  constexpr double kFar = 1e9;
  // A rectangle far larger than the canvas: everything covered.
  const CoverageMask full =
      render_curvescan({rectangle(-kFar, -kFar, kFar, kFar)}, 16, 16, FillRule::kNonZero);
  CHECK(std::all_of(full.values.begin(), full.values.end(), [](std::uint8_t v) { return v == 255; }));
  // A half-plane bounded by a line through the canvas, drawn with vertices 1e9 away: it must match the
  // same half-plane drawn with vertices 1e3 away (same line), and the exact oracle.
  const auto half_plane = [](double far) {
    const Point p{7.3, 8.1};
    const Vec2 d = Vec2{3.0, 1.0}.normalized();
    return Contour{p - d * far, p + d * far, p + d.perp() * far};
  };
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const CoverageMask far = render_curvescan({half_plane(kFar)}, 16, 16, rule);
    const CoverageMask near = render_curvescan({half_plane(1e3)}, 16, 16, rule);
    // The line is the same; its computed position differs by ~1e-7 px at 1e9 (double rounding): 1 step.
    CHECK(max_abs_diff(far, near) <= 1);
    CHECK(max_error_vs_exact(far, rule_resolved_coverage({half_plane(kFar)}, 16, 16, rule)) <= 1.0);
    CHECK(far.total() > 50.0);  // the half-plane really is there
  }
  // A shape entirely far to the left spans rows: its windings cancel, nothing is drawn.
  CHECK(all_zero(render_curvescan({rectangle(-2 * kFar, -kFar, -kFar, kFar)}, 16, 16, FillRule::kNonZero)));
  // A shape entirely far to the right: nothing.
  CHECK(all_zero(render_curvescan({rectangle(kFar, -kFar, 2 * kFar, kFar)}, 16, 16, FillRule::kNonZero)));
  // A rectangle from -1e9 to x = 5.5: columns 0..4 full, column 5 half.
  const CoverageMask left =
      render_curvescan({rectangle(-kFar, -kFar, 5.5, kFar)}, 16, 16, FillRule::kEvenOdd);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 16; ++x) CHECK(left.at(x, y) == (x < 5 ? 255 : (x == 5 ? 128 : 0)));
  }
}

TEST_CASE("edges on pixel boundaries give exactly 0 or 255 and abutting shapes leave no seam", "[named]") {
  const CoverageMask m = render_curvescan({rectangle(2, 3, 10, 7)}, 12, 12, FillRule::kNonZero);
  for (int y = 0; y < 12; ++y) {
    for (int x = 0; x < 12; ++x) CHECK(m.at(x, y) == (x >= 2 && x < 10 && y >= 3 && y < 7 ? 255 : 0));
  }
  // Two rectangles sharing the vertical line x = 6 and a diagonal pair sharing a slanted edge: their
  // union has no seam and no double coverage, under both rules.
  const Shape abutting{rectangle(2, 2, 6, 10), rectangle(6, 2, 10, 10)};
  const Shape diagonal{{{2.0, 2.0}, {10.0, 2.0}, {2.0, 10.0}}, {{10.0, 2.0}, {10.0, 10.0}, {2.0, 10.0}}};
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    for (const Shape& shape : {abutting, diagonal}) {
      const CoverageMask u = render_curvescan(shape, 12, 12, rule);
      for (int y = 0; y < 12; ++y) {
        for (int x = 0; x < 12; ++x) CHECK(u.at(x, y) == (x >= 2 && x < 10 && y >= 2 && y < 10 ? 255 : 0));
      }
    }
  }
}

TEST_CASE("horizontal edges: fractional tops and bottoms, zig-zags of collinear runs", "[named]") {
  // Horizontal edges at y = 2.25 and 5.75: rows 2 and 5 are 3/4 covered -> 191.
  const CoverageMask m = render_curvescan({rectangle(1, 2.25, 7, 5.75)}, 8, 8, FillRule::kNonZero);
  CHECK(m.at(3, 2) == 191);
  CHECK(m.at(3, 3) == 255);
  CHECK(m.at(3, 5) == 191);
  CHECK(m.at(3, 6) == 0);
  // A staircase with many horizontal runs, some on pixel lines and some not, and a horizontal edge
  // doubling back on itself.
  const Contour stairs{{1.0, 1.0},  {3.5, 1.0},  {3.5, 2.5}, {6.0, 2.5}, {6.0, 4.0},
                       {9.25, 4.0}, {9.25, 9.5}, {5.0, 9.5}, {7.0, 9.5}, {1.0, 9.5}};
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const CoverageMask s = render_curvescan({stairs}, 12, 12, rule);
    CHECK(max_error_vs_exact(s, sutherland_hodgman_coverage(stairs, 12, 12)) <= 0.5 + 1e-9);
  }
}

TEST_CASE("zero-area paths produce no spans at all", "[named]") {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    for (const Antialias aa : {Antialias::kExact, Antialias::kNone}) {
      CHECK(span_count({{{3.3, 4.4}}}, 8, rule, aa) == 0);              // a point
      CHECK(span_count({{{1.0, 1.0}, {6.5, 5.5}}}, 8, rule, aa) == 0);  // out and back
      CHECK(span_count({{{1.0, 1.0}, {3.0, 2.0}, {5.0, 3.0}, {7.0, 4.0}}}, 8, rule, aa) == 0);  // collinear
      CHECK(span_count({{{1.0, 2.0}, {7.0, 2.0}}}, 8, rule, aa) == 0);                          // horizontal
      CHECK(span_count({{{4.5, 0.5}, {4.5, 7.5}}}, 8, rule, aa) == 0);                          // vertical
      CHECK(span_count({}, 8, rule, aa) == 0);                                                  // nothing
    }
  }
  // A sliver thinner than half an 8-bit step per pixel rounds to nothing; a wider one does not.
  CHECK(span_count({rectangle(0.5, 1.0, 0.5 + 0.5 / 255.0 * 0.9, 7.0)}, 8, FillRule::kNonZero) == 0);
  const CoverageMask sliver = render_curvescan({rectangle(0.5, 1.0, 0.52, 7.0)}, 8, 8, FillRule::kNonZero);
  CHECK(sliver.at(0, 3) == 5);  // round(0.02 · 255) = 5
}

TEST_CASE("a million edges: a 10^6-gon circle matches its exact area and interior", "[named][large]") {
  constexpr int kEdges = 1'000'000;
  constexpr int kSize = 512;
  const Point centre{256.3, 255.7};
  constexpr double kRadius = 200.0;
  const Contour circle = regular_polygon(centre, kRadius, kRadius, kEdges, 0.1);
  REQUIRE(circle.size() == static_cast<std::size_t>(kEdges));
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const CoverageMask m = render_curvescan({circle}, kSize, kSize, rule);
    // Area of the regular n-gon: n/2 · r² · sin(2π/n). The mask rounds each of the ~2·2πr boundary pixels
    // by at most 1/2 step: |Σ - area| <= 2·2π·200·0.5/255 ≈ 4.9 px.
    const double area = 0.5 * kEdges * kRadius * kRadius * std::sin(2.0 * std::numbers::pi / kEdges);
    CHECK(std::abs(m.total() - area) <= 4.9);
    // Pixels whose square lies entirely inside (outside) the circle are 255 (0). The polygon is inside the
    // circle by at most r(1 - cos(π/n)) ≈ 1e-9 px; one px of margin from the corners' distance is ample.
    for (int y = 0; y < kSize; y += 3) {
      for (int x = 0; x < kSize; x += 3) {
        const double d = std::hypot(x + 0.5 - centre.x, y + 0.5 - centre.y);
        if (d < kRadius - 1.0) REQUIRE(m.at(x, y) == 255);
        if (d > kRadius + 1.0) REQUIRE(m.at(x, y) == 0);
      }
    }
  }
}

TEST_CASE("aliased mode samples pixel centres with a consistent tie rule", "[named]") {
  // Centres on the left and top edges are inside, centres on the right and bottom edges are outside, so
  // abutting shapes split the pixels between them with no gap and no overlap.
  const Contour left = rectangle(2.5, 2.5, 5.5, 6.5);
  const Contour right = rectangle(5.5, 2.5, 8.5, 6.5);
  const CoverageMask a = render_curvescan({left}, 10, 10, FillRule::kNonZero, Antialias::kNone);
  const CoverageMask b = render_curvescan({right}, 10, 10, FillRule::kNonZero, Antialias::kNone);
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 10; ++x) {
      const bool row_in = y >= 2 && y < 6;
      CHECK(a.at(x, y) == (row_in && x >= 2 && x < 5 ? 255 : 0));
      CHECK(b.at(x, y) == (row_in && x >= 5 && x < 8 ? 255 : 0));
    }
  }
  // Even-odd star: the core (winding 2) is out, the points (winding 1) are in.
  const Contour pentagram = star_polygon({10.2, 10.1}, 9.0, 5, 2, -std::numbers::pi / 2);
  const CoverageMask nz = render_curvescan({pentagram}, 20, 20, FillRule::kNonZero, Antialias::kNone);
  const CoverageMask eo = render_curvescan({pentagram}, 20, 20, FillRule::kEvenOdd, Antialias::kNone);
  CHECK(nz.at(10, 10) == 255);
  CHECK(eo.at(10, 10) == 0);
}
