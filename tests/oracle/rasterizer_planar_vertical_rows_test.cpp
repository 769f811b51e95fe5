// The planar row accumulator's repeated rows (raster/scan/rasterizer_planar.cpp, accumulate_planar): where
// every boundary piece of a row is one vertical edge crossing the whole row, the rows below that the same
// edges cross entirely are copies of it instead of being accumulated.
//
// Two references:
//  - the general accumulation of the same shape with every vertical edge cut at every integer row (the
//    same boundary, but each row then meets a new edge, so no row is repeated): the repeated rows claim the
//    very arithmetic of the general path (x_at of a vertical edge is its x at every height, h = 1), so the
//    masks must be identical, byte for byte;
//  - the plain reference scan (rasterize_reference), which resolves every row from scratch: within 1 step
//    of 255, as every planar scene of rasterizer_planar_test.cpp (the same exact area summed in another
//    order may round the other way within ~1e-12 of a midpoint).
// Scenes are wider than the small-fill box (128 columns), so they take the row accumulator: rectangles
// with fractional and integer sides, overlapping (winding 2) and nested (holes), staircases whose steps
// start or end inside a row, shapes crossing the clip's left side (the clipper's vertical edges) and
// leaving it on the right (no leave edge), and rectilinear shapes beside slanted ones in the same rows.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "coverage_mask.h"
#include "polygon_scenes.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr int kWidth = 300, kHeight = 220;

/// The same contour with every vertical edge cut at each integer height it crosses.
Contour cut_vertical_edges(const Contour& contour) {
  Contour out;
  for (std::size_t i = 0; i < contour.size(); ++i) {
    const Point a = contour[i];
    const Point b = contour[(i + 1) % contour.size()];
    out.push_back(a);
    if (a.x != b.x) continue;
    if (a.y < b.y) {
      for (double y = std::floor(a.y) + 1.0; y < b.y; y += 1.0) out.push_back({a.x, y});
    } else {
      for (double y = std::ceil(a.y) - 1.0; y > b.y; y -= 1.0) out.push_back({a.x, y});
    }
  }
  return out;
}

struct Masks {
  CoverageMask fast, cut, reference;
  int violations = 0;
  std::uint64_t planar_fills = 0;
};

Masks render(const Shape& shape, FillRule rule) {
  Masks masks{CoverageMask(kWidth, kHeight), CoverageMask(kWidth, kHeight), CoverageMask(kWidth, kHeight)};
  const IntRect clip{0, 0, kWidth, kHeight};
  Rasterizer rasterizer(clip);
  add_shape(rasterizer, shape);
  MaskSink fast_sink(masks.fast), reference_sink(masks.reference);
  rasterizer.rasterize(rule, Antialias::kExact, fast_sink);
  masks.planar_fills = rasterizer.stats().planar_fills;
  rasterizer.rasterize_reference(rule, Antialias::kExact, reference_sink);

  Shape cut_shape;
  for (const Contour& contour : shape) cut_shape.push_back(cut_vertical_edges(contour));
  Rasterizer cut_rasterizer(clip);
  add_shape(cut_rasterizer, cut_shape);
  MaskSink cut_sink(masks.cut);
  cut_rasterizer.rasterize(rule, Antialias::kExact, cut_sink);
  masks.planar_fills += cut_rasterizer.stats().planar_fills;
  masks.violations = fast_sink.violations + reference_sink.violations + cut_sink.violations;
  return masks;
}

void check(const Shape& shape) {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    INFO((rule == FillRule::kNonZero ? "nonzero" : "even-odd"));
    const Masks masks = render(shape, rule);
    CHECK(masks.planar_fills == 2);  // both took the planar path
    CHECK(masks.violations == 0);
    CHECK(masks.fast.values == masks.cut.values);
    CHECK(max_abs_diff(masks.fast, masks.reference) <= 1);
  }
}

}  // namespace

TEST_CASE("repeated rows of vertical edges equal the general accumulation", "[oracle][planar]") {
  const std::vector<Shape> scenes = {
      {rect(0, 0, kWidth, kHeight)},
      {rect(10.25, 3.5, 280.75, 200.125)},
      {rect(10, 3, 280, 200)},
      {rect(10.5, 20.5, 200.5, 120.5), rect(100.25, 60.75, 290.5, 180.25)},  // overlapping: winding 2
      {rect(5, 5, 295, 215), cut_vertical_edges(rect(40.5, 40.5, 250.5, 180.5))},
      {rect(5, 5, 295, 215), {{40.5, 40.5}, {40.5, 180.5}, {250.5, 180.5}, {250.5, 40.5}}},  // a hole
      {rect(-50, 10.5, 150.5, 100.5), rect(-20, 120, 30.5, 130)},  // the clip's left side
      {rect(150.5, 30.25, 400, 190.75)},                           // leaves the clip on the right
      {{{20, 10}, {60.5, 10}, {60.5, 40.25}, {120.75, 40.25}, {120.75, 90.5}, {200, 90.5}, {200, 150.75},
        {260.5, 150.75}, {260.5, 210}, {20, 210}}},  // a staircase: steps inside rows
      {rect(10, 10, 140, 200), {{160, 10}, {290, 30.5}, {280, 200}, {170, 190}}},  // beside a slanted shape
  };
  int index = 0;
  for (const Shape& shape : scenes) {
    INFO("scene " << index++);
    check(shape);
  }
}

TEST_CASE("random rectilinear fills: repeated rows equal the general accumulation", "[oracle][planar]") {
  std::mt19937 rng(18018);
  std::uniform_real_distribution<double> x(-20.0, kWidth + 20.0), y(-10.0, kHeight + 10.0);
  std::uniform_int_distribution<int> count(1, 6), grid(0, 1);
  for (int trial = 0; trial < 60; ++trial) {
    Shape shape;
    const int rects = count(rng);
    for (int i = 0; i < rects; ++i) {
      // Half the trials on the pixel grid (integer sides), half anywhere.
      const bool snap = grid(rng) == 0;
      auto pick = [&](std::uniform_real_distribution<double>& d) { return snap ? std::round(d(rng)) : d(rng); };
      double x0 = pick(x), x1 = pick(x), y0 = pick(y), y1 = pick(y);
      if (x0 == x1 || y0 == y1) continue;
      Contour c = rect(std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1));
      if (i % 2 == 1) std::reverse(c.begin(), c.end());  // both orientations: holes and windings ±2
      shape.push_back(c);
    }
    if (shape.empty()) continue;
    INFO("trial " << trial);
    check(shape);
  }
}
