// Rasterizer::rasterize_mask: the coverage of every pixel of the clip box written into a caller's buffer.
// Its scenes' coverage is checked against the reference scan in rasterizer_planar_test.cpp; here its
// contract: every byte of the box written (zeros included), a box anywhere on the plane (negative
// origin), boxes too wide for the dense accumulation (dense_coverage.h: more than 4096 columns) and
// non-planar fills taking the span scans into the same buffer, and a buffer of the wrong size untouched.
//
// Metric: against rasterize() painted into a zeroed mask, at most 1 step of 255 per pixel (the dense
// accumulation's float cells are off by < 5e-4 of a pixel, dense_coverage.h, which moves only values
// sitting within that of a rounding midpoint, by one step); equal (0) where both take the span scans.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdint>
#include <vector>

#include "coverage_mask.h"
#include "polygon_scenes.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

/// The coverage rasterize() sends as spans, painted into a zeroed box-sized mask.
std::vector<std::uint8_t> spans_as_mask(const Shape& shape, IntRect box, FillRule rule) {
  const int width = box.x1 - box.x0;
  const int height = box.y1 - box.y0;
  CoverageMask mask(width, height);
  // MaskSink expects a box at the origin: move the shape instead of the box.
  Shape moved = shape;
  for (Contour& contour : moved) {
    for (Point& p : contour) p = {p.x - box.x0, p.y - box.y0};
  }
  Rasterizer rasterizer(IntRect{0, 0, width, height});
  rasterizer.set_sweep_crossing_budget(0.0);  // crossing fills take the row scan, which this test is about
  add_shape(rasterizer, moved);
  MaskSink sink(mask);
  rasterizer.rasterize(rule, Antialias::kExact, sink);
  REQUIRE(sink.violations == 0);
  return mask.values;
}

struct MaskRun {
  std::vector<std::uint8_t> values;
  std::uint64_t planar_fills = 0;
};

MaskRun rasterize_mask(const Shape& shape, IntRect box, FillRule rule, std::uint8_t prefill) {
  MaskRun run;
  run.values.assign(static_cast<std::size_t>(box.x1 - box.x0) * static_cast<std::size_t>(box.y1 - box.y0),
                    prefill);
  Rasterizer rasterizer(box);
  rasterizer.set_sweep_crossing_budget(0.0);  // crossing fills take the row scan, which this test is about
  add_shape(rasterizer, shape);
  rasterizer.rasterize_mask(rule, run.values);
  run.planar_fills = rasterizer.stats().planar_fills;
  return run;
}

int max_difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
  REQUIRE(a.size() == b.size());
  int worst = 0;
  for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(int{a[i]} - int{b[i]}));
  return worst;
}

}  // namespace

TEST_CASE("rasterize_mask writes every pixel of a box anywhere on the plane", "[oracle][mask]") {
  // A ring (hole of the opposite orientation) in a box with a negative origin, and empty rows and columns
  // around it that a garbage-filled buffer must come back zero in.
  const IntRect box{-70, -30, -10, 20};
  const Shape ring = {regular_polygon({-40.3, -5.2}, 20, 17, 80), regular_polygon({-40.3, -5.2}, 9, 7, 40, 0.1, true)};
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const MaskRun dense = rasterize_mask(ring, box, rule, 0xa5);
    CHECK(dense.planar_fills == 1);
    CHECK(max_difference(dense.values, spans_as_mask(ring, box, rule)) <= 1);
    CHECK(dense.values.front() == 0);  // the box's corner, far from the ring
    CHECK(dense.values.back() == 0);
  }
}

TEST_CASE("rasterize_mask of an empty fill is all zero", "[oracle][mask]") {
  const MaskRun run = rasterize_mask({}, IntRect{0, 0, 23, 7}, FillRule::kNonZero, 0xff);
  CHECK(std::all_of(run.values.begin(), run.values.end(), [](std::uint8_t v) { return v == 0; }));
}

TEST_CASE("rasterize_mask takes the span scans where the dense accumulation does not apply", "[oracle][mask]") {
  // Too wide for the dense cells (4100 > 4096 columns): planar, accumulated row by row into the buffer.
  const IntRect wide{0, 0, 4100, 6};
  const Shape slanted = {{{3.2, 0.5}, {4090.7, 1.3}, {4095.1, 5.6}, {10.4, 4.9}}};
  const MaskRun planar = rasterize_mask(slanted, wide, FillRule::kNonZero, 0x33);
  CHECK(planar.planar_fills == 1);
  CHECK(max_difference(planar.values, spans_as_mask(slanted, wide, FillRule::kNonZero)) == 0);
  // Crossing chains: not planar, the row scan into the buffer.
  const IntRect box{0, 0, 64, 64};
  const Shape bow_tie = {{{8, 8}, {56, 56}, {56, 8}, {8, 56}}};
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const MaskRun crossing = rasterize_mask(bow_tie, box, rule, 0x77);
    CHECK(crossing.planar_fills == 0);
    CHECK(max_difference(crossing.values, spans_as_mask(bow_tie, box, rule)) == 0);
  }
}

TEST_CASE("rasterize_mask leaves a buffer of the wrong size untouched", "[oracle][mask]") {
  Rasterizer rasterizer(IntRect{0, 0, 8, 8});
  add_shape(rasterizer, {{{1, 1}, {7, 1}, {7, 7}, {1, 7}}});
  std::vector<std::uint8_t> too_small(63, 0x11);
  rasterizer.rasterize_mask(FillRule::kNonZero, too_small);
  CHECK(std::all_of(too_small.begin(), too_small.end(), [](std::uint8_t v) { return v == 0x11; }));
  std::vector<std::uint8_t> right(64, 0x11);
  rasterizer.rasterize_mask(FillRule::kNonZero, right);
  CHECK(right[9] == 255);  // pixel (1, 1): inside the square
  CHECK(right[0] == 0);
}

TEST_CASE(
    "rasterize_mask's byte pass at every row width: vector groups, the run past a row's end, the last row",
    "[oracle][mask]") {
  // The byte pass (dense_coverage.cpp) writes groups of 16 columns (eight lanes with AVX2, four without),
  // then groups of four, where every row but the last runs up to three bytes into the next row, which is
  // written after it; the last row finishes column by column. Widths 1 to 40 and heights 1 to 3 reach each
  // combination: a triangle leaving partial coverage in every row, and a rectangle covering its whole box
  // (full rows next to the right side, whose carry must not reach the next row). Both against the
  // plain reference scan (rasterize_reference: the span scans of small planar fills share the dense
  // accumulation, so they would not tell), every byte (the buffer starts as garbage).
  for (int width = 1; width <= 40; ++width) {
    for (int height = 1; height <= 3; ++height) {
      const IntRect box{0, 0, width, height};
      const double w = width;
      const double h = height;
      const Shape triangle = {{{0.3, 0.2}, {w - 0.4, 0.5 * h}, {0.7, h - 0.1}}};
      const Shape full = {{{0.0, 0.0}, {w, 0.0}, {w, h}, {0.0, h}}};
      for (const Shape& shape : {triangle, full}) {
        INFO("width " << width << " height " << height);
        const MaskRun dense = rasterize_mask(shape, box, FillRule::kNonZero, 0xa5);
        CHECK(dense.planar_fills == 1);
        CoverageMask reference(width, height);
        MaskSink sink(reference);
        Rasterizer oracle(box);
        add_shape(oracle, shape);
        oracle.rasterize_reference(FillRule::kNonZero, Antialias::kExact, sink);
        REQUIRE(sink.violations == 0);
        CHECK(max_difference(dense.values, reference.values) <= 1);
      }
    }
  }
}
