// Large fills cut into bands (Canvas::set_threads, Rasterizer::split_rows): the pixels do not depend on
// the number of threads, and a fill cut into bands covers each pixel as the uncut fill does.
//
// Metric: images with 1, 2 and 3 threads compared byte for byte (the cut depends on the fill only, so
// each band does the same arithmetic whatever thread runs it). Against the uncut rasterizer, coverage
// within 1 step of 255: cutting an edge at a row line recomputes its slope from the cut point, which can
// move an exact area sitting on a rounding midpoint by one step, never more.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"

using namespace curvescan;

namespace {

/// A star of `points` spikes between radii r0 and r1: many edges crossing every band line.
Path star(Point c, double r0, double r1, int points) {
  PathBuilder builder;
  for (int i = 0; i < 2 * points; ++i) {
    const double a = std::numbers::pi * i / points;
    const double r = i % 2 == 0 ? r1 : r0;
    const Point p{c.x + r * std::cos(a), c.y + r * std::sin(a)};
    if (i == 0) builder.move_to(p); else builder.line_to(p);
  }
  return *builder.close().build();
}

Image render(int threads) {
  Canvas canvas{Image(700, 1300)};
  canvas.set_threads(threads);
  const Path shape = star({350.3, 650.7}, 120.0, 640.0, 97);
  REQUIRE(canvas.fill(shape, Paint::solid(Color::from_rgba8(30, 120, 200, 180)), FillRule::kNonZero).is_ok());
  const GradientStop stops[] = {{0.0, {1.0, 0.2, 0.1, 0.9}}, {1.0, {0.1, 0.8, 0.3, 0.6}}};
  const Paint gradient = linear_gradient_paint({{0.0, 0.0}, {700.0, 1300.0}}, stops, SpreadMethod::kPad);
  REQUIRE(canvas.fill(star({300.1, 700.2}, 40.0, 600.0, 31), gradient, FillRule::kEvenOdd).is_ok());
  // Through a clip mask and inside a group, the other paint paths.
  REQUIRE(canvas.push_layer().is_ok());
  REQUIRE(canvas.push_clip(star({400.0, 600.0}, 300.0, 560.0, 7), FillRule::kNonZero).is_ok());
  REQUIRE(canvas
              .fill(star({380.0, 640.0}, 200.0, 630.0, 53), Paint::solid(Color::from_rgba8(200, 40, 90, 255)),
                    FillRule::kNonZero)
              .is_ok());
  REQUIRE(canvas.pop_clip().is_ok());
  REQUIRE(canvas.pop_layer(0.7).is_ok());
  return std::move(canvas).take_image();
}

/// Coverage of one fill, rasterized whole or cut at `cuts` (ascending rows), as an 8-bit mask.
std::vector<std::uint8_t> coverage(const std::vector<Point>& polygon, IntRect box, const std::vector<int>& cuts) {
  std::vector<Rasterizer> parts(1);
  parts[0].reset(box);
  parts[0].add_polyline(polygon);
  for (auto it = cuts.rbegin(); it != cuts.rend(); ++it) {
    Rasterizer lower;
    parts[0].split_rows(*it, lower);
    parts.push_back(std::move(lower));
  }
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(box.x1 - box.x0) * (box.y1 - box.y0), 0);
  struct Sink : SpanSink {
    std::vector<std::uint8_t>& mask;
    IntRect box;
    Sink(std::vector<std::uint8_t>& m, IntRect b) : mask(m), box(b) {}
    void blend(std::span<const Span> spans) override {
      for (const Span& s : spans) {
        for (int x = s.x; x < s.x + s.len; ++x) {
          mask[static_cast<std::size_t>(s.y - box.y0) * (box.x1 - box.x0) + (x - box.x0)] = s.coverage;
        }
      }
    }
  } sink(mask, box);
  for (Rasterizer& part : parts) part.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
  return mask;
}

}  // namespace

TEST_CASE("a large fill gives the same pixels with one, two or three threads", "[paint][bands]") {
  const Image one = render(1);
  CHECK(render(2) == one);
  CHECK(render(3) == one);
}

TEST_CASE("a fill cut into bands covers every pixel as the whole fill does", "[paint][bands]") {
  std::vector<Point> polygon;
  for (int i = 0; i <= 2 * 41; ++i) {
    const double a = std::numbers::pi * i / 41;
    const double r = i % 2 == 0 ? 90.0 : 12.5;
    polygon.push_back({100.3 + r * std::cos(a), 100.6 + r * std::sin(a)});
  }
  const IntRect box{0, 0, 200, 200};
  const std::vector<std::uint8_t> whole = coverage(polygon, box, {});
  const std::vector<std::uint8_t> cut = coverage(polygon, box, {37, 100, 101, 150});
  int worst = 0;
  long covered = 0;
  for (std::size_t i = 0; i < whole.size(); ++i) {
    worst = std::max(worst, std::abs(int{whole[i]} - int{cut[i]}));
    covered += whole[i];
  }
  CHECK(worst <= 1);
  CHECK(covered > 255L * 3000);  // the star is drawn: more than 3000 pixels' worth of coverage (3531)
}

TEST_CASE("split_rows keeps each part's rows and its edges' rows", "[paint][bands]") {
  Rasterizer upper(IntRect{0, 0, 50, 100});
  upper.add_line({10.0, 5.5}, {20.0, 95.25});
  upper.add_line({30.0, 95.25}, {30.0, 5.5});
  Rasterizer lower;
  upper.split_rows(40, lower);
  CHECK(upper.clip() == IntRect{0, 0, 50, 40});
  CHECK(lower.clip() == IntRect{0, 40, 50, 100});
  CHECK(upper.edge_rows() == std::pair<int, int>{5, 40});
  CHECK(lower.edge_rows() == std::pair<int, int>{40, 96});
}
