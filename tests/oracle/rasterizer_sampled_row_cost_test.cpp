// Sampled rows of mutually crossing edges: their cost is linear in the row's edges, and their coverage is
// that of their sixteen sub-scanlines.
//
// A row whose crossings exceed its work budget is sampled by 16 sub-scanlines, each exact in x (essay of
// raster/scan/rasterizer.cpp, step 7). Each sub-scanline used to sort all of the row's edges; where they
// cross each other everywhere (10^6 random segments in a 512² clip: 3·10^5 edges a row, about 1.4·10^7
// inversions between two sub-scanlines) the sort ran past adaptive_sort's insertion cap into std::sort,
// O(n log n) sixteen times a row, and 10^6 segments took 23× the time of 10^5. Now each sub-scanline
// counts its edges' directions in column buckets and sorts only the edges of the buckets where the
// winding number may reach a boundary of the fill rule (raster/scan/sub_scanline_columns.cpp), and the
// search for a row's independent groups orders the edges' extents by buckets too
// (rasterizer_row_groups.cpp).
//
// The scene reproduces that density on a small canvas: a closed polyline through random points of a
// 512 x 2 clip. Crossing is invariant under the affine map from the 512² square, so the segments cross as
// often (about 0.12·n² times), but over 2 rows instead of 512: at 6000 segments a row holds about 5000
// edges and two sub-scanlines differ by about 10^5 inversions, past the n·⌈log2(n + 2)⌉ = 6.5·10^4 cap,
// as at 10^6 segments in the square. A zero crossing budget samples every row.
//
// Work, from Rasterizer::stats() (independent of the machine and its load), per edge of a row and
// sub-scanline: the pass that finds each edge's x and counts it in its bucket (1), the pass that gathers
// the edges of the buckets that may hold a boundary (1), the walk over the buckets (1/4), and the placing
// of the gathered edges into their buckets, their sorts inside the buckets and their walk (where the
// winding number is near zero: under a third of the edges here); per row, once, the search for groups
// (about 2¼ per edge) and the ordering of the row for the next one (about 4–5 per edge), so under 1/2 per
// sub-scanline. That is under 4 (3.92 and 3.92 measured; 3.72 and 3.81 before the gathering pass was
// counted, when the gathered edges were sorted all at once); the
// bound is 6, with room for the uneven spread of the edges over the buckets. Doubling the segments may
// raise that figure by at most 5 % (measured +2.6 %: a few more buckets near zero winding and more
// inversions in the row's ordering, each bounded per bucket). The code before this change visited 17.3
// and 18.4 per edge and sub-scanline at 6000 and 12000 segments (a full sort in every sub-scanline and
// one of the extents per row: a log n factor, +6.7 % for 2× the segments).
//
// Coverage: against a plain implementation of the same sampling written here (every sub-scanline sorted
// whole, the filled intervals cut into pixel columns): within 1 step of 255, as the same sum in another
// order may round the other way at a midpoint.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "coverage_mask.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr int kWidth = 512;
constexpr int kHeight = 2;
constexpr int kSubScanlines = 16;

Contour random_polyline(std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> x(0.0, kWidth);
  std::uniform_real_distribution<double> y(0.0, kHeight);
  Contour points(count);
  for (Point& p : points) p = {x(rng), y(rng)};
  return points;
}

/// Edges meeting each row (an edge from y0 to y1 meets the rows it has positive height in), summed.
double edge_rows(const Contour& contour) {
  double sum = 0.0;
  for (std::size_t i = 0; i < contour.size(); ++i) {
    const double y0 = std::min(contour[i].y, contour[(i + 1) % contour.size()].y);
    const double y1 = std::max(contour[i].y, contour[(i + 1) % contour.size()].y);
    for (int row = 0; row < kHeight; ++row) sum += (y0 < row + 1.0 && y1 > row) ? 1.0 : 0.0;
  }
  return sum;
}

struct Render {
  CoverageMask mask{kWidth, kHeight};
  RasterizerStats stats;
  int violations = 0;
};

Render render_sampled(const Contour& contour, FillRule rule) {
  Render out;
  Rasterizer rasterizer(IntRect{0, 0, kWidth, kHeight});
  rasterizer.set_sweep_crossing_budget(0.0);  // crossing fills take the row scan, which this test is about
  add_shape(rasterizer, {contour});
  rasterizer.set_crossing_budget(0.0);
  MaskSink sink(out.mask);
  rasterizer.rasterize(rule, Antialias::kExact, sink);
  out.stats = rasterizer.stats();
  out.violations = sink.violations;
  return out;
}

/// The sampling of the essay, plainly: at each sub-scanline's height the crossings of the edges that
/// meet it (top-inclusive), sorted, walked for the winding number; each filled interval adds its length
/// inside each pixel column, weighted 1/16.
CoverageMask plain_sub_scanlines(const Contour& contour, FillRule rule) {
  CoverageMask mask(kWidth, kHeight);
  struct Crossing {
    double x;
    int dir;
  };
  std::vector<Crossing> crossings;
  for (int row = 0; row < kHeight; ++row) {
    std::vector<double> area(kWidth, 0.0);
    for (int k = 0; k < kSubScanlines; ++k) {
      const double yc = row + (k + 0.5) / kSubScanlines;
      crossings.clear();
      for (std::size_t i = 0; i < contour.size(); ++i) {
        const Point a = contour[i];
        const Point b = contour[(i + 1) % contour.size()];
        const Point top = a.y < b.y ? a : b;
        const Point bottom = a.y < b.y ? b : a;
        if (!(top.y <= yc && yc < bottom.y)) continue;
        const double x = top.x + (bottom.x - top.x) * (yc - top.y) / (bottom.y - top.y);
        crossings.push_back({x, b.y > a.y ? 1 : -1});
      }
      std::sort(crossings.begin(), crossings.end(),
                [](const Crossing& p, const Crossing& q) { return p.x < q.x; });
      int winding = 0;
      for (std::size_t c = 0; c + 1 < crossings.size(); ++c) {
        winding += crossings[c].dir;
        const bool filled = rule == FillRule::kNonZero ? winding != 0 : (winding & 1) != 0;
        if (!filled) continue;
        const double x0 = std::clamp(crossings[c].x, 0.0, static_cast<double>(kWidth));
        const double x1 = std::clamp(crossings[c + 1].x, 0.0, static_cast<double>(kWidth));
        for (int column = static_cast<int>(x0); column < kWidth && column < x1; ++column) {
          const double covered = std::min(x1, column + 1.0) - std::max(x0, static_cast<double>(column));
          if (covered > 0.0) area[static_cast<std::size_t>(column)] += covered / kSubScanlines;
        }
      }
    }
    for (int column = 0; column < kWidth; ++column) {
      const double a = std::clamp(area[static_cast<std::size_t>(column)], 0.0, 1.0);
      mask.at(column, row) = static_cast<std::uint8_t>(std::lround(a * 255.0));
    }
  }
  return mask;
}

// Pieces visited per edge and sub-scanline at 6000 and 12000 random segments, every row sampled: at most
// `bound`, and growing by at most 5 % when the segments double (linear time, with room for the spread).
void check_linear_visits(FillRule rule, double bound) {
  double previous_per_edge = 0.0;
  for (const std::size_t segments : {std::size_t{6000}, std::size_t{12000}}) {
    const Contour contour = random_polyline(segments, 20261126);
    const Render r = render_sampled(contour, rule);
    const double per_edge =
        static_cast<double>(r.stats.pieces_visited) / (edge_rows(contour) * kSubScanlines);
    INFO(segments << " segments: " << r.stats.pieces_visited << " pieces visited, " << per_edge
                  << " per edge and sub-scanline, " << r.stats.sampled_rows << " rows sampled");
    REQUIRE(r.stats.sampled_rows == kHeight);
    CHECK(per_edge <= bound);
    if (previous_per_edge > 0.0) CHECK(per_edge <= 1.05 * previous_per_edge);
    previous_per_edge = per_edge;
  }
}

}  // namespace

TEST_CASE("a sampled row of mutually crossing edges costs time linear in its edges", "[oracle][crossings]") {
  constexpr double kVisitsPerEdgeAndSubScanline = 6.0;  // under 4 by the count of the header, + spread
  check_linear_visits(FillRule::kNonZero, kVisitsPerEdgeAndSubScanline);
}

TEST_CASE("a sampled row of mutually crossing edges is its sub-scanlines' coverage", "[oracle][crossings]") {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    for (const std::size_t segments : {std::size_t{40}, std::size_t{700}, std::size_t{6000}}) {
      const Contour contour = random_polyline(segments, 7 + segments);
      const Render r = render_sampled(contour, rule);
      const CoverageMask plain = plain_sub_scanlines(contour, rule);
      INFO((rule == FillRule::kNonZero ? "nonzero, " : "even-odd, ") << segments << " segments");
      CHECK(r.violations == 0);
      CHECK(r.stats.sampled_rows + r.stats.sampled_bands > 0);
      CHECK(max_abs_diff(r.mask, plain) <= 1);
    }
  }
}

TEST_CASE("a sampled row under even-odd sorts its edges bucket by bucket", "[oracle][crossings]") {
  // Under even-odd every bucket holding an edge may hold a boundary, so every edge is gathered and
  // sorted at every sub-scanline: per edge and sub-scanline the x pass (1), the gathering pass and the
  // placing into its bucket (2), the walk over the buckets (1/4), the sort inside its bucket and the
  // walk (about 1½: a bucket holds about four edges), and the row's share of the groups and the ordering
  // (under 1/2): about 5 (4.96 measured at 6000 and 12000 segments). The bound is 7, with room for the
  // uneven spread of the edges over the buckets. Sorting all the gathered edges at once from the row's
  // order (the code before) visited 14.1 and 15.0: every edge moving past the others since the row's
  // top, beyond adaptive_sort's cap at 12000 segments (+6.6 % for 2× the segments).
  constexpr double kVisitsPerEdgeAndSubScanline = 7.0;
  check_linear_visits(FillRule::kEvenOdd, kVisitsPerEdgeAndSubScanline);
}
