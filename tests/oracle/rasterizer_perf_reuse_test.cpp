// Fast paths of the scan that the other oracle tests reach only by chance:
//  - per-fill costs proportional to what is touched (CoverageRow::reset keeps its zeroed buffer while the
//    width is unchanged; the row buckets span only the rows the edges start in): one Rasterizer reused
//    across fills of changing clips, rules and modes must give what a fresh one gives, byte for byte;
//  - edges much shorter than a pixel inside a chain go straight to the row accumulator, not through the
//    per-edge runs: held to the plain reference scan.
//
// Metrics: a reused rasterizer does the same operations in the same order as a fresh one, so its output
// must be identical (difference 0). Against the reference, the same exact area is summed in another
// order: an area within ~1e-12 of a rounding midpoint may round either way, so 1 step (as in
// exact_coverage_test.cpp); aliased output makes the same comparisons, so it must be identical.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <span>
#include <vector>

#include "coverage_mask.h"
#include "polygon_scenes.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

/// Moves spans by (-dx, -dy) on their way to a mask sink, so clips away from the origin fit a mask.
class OffsetSink final : public SpanSink {
 public:
  OffsetSink(SpanSink& inner, int dx, int dy) : inner_(inner), dx_(dx), dy_(dy) {}
  void blend(std::span<const Span> spans) override {
    moved_.assign(spans.begin(), spans.end());
    for (Span& s : moved_) {
      s.x -= dx_;
      s.y -= dy_;
    }
    inner_.blend(moved_);
  }

 private:
  SpanSink& inner_;
  int dx_, dy_;
  std::vector<Span> moved_;
};

/// Renders `shape` (device pixels) clipped to `clip` into a mask of the clip's size, whose (0, 0) is the
/// clip's top-left pixel.
CoverageMask render_with(Rasterizer& rasterizer, const Shape& shape, IntRect clip, FillRule rule,
                         Antialias antialias, ScanPath path, int* violations) {
  CoverageMask mask(clip.x1 - clip.x0, clip.y1 - clip.y0);
  MaskSink sink(mask);
  OffsetSink offset(sink, clip.x0, clip.y0);
  rasterizer.reset(clip);
  add_shape(rasterizer, shape);
  if (path == ScanPath::kOptimised) {
    rasterizer.rasterize(rule, antialias, offset);
  } else {
    rasterizer.rasterize_reference(rule, antialias, offset);
  }
  *violations += sink.violations;
  return mask;
}

/// A circle of `count` edges (much shorter than a pixel when count is large).
Contour fine_circle(Point centre, double radius, int count, double phase) {
  Contour out;
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * std::numbers::pi * i / count + phase;
    out.push_back({centre.x + radius * std::cos(a), centre.y + radius * std::sin(a)});
  }
  return out;
}

}  // namespace

TEST_CASE("a rasterizer reused across fills of changing clips gives what a fresh one gives",
          "[oracle][perf][reuse]") {
  std::mt19937 rng(1234567);
  std::uniform_int_distribution<int> side(1, 48);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> vertices(3, 30);
  Rasterizer reused;
  int violations = 0;
  for (int fill = 0; fill < 300; ++fill) {
    // Widths repeat often (the O(1) reset), and change (the full one); heights too (the buckets).
    const int width = fill % 3 == 0 ? side(rng) : 32;
    const int height = fill % 5 == 0 ? side(rng) : 24;
    // The same width at another origin keeps the accumulator but moves its first column.
    const int x0 = fill % 6 == 1 ? side(rng) - 20 : 0;
    const int y0 = fill % 4 == 1 ? side(rng) - 20 : 0;
    const IntRect clip{x0, y0, x0 + width, y0 + height};
    Shape shape;
    if (fill % 2 == 0) {
      shape.push_back(random_polygon(rng, x0 - 3.0, y0 - 3.0, x0 + width + 3.0, y0 + height + 3.0, vertices(rng)));
    } else {
      // A small shape somewhere in the clip: most rows and columns of the clip untouched.
      const Point c{x0 + unit(rng) * width, y0 + unit(rng) * height};
      shape.push_back(fine_circle(c, 0.5 + 4.0 * unit(rng), 12 + fill % 40, unit(rng)));
    }
    const FillRule rule = fill % 4 < 2 ? FillRule::kNonZero : FillRule::kEvenOdd;
    const Antialias aa = fill % 7 == 0 ? Antialias::kNone : Antialias::kExact;
    // Every so often the reused rasterizer runs the reference scan, which shares the row accumulator.
    const ScanPath path = fill % 11 == 0 ? ScanPath::kReference : ScanPath::kOptimised;
    Rasterizer fresh;
    const CoverageMask a = render_with(reused, shape, clip, rule, aa, path, &violations);
    const CoverageMask b = render_with(fresh, shape, clip, rule, aa, path, &violations);
    INFO("fill " << fill << " clip " << width << " x " << height);
    REQUIRE(max_abs_diff(a, b) == 0);
  }
  CHECK(violations == 0);
}

TEST_CASE("chains of edges much shorter than a pixel match the reference scan", "[oracle][perf][chains]") {
  std::mt19937 rng(271828);
  std::uniform_real_distribution<double> centre(8.0, 24.0);
  std::uniform_real_distribution<double> radius(2.0, 9.0);
  constexpr int kSize = 32;
  for (int scene = 0; scene < 24; ++scene) {
    Shape shape;
    // 400-900 edges on circles of circumference 12-57 px: edges of 0.02-0.14 px, many per cell.
    shape.push_back(fine_circle({centre(rng), centre(rng)}, radius(rng), 400 + 20 * scene, 0.1 * scene));
    if (scene % 2 == 1) shape.push_back(fine_circle({centre(rng), centre(rng)}, radius(rng), 500, 0.2));
    if (scene % 3 == 2) std::reverse(shape[0].begin(), shape[0].end());  // the other winding direction
    const FillRule rule = scene % 4 < 2 ? FillRule::kNonZero : FillRule::kEvenOdd;
    for (const Antialias aa : {Antialias::kExact, Antialias::kNone}) {
      int violations_fast = 0;
      int violations_ref = 0;
      const CoverageMask fast =
          render_curvescan(shape, kSize, kSize, rule, aa, ScanPath::kOptimised, &violations_fast);
      const CoverageMask ref = render_curvescan(shape, kSize, kSize, rule, aa, ScanPath::kReference, &violations_ref);
      INFO("scene " << scene << " aliased " << (aa == Antialias::kNone));
      CHECK(violations_fast == 0);
      CHECK(violations_ref == 0);
      REQUIRE(max_abs_diff(fast, ref) <= (aa == Antialias::kExact ? 1 : 0));
    }
  }
}
