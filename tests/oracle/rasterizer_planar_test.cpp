// The planar fast path of the exact scan (raster/scan/rasterizer_planar.cpp): a fill whose monotone chains
// never cross is accumulated straight from its boundary chains. Held to the plain reference scan
// (rasterize_reference), which resolves every row from scratch, on scenes chosen to reach the proof's
// corners: ties at contour tips, touching and coincident contours, nested contours of either orientation
// (winding 2 is planar but not a boundary under nonzero), clipping on every side, sub-pixel edges; and
// held to fall back (RasterizerStats::planar_fills == 0) wherever chains cross or the proof's budget
// runs out, with the same output.
//
// Every scene also goes through Rasterizer::rasterize_mask, which accumulates a planar fill densely in float
// (raster/scan/dense_coverage.h) and must take the same path (planar_fills) and give the same coverage.
//
// Metric: the same exact area summed in another order, so an area within ~1e-12 of a rounding midpoint
// may round either way: at most 1 step of 255 per pixel (as in exact_coverage_test.cpp), and no SpanSink
// contract violation. The dense mask's float cells are off by < 5e-4 (dense_coverage.h), an eighth of a
// step, so it too is within 1 step of the reference.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "coverage_mask.h"
#include "polygon_scenes.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr int kSize = 64;

// Crossing fills take the row scan here (no sweep budget), which this test is about.
SpanAndMaskComparison compare_with_reference(const Shape& shape, FillRule rule,
                                             IntRect clip = {0, 0, kSize, kSize}) {
  return compare_spans_and_mask_with_reference(shape, rule, clip, 0.0);
}

/// Both scans (spans and the dense mask) took the planar path, or both the row scan, and match the
/// reference within 1 step.
void check_run(const SpanAndMaskComparison& run, bool planar) {
  CHECK(run.stats.planar_fills == (planar ? 1u : 0u));
  CHECK(run.mask_planar_fills == (planar ? 1u : 0u));
  CHECK(run.max_diff <= 1);
  CHECK(run.mask_max_diff <= 1);
  CHECK(run.violations == 0);
}

/// A circle of `count` edges; counter-clockwise on screen when `reverse`.
Contour circle(Point centre, double radius, int count, bool reverse = false) {
  Contour out;
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * std::numbers::pi * i / count;
    out.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
  }
  return reverse ? reversed(out) : out;
}

}  // namespace

TEST_CASE("planar fills take the planar path and match the reference scan", "[oracle][planar]") {
  struct Scene {
    std::string name;
    Shape shape;
  };
  const std::vector<Scene> scenes = {
      {"diamond: two chains start and end at one point", {{{32, 4}, {60, 32}, {32, 60}, {4, 32}}}},
      {"ring: hole of the opposite orientation", {circle({32, 32}, 25, 90), circle({32, 32}, 12, 60, true)}},
      {"nested, same orientation: winding 2 inside", {circle({32, 32}, 25, 90), circle({32, 32}, 12, 60)}},
      {"two squares sharing an edge", {rect(8.3, 8.3, 32.5, 40.2), rect(32.5, 8.3, 55.1, 40.2)}},
      {"two squares touching at a corner", {rect(8.3, 8.3, 32.5, 32.5), rect(32.5, 32.5, 55.1, 55.1)}},
      {"a contour drawn twice", {circle({30, 34}, 20, 33), circle({30, 34}, 20, 33)}},
      {"a contour and its reverse", {circle({30, 34}, 20, 33), circle({30, 34}, 20, 33, true)}},
      {"sub-pixel edges (a circle of 2000 edges)", {circle({31.3, 30.7}, 27.9, 2000)}},
      {"past every side of the clip", {circle({32, 32}, 45, 120), circle({32, 32}, 20, 40, true)}},
      {"left of the clip: vertical edges on its left side", {rect(-30, 5, 10, 20), rect(-20, 30, 12, 50)}},
      {"thin slivers narrower than a pixel", {rect(10.1, 3, 10.4, 60), rect(10.4, 3, 10.6, 60), rect(20, 5.5, 50, 5.7)}},
  };
  for (const Scene& scene : scenes) {
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      INFO(scene.name << (rule == FillRule::kNonZero ? ", nonzero" : ", even-odd"));
      const SpanAndMaskComparison run = compare_with_reference(scene.shape, rule);
      check_run(run, true);
    }
  }
}

TEST_CASE("random simple polygons, nested or side by side, stay planar and exact", "[oracle][planar]") {
  std::mt19937 rng(20261122);
  std::uniform_real_distribution<double> jitter(0.0, 0.9);
  std::uniform_real_distribution<double> offset(-4.0, 4.0);
  std::uniform_int_distribution<int> vertices(4, 60);
  // A polygon star-shaped around `centre`: one vertex per sector of 2π/n at a random angle inside it, so
  // consecutive vertices are less than π apart and the centre is in its kernel.
  const auto star_shaped = [&](Point centre, double r_min, double r_max) {
    std::uniform_real_distribution<double> radius(r_min, r_max);
    const int n = vertices(rng);
    Contour out;
    for (int i = 0; i < n; ++i) {
      const double a = 2.0 * std::numbers::pi * (i + jitter(rng)) / n;
      const double r = radius(rng);
      out.push_back({centre.x + r * std::cos(a), centre.y + r * std::sin(a)});
    }
    return out;
  };
  for (int trial = 0; trial < 200; ++trial) {
    // An outer polygon; copies of it shrunk towards its centre lie inside it: a hole of the opposite
    // orientation and an island inside the hole. And a polygon beside it, disjoint from the rest.
    const Point centre{32.0 + offset(rng), 32.0 + offset(rng)};
    const Contour outer = star_shaped(centre, 12.0, 26.0);
    const auto shrunk = [&](double factor) {
      Contour out;
      for (const Point p : outer) out.push_back({centre.x + factor * (p.x - centre.x), centre.y + factor * (p.y - centre.y)});
      return out;
    };
    const Shape shape = {outer, reversed(shrunk(0.6)), shrunk(0.3), star_shaped({96.0 + offset(rng), 32.0}, 4.0, 24.0)};
    const FillRule rule = trial % 2 == 0 ? FillRule::kNonZero : FillRule::kEvenOdd;
    INFO("trial " << trial);
    const SpanAndMaskComparison run = compare_with_reference(shape, rule, {0, 0, 2 * kSize, kSize});
    check_run(run, true);
  }
}

TEST_CASE("crossing chains fall back to the row scan with the same output", "[oracle][planar]") {
  const std::vector<Shape> crossing = {
      {star_polygon({32, 32}, 28, 7, 3)},                               // {7/3}: self-intersecting
      {{{8, 8}, {56, 56}, {56, 8}, {8, 56}}},                           // a bow tie
      {rect(8, 8, 40, 40), {{24, 20}, {60, 24}, {50, 60}, {20, 44}}},  // two overlapping contours
  };
  for (const Shape& shape : crossing) {
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      const SpanAndMaskComparison run = compare_with_reference(shape, rule);
      check_run(run, false);
    }
  }
}

TEST_CASE("planar fills wider than a small box accumulate row by row, as exactly", "[oracle][planar]") {
  // Fills of at most 128 columns and 32768 pixels (the scenes above) are accumulated densely over their
  // box and cut into spans (accumulate_small_planar); wider ones take the row accumulator. The same
  // scenes four times larger, and a wide thin one, on a 256 px clip.
  const auto scaled = [](Shape shape) {
    for (Contour& contour : shape) {
      for (Point& p : contour) p = {4.0 * p.x + 0.37, 4.0 * p.y - 0.21};
    }
    return shape;
  };
  const std::vector<Shape> shapes = {
      scaled({circle({32, 32}, 25, 90), circle({32, 32}, 12, 60, true)}),
      scaled({circle({32, 32}, 25, 90), circle({32, 32}, 12, 60)}),
      scaled({rect(8.3, 8.3, 32.5, 40.2), rect(32.5, 8.3, 55.1, 40.2)}),
      scaled({circle({32, 32}, 45, 120), circle({32, 32}, 20, 40, true)}),
      {rect(3.5, 100.25, 250.75, 104.5)},
  };
  for (const Shape& shape : shapes) {
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      check_run(compare_with_reference(shape, rule, {0, 0, 256, 256}), true);
    }
  }
}

TEST_CASE("chains that become neighbours again are held to their order below", "[oracle][planar]") {
  // The proof checks a pair of chains once, when they become neighbours, down to where the first of them
  // ends. Here the outer contour's two chains are neighbours at the top, are parted by the holes (two or
  // three chains between them), and are neighbours again below the holes: where the outer contour
  // crosses itself below (a bow tie under the holes) the fill must fall back; where it does not, it stays
  // planar. Either way the coverage is the reference scan's.
  const Contour crossing_below = {{8, 4}, {56, 4}, {56, 30}, {10, 58}, {54, 58}, {8, 30}};
  const Contour waisted = {{8, 4}, {56, 4}, {56, 30}, {40, 58}, {24, 58}, {8, 30}};
  const Contour hole = reversed(rect(20.5, 10.25, 40.5, 20.75));
  const Contour second_hole = reversed(rect(14.5, 22.5, 28.5, 26.5));
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    INFO((rule == FillRule::kNonZero ? "nonzero" : "even-odd"));
    check_run(compare_with_reference({crossing_below, hole}, rule), false);
    check_run(compare_with_reference({crossing_below, hole, second_hole}, rule), false);
    check_run(compare_with_reference({waisted, hole}, rule), true);
    check_run(compare_with_reference({waisted, hole, second_hole}, rule), true);
  }
}

TEST_CASE("a fill whose proof outgrows its budget falls back", "[oracle][planar]") {
  // A comb of n thin teeth, each starting and ending at its own height: 2n events, each seeing up to 2n
  // chains, so the sweep costs ~4n^2 steps against a budget of 32 * (2n edges) + 4096. Few teeth fit the
  // budget; many do not. Both must give the reference's coverage.
  const auto comb = [](int teeth, double pitch) {
    Shape shape;
    for (int i = 0; i < teeth; ++i) {
      const double x = 1.0 + i * pitch;
      shape.push_back(rect(x, 1.0 + 0.01 * i, x + 0.5 * pitch, 60.0 - 0.013 * i));
    }
    return shape;
  };
  const SpanAndMaskComparison few = compare_with_reference(comb(10, 6.0), FillRule::kNonZero);
  check_run(few, true);
  const SpanAndMaskComparison many = compare_with_reference(comb(600, 0.1), FillRule::kNonZero);
  check_run(many, false);
}

TEST_CASE("rows whose chains cross in some bands only match the reference scan", "[oracle][chains]") {
  // Overlapping ellipses of 100-1500 sub-pixel edges, alternating orientation: every row holds many
  // chain joints, and its chains cross in the bands where two ellipses overlap and nowhere else, so the
  // row scan resolves those bands edge by edge and the others chain by chain (essay, step 6).
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> position(4.0, 60.0), radius(2.0, 15.0), phase(0.0, 6.28);
  std::uniform_int_distribution<int> edge_count(100, 1500);
  std::uint64_t crossings = 0;
  for (int trial = 0; trial < 60; ++trial) {
    Shape shape;
    for (int i = 0; i < 2 + trial % 4; ++i) {
      const Point centre{position(rng), position(rng)};
      const double r = radius(rng);
      const double start = phase(rng);
      const int n = edge_count(rng);
      Contour ellipse;
      for (int j = 0; j < n; ++j) {
        const double a = start + 2.0 * std::numbers::pi * j / n;
        ellipse.push_back({centre.x + r * std::cos(a), centre.y + 0.7 * r * std::sin(a)});
      }
      shape.push_back(i % 2 == 1 ? reversed(ellipse) : ellipse);
    }
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      INFO("trial " << trial);
      Rasterizer rasterizer(IntRect{0, 0, kSize, kSize});
      // Crossing fills take the row scan, which this test is about.
      rasterizer.set_sweep_crossing_budget(0.0);
      add_shape(rasterizer, shape);
      CoverageMask fast(kSize, kSize), reference(kSize, kSize);
      MaskSink fast_sink(fast), reference_sink(reference);
      rasterizer.rasterize(rule, Antialias::kExact, fast_sink);
      crossings += rasterizer.stats().crossings;
      CHECK(rasterizer.stats().sampled_bands == 0);
      rasterizer.rasterize_reference(rule, Antialias::kExact, reference_sink);
      CHECK(max_abs_diff(fast, reference) <= 1);
      CHECK(fast_sink.violations + reference_sink.violations == 0);
    }
  }
  CHECK(crossings > 0);  // the scenes do reach the crossing bands
}
