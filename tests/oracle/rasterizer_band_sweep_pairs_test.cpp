// The row scan's band sweep (raster/scan/rasterizer_sweep.cpp; essay of rasterizer.cpp, step 3) at its
// heights of one crossing pair: an adjacent pair is swapped with each x computed once, and a pair whose
// swap leaves a neighbour out of order (crossing heights rounded apart where several pieces cross at
// nearly one point) takes the general repair, which re-sorts and widens the range. Held to the plain
// reference scan (rasterize_reference) and to the count of crossings the geometry has, which the sweep
// reports (RasterizerStats::crossings): every pair of pieces crossing inside a band, once.
//
// The whole-fill sweep is turned off (set_sweep_crossing_budget(0)), so these fills take the row scan.
// Metric: the same exact area summed in another order may round the other way at a midpoint: at most 1
// step of 255 per pixel (as in rasterizer_crossings_test.cpp).
#include <catch2/catch.hpp>
#include <random>

#include "coverage_mask.h"
#include "polygon_scenes.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

/// `bars` thin parallelograms from the top to the bottom of a 64 x 64 clip, each through `centre` at its
/// own slope: the two long edges of one bar are parallel (they never cross), every other pair of long
/// edges crosses once, all near the centre, in one row. The short top and bottom edges are horizontal
/// (the clipper drops them).
Shape bars_through(Point centre, int bars, double width) {
  Shape shape;
  for (int i = 0; i < bars; ++i) {
    // dx/dy in (-0.9, 0.9): every bar stays inside the clip (x from 4.8 to 59.8), so no edge is clipped
    // to the clip's left side, where the clipped parts of two edges would meet.
    const double slope = -0.9 + 1.8 * (i + 0.5) / bars;
    const auto x_at = [&](double y, double offset) { return centre.x + offset + slope * (y - centre.y); };
    shape.push_back({{x_at(2, 0), 2}, {x_at(62, 0), 62}, {x_at(62, width), 62}, {x_at(2, width), 2}});
  }
  return shape;
}

}  // namespace

TEST_CASE("pieces crossing at nearly one point: every pair once, and the reference's coverage",
          "[oracle][crossings]") {
  for (const double width : {0.5, 1e-3, 1e-9}) {
    for (const int bars : {2, 3, 8, 16}) {
      const Shape shape = bars_through({32.3, 32.55}, bars, width);
      for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
        INFO(bars << " bars of width " << width << ", "
                  << (rule == FillRule::kNonZero ? "nonzero" : "even-odd"));
        const ReferenceComparison run = compare_with_reference(shape, 64, 64, rule);
        CHECK(run.stats.planar_fills == 0);
        CHECK(run.stats.sampled_bands + run.stats.sampled_rows == 0);
        // 2·bars long edges; each pair crosses once except the two edges of one bar.
        const std::uint64_t edges = 2 * static_cast<std::uint64_t>(bars);
        CHECK(run.stats.crossings == edges * (edges - 1) / 2 - static_cast<std::uint64_t>(bars));
        CHECK(run.max_diff <= 1);
        CHECK(run.violations == 0);
      }
    }
  }
}

TEST_CASE("lines through nearly one point, crossing at heights rounding apart, match the reference",
          "[oracle][crossings]") {
  // Segments through points within `spread` of one point: their crossing heights differ by about that,
  // or only by their rounding, and the pairs cross alone at their heights with their neighbours a hair
  // away: the heights where a swapped pair may leave a neighbour out of order (a few of these trials do,
  // so the general repair is taken after the pair's swap).
  std::mt19937 rng(77);
  for (const double spread : {1e-6, 1e-10, 1e-13}) {
    std::uniform_real_distribution<double> jitter(-spread, spread);
    std::uniform_real_distribution<double> slope(-0.9, 0.9);
    for (int trial = 0; trial < 50; ++trial) {
      Shape shape;
      for (int i = 0; i < 6; ++i) {
        const double cx = 32.3 + jitter(rng);
        const double cy = 32.55 + jitter(rng);
        const double a = slope(rng);
        const double b = slope(rng);
        // A triangle whose long side goes through the point (a second side through it too when the
        // point lies on it, a third never does): the six long sides cross near the point.
        shape.push_back({{cx + a * (2 - cy), 2}, {cx + a * (62 - cy), 62}, {cx + b * (62 - cy), 62}});
      }
      for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
        INFO("spread " << spread << ", trial " << trial << ", "
                       << (rule == FillRule::kNonZero ? "nonzero" : "even-odd"));
        const ReferenceComparison run = compare_with_reference(shape, 64, 64, rule);
        CHECK(run.stats.sampled_bands + run.stats.sampled_rows == 0);
        CHECK(run.max_diff <= 1);
        CHECK(run.violations == 0);
      }
    }
  }
}

TEST_CASE("random polylines of lone crossings match the reference in the row scan", "[oracle][crossings]") {
  // 60 to 200 random segments in a 64 x 64 clip: thousands of crossings, most of them alone at their
  // height and between neighbours, the others in rows where several meet.
  std::mt19937 rng(2026);
  std::uniform_real_distribution<double> pos(0.0, 64.0);
  for (const int segments : {60, 120, 200}) {
    Contour polyline;
    for (int i = 0; i < segments; ++i) polyline.push_back({pos(rng), pos(rng)});
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      INFO(segments << " segments, " << (rule == FillRule::kNonZero ? "nonzero" : "even-odd"));
      const ReferenceComparison run = compare_with_reference({polyline}, 64, 64, rule);
      CHECK(run.stats.crossings > 0);
      CHECK(run.stats.sampled_bands + run.stats.sampled_rows == 0);
      CHECK(run.max_diff <= 1);
      CHECK(run.violations == 0);
    }
  }
}
