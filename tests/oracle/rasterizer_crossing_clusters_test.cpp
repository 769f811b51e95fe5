// Crossing clusters of the chain path (raster/scan/rasterizer.cpp, cover_row_by_chains): a band of a row
// whose chains cross is cut into clusters that no chain outside them meets, and only a cluster whose own
// chains cross is cut at its joints and swept, starting from the winding number its left neighbours fix.
// Held to the plain reference scan (rasterize_reference) on scenes that reach it: self-crossing and
// mutually crossing finely flattened curves (figure eights, braids, overlapping rings, star polygons) inside
// a larger filled shape, so that the gaps between the clusters have a non-zero winding number (the row's
// independent groups, which need a zero one, do not separate them); stacked and opposite windings,
// coincident contours, both fill rules; and the outlines of wide, dashed and self-crossing strokes. And
// held to the work it saves: a row of separate crossing clusters costs per cluster, not clusters ×
// joints of the whole band.
//
// Metric: the same exact area summed in another order, so an area within ~1e-12 of a rounding midpoint
// may round either way: at most 1 step of 255 per pixel (as in rasterizer_row_groups_test.cpp).
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "coverage_mask.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/stroke.h"
#include "outline_shape.h"
#include "polygon_scenes.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

/// Under both rules: `shape` takes the row scan (it crosses itself), exactly (no sampled row or band) and
/// within 1 step of the reference.
void check_exact(const Shape& shape, int width, int height) {
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    const ReferenceComparison run = compare_with_reference(shape, width, height, rule);
    INFO((rule == FillRule::kNonZero ? "nonzero" : "even-odd") << ", crossings " << run.stats.crossings);
    CHECK(run.stats.planar_fills == 0);
    CHECK(run.max_diff <= 1);
    CHECK(run.violations == 0);
    CHECK(run.stats.sampled_rows == 0);
    CHECK(run.stats.sampled_bands == 0);
  }
}

/// A figure eight (Gerono's lemniscate) of `n` vertices: a finely flattened curve crossing itself once at
/// its centre, so its chains cross there.
Contour figure_eight(Point centre, double rx, double ry, int n, double rotation = 0.0) {
  Contour c;
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    const double x = rx * std::cos(t);
    const double y = ry * std::sin(t) * std::cos(t);
    c.push_back({centre.x + x * std::cos(rotation) - y * std::sin(rotation),
                 centre.y + x * std::sin(rotation) + y * std::cos(rotation)});
  }
  return c;
}

/// A braid: a closed contour down x = cx + a·sin(1.5 y + 0.3) and back up x = cx − a·sin(1.5 y + 0.3), from
/// y0 to y1, `n` vertices a side: its two sides cross each other every 2.1 rows.
Contour braid(double cx, double y0, double y1, double a, int n) {
  Contour c;
  for (int i = 0; i <= n; ++i) {
    const double y = y0 + (y1 - y0) * i / n;
    c.push_back({cx + a * std::sin(1.5 * y + 0.3), y});
  }
  for (int i = n; i >= 0; --i) {
    const double y = y0 + (y1 - y0) * i / n;
    c.push_back({cx - a * std::sin(1.5 * y + 0.3), y});
  }
  return c;
}

/// A rectangle under everything else, so that the winding number between the clusters is not zero.
Contour backdrop(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

}  // namespace

TEST_CASE("crossing clusters on a filled backdrop match the reference scan", "[oracle][clusters]") {
  constexpr int kWidth = 200;
  constexpr int kHeight = 40;
  // A row of figure eights, rings overlapping in pairs (same and opposite orientation), a ring drawn
  // twice (stacked winding 2, and coincident edges) and small star polygons, all over one rectangle.
  Shape shape{backdrop(1.5, 2.5, 198.5, 37.5)};
  shape.push_back(figure_eight({20.0, 20.0}, 14.0, 14.0, 160));
  shape.push_back(reversed(figure_eight({52.0, 20.5}, 13.0, 12.0, 150, 0.3)));
  shape.push_back(regular_polygon({80.0, 20.0}, 9.0, 12.0, 120));
  shape.push_back(regular_polygon({88.3, 18.7}, 8.0, 11.0, 110));
  shape.push_back(regular_polygon({112.0, 20.0}, 9.5, 12.0, 130));
  shape.push_back(reversed(regular_polygon({119.6, 21.2}, 8.5, 10.0, 100)));
  shape.push_back(regular_polygon({145.0, 20.0}, 10.0, 13.0, 90));
  shape.push_back(regular_polygon({145.0, 20.0}, 10.0, 13.0, 90));
  shape.push_back(star_polygon({172.0, 14.0}, 8.0, 7, 3, 0.2));
  shape.push_back(star_polygon({186.0, 26.0}, 9.0, 9, 4, 0.1));
  shape.push_back(regular_polygon({180.0, 20.0}, 6.0, 15.0, 80, 0.4));
  shape.push_back(braid(66.0, 3.0, 37.0, 4.0, 150));
  shape.push_back(reversed(braid(131.0, 5.0, 35.0, 3.0, 120)));
  check_exact(shape, kWidth, kHeight);
  // The same without the backdrop (the gaps' winding is zero there) and with the backdrop reversed
  // (winding -1 between the clusters: even-odd and nonzero differ inside the rings).
  Shape bare(shape.begin() + 1, shape.end());
  check_exact(bare, kWidth, kHeight);
  shape[0] = reversed(shape[0]);
  check_exact(shape, kWidth, kHeight);
}

TEST_CASE("random crossing rings on a backdrop match the reference scan", "[oracle][clusters]") {
  constexpr int kWidth = 160;
  constexpr int kHeight = 48;
  std::mt19937 rng(1818);
  std::uniform_real_distribution<double> x(10.0, 150.0), y(10.0, 38.0), r(3.0, 12.0), coin(0.0, 1.0);
  for (int scene = 0; scene < 6; ++scene) {
    Shape shape;
    if (scene % 2 == 0) shape.push_back(backdrop(0.5, 4.25, 159.5, 43.75));
    for (int i = 0; i < 12; ++i) {
      Contour c = coin(rng) < 0.3
                      ? figure_eight({x(rng), y(rng)}, r(rng) + 2.0, r(rng), 60 + 10 * i, coin(rng))
                      : regular_polygon({x(rng), y(rng)}, r(rng), r(rng), 40 + 10 * i, coin(rng));
      if (coin(rng) < 0.4) c = reversed(c);
      shape.push_back(c);
    }
    INFO("scene " << scene);
    check_exact(shape, kWidth, kHeight);
  }
}

TEST_CASE("stroke outlines that cross themselves match the reference scan", "[oracle][clusters]") {
  constexpr int kSize = 96;
  std::mt19937 rng(2020);
  std::uniform_real_distribution<double> in(8.0, 88.0);
  for (int scene = 0; scene < 6; ++scene) {
    PathBuilder b;
    b.move_to({in(rng), in(rng)});
    for (int i = 0; i < 5; ++i) {
      if (scene % 2 == 0) {
        b.cubic_to({in(rng), in(rng)}, {in(rng), in(rng)}, {in(rng), in(rng)});
      } else {
        b.line_to({in(rng), in(rng)});
      }
    }
    StrokeStyle style;
    style.width = scene < 2 ? 14.0 : (scene < 4 ? 3.0 : 8.0);
    style.join = scene == 3 ? LineJoin::kMiter : LineJoin::kRound;
    style.cap = scene == 5 ? LineCap::kSquare : LineCap::kRound;
    if (scene >= 4) style.dash_array = {9.0, 4.0};
    INFO("scene " << scene << ", width " << style.width);
    check_exact(outline_shape(*b.build(), style), kSize, kSize);
  }
}

TEST_CASE("separate crossing clusters cost per cluster", "[oracle][clusters]") {
  // Braids side by side over one rectangle: every band holds the rectangle's sides and all the braids'
  // chains, and each braid's two sides cross each other every 2 rows; their joints lie at different
  // heights (each braid has its own vertex count), so a band cut at all of them has braids × joints
  // sub-bands. Cutting such a band at the joints
  // of all its chains costs (braids × joints per braid)² piece visits per row; cluster by cluster,
  // braids × joints². So 4× the braids may cost about 4× the visits (measured: see the WARN; before the
  // clusters, 8 → 32 braids cost 13.5× the visits; now 4.5×), not 16×; the bound 6× leaves room for the rows'
  // fixed costs, which do not grow with the braids.
  const auto visits = [](int braids) {
    const double width = 16.0 * braids + 8.0;
    Shape shape{backdrop(2.0, 1.0, width - 2.0, 31.0)};
    for (int i = 0; i < braids; ++i) shape.push_back(braid(8.0 + 16.0 * i, 2.0, 30.0, 5.0, 280 + 3 * i));
    const int pixels = static_cast<int>(std::ceil(width));
    Rasterizer rasterizer(IntRect{0, 0, pixels, 32});
    rasterizer.set_sweep_crossing_budget(0.0);  // crossing fills take the row scan, which this test is about
    add_shape(rasterizer, shape);
    CoverageMask mask(pixels, 32);
    MaskSink sink(mask);
    rasterizer.rasterize(FillRule::kEvenOdd, Antialias::kExact, sink);
    CHECK(rasterizer.stats().sampled_bands == 0);
    CHECK(rasterizer.stats().crossings >= static_cast<std::uint64_t>(12 * braids));
    return static_cast<double>(rasterizer.stats().pieces_visited);
  };
  const double few = visits(8);
  const double many = visits(32);
  WARN("8 braids: " << few << " pieces visited, 32 braids: " << many);
  CHECK(many <= 6.0 * few);
}
