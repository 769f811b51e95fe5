// The general sweep's walk of a pair of neighbours a block of edges at a time (first_crossing_by_blocks,
// raster/scan/planar_checks.h): where the two chains' blocks are apart in x the joints down to the nearer
// block end are passed at once. The answer is first_crossing's, bit for bit; the joints walked fall.
// Counts, not times: ScanState::planar_joints_walked.
#include <algorithm>
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "coverage_mask.h"
#include "curvescan/raster/rasterizer.h"
#include "scan/edge_clip.h"
#include "scan/planar_checks.h"
#include "scan/rasterizer_impl.h"

using namespace curvescan;
using namespace curvescan::detail;

namespace {

constexpr int kBands = 10;
constexpr IntRect kWavesClip{0, 0, 640, 200};
/// Vertices every 0.25 px of height: 800 edges a side.
constexpr int kSteps = 800;

/// Ten bands 24 px wide, 60 px apart, whose sides swing by 20 px (x = 30 + 60 i + 20 sin(y / 10)), a wide
/// stroke's two sides: every side's whole x extent overlaps its neighbours', so every pair of neighbours is
/// walked, but over 16 edges (4 px of height) a side moves at most 8 px, so their blocks are apart.
std::vector<std::vector<Point>> waves() {
  std::vector<std::vector<Point>> shape;
  for (int i = 0; i < kBands; ++i) {
    std::vector<Point> band;
    for (int k = 0; k <= kSteps; ++k) {
      const double y = 0.25 * k;
      band.push_back({30.0 + 60.0 * i + 20.0 * std::sin(y / 10.0), y});
    }
    for (int k = kSteps; k >= 0; --k) {
      const double y = 0.25 * k;
      band.push_back({54.0 + 60.0 * i + 20.0 * std::sin(y / 10.0), y});
    }
    shape.push_back(band);
  }
  return shape;
}

void add_shape(ScanState& s, const std::vector<std::vector<Point>>& shape, IntRect clip) {
  s.clip = clip;
  for (const std::vector<Point>& contour : shape) {
    for (std::size_t i = 0; i < contour.size(); ++i) {
      clip_edge(contour[i], contour[(i + 1) % contour.size()], clip, s.edges);
    }
  }
  link_edges_into_chains(s);
}

}  // namespace

TEST_CASE("long neighbours apart block by block are walked a block at a time", "[raster][planar]") {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    ScanState s;
    add_shape(s, waves(), kWavesClip);
    REQUIRE(s.planar_chains.size() == 2 * kBands);
    REQUIRE(sweep_planar_chains(s, rule));
    // Every pair of neighbours once (no extents apart): a band's two sides, and a band's right side with the
    // next band's left.
    CHECK(s.planar_pairs_walked == 2 * kBands - 1);
    // Joint by joint each walk is 800 joints (15,200 in all). By blocks: a block passed and the joint at its
    // end, per 16 edges, plus the first and last comparisons.
    CHECK(s.planar_joints_walked <= (2 * kBands - 1) * (2 * (kSteps / kPlanarBlockEdges) + 2));
    CHECK(s.planar_joints_walked >= (2 * kBands - 1) * (kSteps / kPlanarBlockEdges));
  }
}

TEST_CASE("long neighbours walked by blocks are drawn as the reference draws them", "[raster][planar]") {
  // At most one step of 255: the same area summed in another order.
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const testing::ReferenceComparison result =
        testing::compare_with_reference(waves(), kWavesClip.x1, kWavesClip.y1, rule);
    CHECK(result.stats.planar_fills == 1);
    CHECK(result.violations == 0);
    CHECK(result.max_diff <= 1);
  }
}

TEST_CASE("a walk by blocks gives first_crossing's answer bit for bit", "[raster][planar]") {
  // Seeded random y-monotone chains of 40 to 400 edges (random steps in x and y), whose pairs run apart,
  // touch, cross once or many times; every pair is walked from the lower of their tops (and from heights
  // inside) to the higher of their bottoms both ways, and the two answers (and the steps of the plain walk,
  // as an upper bound) compared.
  std::mt19937 rng(20261128);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int compared = 0;
  int crossings = 0;
  int passed_blocks = 0;
  for (int trial = 0; trial < 40; ++trial) {
    ScanState s;
    s.clip = {0, 0, 400, 400};
    const int chains = 6;
    for (int c = 0; c < chains; ++c) {
      // One chain: a contour down one side and straight back up far right (the back edge is its own chain).
      std::vector<Point> down;
      double x = 40.0 + 50.0 * c + 20.0 * unit(rng);
      double y = 5.0 * unit(rng);
      const int n = 40 + static_cast<int>(360 * unit(rng));
      const double swing = trial % 2 == 0 ? 0.5 : 6.0;  // small swings stay apart, large ones cross
      for (int k = 0; k <= n; ++k) {
        down.push_back({x, y});
        x += swing * (unit(rng) - 0.5) + (trial % 4 == 1 ? 0.3 * std::sin(k / 7.0) : 0.0);
        y += 0.05 + 0.9 * unit(rng);
      }
      for (std::size_t i = 0; i + 1 < down.size(); ++i) clip_edge(down[i], down[i + 1], s.clip, s.edges);
    }
    link_edges_into_chains(s);
    s.planar_blocks.resize(s.edges.size());
    for (PlanarChain& chain : s.planar_chains)
      build_chain_blocks(s.edges.data(), s.planar_blocks.data(), chain);
    for (std::size_t i = 0; i < s.planar_chains.size(); ++i) {
      for (std::size_t j = 0; j < s.planar_chains.size(); ++j) {
        if (i == j) continue;
        for (const double at : {0.0, 0.3, 0.7}) {
          PlanarChain left = s.planar_chains[i];
          PlanarChain right = s.planar_chains[j];
          const double y0 = std::max(left.top, right.top);
          const double y1 = std::min(left.bottom, right.bottom);
          if (!(y1 > y0)) continue;
          const double from = y0 + at * (y1 - y0);
          cursor_at(s.edges.data(), left, from);
          cursor_at(s.edges.data(), right, from);
          std::uint64_t plain_steps = 0;
          std::uint64_t block_steps = 0;
          const double plain = first_crossing(s.edges.data(), left, right, from, y1, plain_steps);
          const double by_blocks = first_crossing_by_blocks(s.edges.data(), s.planar_blocks.data(), left,
                                                            right, from, y1, block_steps);
          INFO("trial " << trial << ", chains " << i << " and " << j << " from " << from);
          CHECK(std::bit_cast<std::uint64_t>(plain) == std::bit_cast<std::uint64_t>(by_blocks));
          ++compared;
          if (plain != std::numeric_limits<double>::infinity()) ++crossings;
          if (block_steps < plain_steps) ++passed_blocks;
        }
      }
    }
  }
  // The set exercises both outcomes and walks where blocks are passed.
  CHECK(compared > 2000);
  CHECK(crossings > 300);
  CHECK(passed_blocks > 300);
}
