// Fills cut into bands and drawn on a thread pool (Canvas::set_threads, Rasterizer::split_at_rows,
// band_queue.h): the pixels do not depend on the number of threads, and a fill cut into
// bands covers each pixel as the uncut fill does.
//
// Metric: images with 1, 2 and 3 threads compared byte for byte (the cut depends on the fill only, so
// each band does the same arithmetic whatever thread runs it). Against the uncut rasterizer, coverage
// within 1 step of 255: cutting an edge at a row line recomputes its slope from the cut point, which can
// move an exact area sitting on a rounding midpoint by one step, never more.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"
#include "curvescan/raster/stroke.h"

using namespace curvescan;

namespace {

/// A star of `points` spikes between radii r0 and r1: many edges crossing every band line.
Path star(Point c, double r0, double r1, int points) {
  PathBuilder builder;
  for (int i = 0; i < 2 * points; ++i) {
    const double a = std::numbers::pi * i / points;
    const double r = i % 2 == 0 ? r1 : r0;
    const Point p{c.x + r * std::cos(a), c.y + r * std::sin(a)};
    if (i == 0)
      builder.move_to(p);
    else
      builder.line_to(p);
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

/// Coverage of one fill, rasterized whole or cut at `cuts` (ascending rows) by split_at_rows, as an 8-bit
/// mask.
std::vector<std::uint8_t> coverage(const std::vector<Point>& polygon, IntRect box,
                                   const std::vector<int>& cuts) {
  std::vector<Rasterizer> parts(1);
  parts[0].reset(box);
  parts[0].add_polyline(polygon);
  if (!cuts.empty()) {
    parts.resize(cuts.size() + 1);
    parts[0].split_at_rows(cuts, std::span<Rasterizer>(parts).subspan(1));
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
  for (const std::vector<int>& cuts : {std::vector<int>{37, 100, 101, 150}, std::vector<int>{100}}) {
    INFO("cuts: " << cuts.size());
    const std::vector<std::uint8_t> cut = coverage(polygon, box, cuts);
    int worst = 0;
    long covered = 0;
    for (std::size_t i = 0; i < whole.size(); ++i) {
      worst = std::max(worst, std::abs(int{whole[i]} - int{cut[i]}));
      covered += whole[i];
    }
    CHECK(worst <= 1);
    CHECK(covered > 255L * 3000);  // the star is drawn: more than 3000 pixels' worth of coverage (3531)
  }
}

TEST_CASE("split_at_rows gives each band its rows and the pieces of the edges crossing it",
          "[paint][bands]") {
  Rasterizer upper(IntRect{0, 0, 50, 100});
  upper.add_line({10.0, 5.5}, {20.0, 95.25});  // crosses every cut
  upper.add_line({30.0, 95.25}, {30.0, 5.5});  // the same rows, upward
  upper.add_line({40.0, 60.0}, {45.0, 70.0});  // inside the third band only
  const int cuts[] = {40, 60, 61};
  std::vector<Rasterizer> lower(3);
  upper.split_at_rows(cuts, lower);
  CHECK(upper.clip() == IntRect{0, 0, 50, 40});
  CHECK(lower[0].clip() == IntRect{0, 40, 50, 60});
  CHECK(lower[1].clip() == IntRect{0, 60, 50, 61});
  CHECK(lower[2].clip() == IntRect{0, 61, 50, 100});
  CHECK(upper.edge_rows() == std::pair<int, int>{5, 40});
  CHECK(lower[0].edge_rows() == std::pair<int, int>{40, 60});
  CHECK(lower[1].edge_rows() == std::pair<int, int>{60, 61});
  CHECK(lower[2].edge_rows() == std::pair<int, int>{61, 96});
  // Two pieces above, two in each band below, and the short edge in rows 60..70 cut at 61.
  CHECK(upper.edge_count() == 2);
  CHECK(lower[0].edge_count() == 2);
  CHECK(lower[1].edge_count() == 3);
  CHECK(lower[2].edge_count() == 3);
}

namespace {

/// Many small translucent fills and strokes overlapping each other across band lines (each waits for
/// the ones before it on the same rows), gradients, a group and a clip in the middle, a read of the
/// image half-way: the work of the band queue. Seeded, so every call draws the same.
Image render_many(int threads, Image* half_way) {
  Canvas canvas{Image(600, 900)};
  canvas.set_threads(threads);
  std::mt19937 random(20261126);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const GradientStop stops[] = {{0.0, {1.0, 0.2, 0.1, 0.9}}, {1.0, {0.1, 0.8, 0.3, 0.6}}};
  const auto draw_some = [&](int count) {
    for (int i = 0; i < count; ++i) {
      const Point c{600.0 * unit(random), 900.0 * unit(random)};
      const double r1 = 10.0 + 200.0 * unit(random);
      const Path shape = star(c, 0.3 * r1, r1, 5 + i % 17);
      const auto channel = [&] { return static_cast<std::uint8_t>(255.0 * unit(random)); };
      const std::uint8_t rgba[4] = {channel(), channel(), channel(), channel()};  // braces: left to right
      Paint paint = Paint::solid(Color::from_rgba8(rgba[0], rgba[1], rgba[2], rgba[3]));
      if (i % 7 == 3) paint = linear_gradient_paint({c, {c.x + r1, c.y + r1}}, stops, SpreadMethod::kReflect);
      if (i % 5 == 1) {
        StrokeStyle style;
        style.width = 1.0 + 8.0 * unit(random);
        REQUIRE(canvas.stroke(shape, paint, style).is_ok());
      } else {
        REQUIRE(canvas.fill(shape, paint, i % 2 == 0 ? FillRule::kNonZero : FillRule::kEvenOdd).is_ok());
      }
    }
  };
  draw_some(120);
  if (half_way != nullptr) *half_way = canvas.image();
  REQUIRE(canvas.push_layer().is_ok());
  REQUIRE(canvas.push_clip(star({300.0, 450.0}, 150.0, 420.0, 9), FillRule::kNonZero).is_ok());
  draw_some(60);
  REQUIRE(canvas.pop_clip().is_ok());
  REQUIRE(canvas.pop_layer(0.6).is_ok());
  draw_some(120);
  Canvas moved = std::move(canvas);  // moving finishes the queued fills first
  return std::move(moved).take_image();
}

}  // namespace

TEST_CASE("many overlapping fills give the same pixels with one to four threads", "[paint][bands]") {
  Image one_half;
  const Image one = render_many(1, &one_half);
  for (const int threads : {2, 3, 4}) {
    INFO(threads << " threads");
    Image half;
    CHECK(render_many(threads, &half) == one);
    CHECK(half == one_half);  // image() waits for the fills queued before it
  }
  // The scene is drawn: not left transparent.
  long opaque = 0;
  for (const Rgba8 p : one.pixels()) opaque += p.a == 255 ? 1 : 0;
  CHECK(opaque > 10000);
}

TEST_CASE("fills drawn with threads composite as each whole fill blended in order", "[paint][bands]") {
  // Oracle: each star rasterized whole (no band cut) into a coverage mask and blended pixel by pixel
  // with composite_source_over in drawing order. Metric: largest channel difference. Tolerance 5: a
  // cut moves a coverage by at most one step (test above), which moves one blend's result by at most 2
  // (MUL_UN8 of a coverage one step off, plus its rounding); each later blend multiplies an earlier
  // difference by (255 - alpha 120)/255 < 0.53, so the differences of all fills sum to below 2 / 0.47.
  const IntRect box{0, 0, 300, 700};
  Canvas threaded{Image(box.x1, box.y1)};
  threaded.set_threads(2);
  Image oracle(box.x1, box.y1);
  for (int i = 0; i < 40; ++i) {
    std::vector<Point> polygon;
    const int points = 11 + i;
    for (int k = 0; k <= 2 * points; ++k) {
      const double a = std::numbers::pi * k / points;
      const double r = k % 2 == 0 ? 320.0 : 20.0;
      polygon.push_back({150.0 + 3.0 * i + r * std::cos(a), 350.0 - 5.0 * i + r * std::sin(a)});
    }
    const Paint paint = Paint::solid(Color::from_rgba8(static_cast<std::uint8_t>(6 * i), 90, 200, 120));
    PathBuilder builder;
    builder.move_to(polygon[0]);
    for (std::size_t k = 1; k < polygon.size(); ++k) builder.line_to(polygon[k]);
    REQUIRE(threaded.fill(*builder.close().build(), paint, FillRule::kNonZero).is_ok());
    const std::vector<std::uint8_t> mask = coverage(polygon, box, {});
    for (int y = 0; y < box.y1; ++y) {
      for (int x = 0; x < box.x1; ++x) {
        const std::uint8_t c = mask[static_cast<std::size_t>(y) * box.x1 + x];
        if (c != 0) oracle.at(x, y) = composite_source_over(oracle.at(x, y), paint.color, c);
      }
    }
  }
  int worst = 0;
  long equal = 0;
  const Image& drawn = threaded.image();
  for (std::size_t i = 0; i < oracle.pixels().size(); ++i) {
    const Rgba8 a = drawn.pixels()[i], b = oracle.pixels()[i];
    const int d =
        std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b), std::abs(a.a - b.a)});
    worst = std::max(worst, d);
    equal += d == 0 ? 1 : 0;
  }
  CHECK(worst <= 5);
  // Only pixels on an edge crossing a band line can differ at all: a small minority.
  CHECK(equal > static_cast<long>(oracle.pixels().size()) * 99 / 100);
}

TEST_CASE("split_at_rows at one row keeps each part's rows and its edges' rows", "[paint][bands]") {
  Rasterizer upper(IntRect{0, 0, 50, 100});
  upper.add_line({10.0, 5.5}, {20.0, 95.25});
  upper.add_line({30.0, 95.25}, {30.0, 5.5});
  const int cut[] = {40};
  std::vector<Rasterizer> lower(1);
  upper.split_at_rows(cut, lower);
  CHECK(upper.clip() == IntRect{0, 0, 50, 40});
  CHECK(lower[0].clip() == IntRect{0, 40, 50, 100});
  CHECK(upper.edge_rows() == std::pair<int, int>{5, 40});
  CHECK(lower[0].edge_rows() == std::pair<int, int>{40, 96});
}

TEST_CASE("a new image is transparent, also in memory a freed image used", "[paint][bands]") {
  // Image's pixels are not written at creation (ZeroedPixelAllocator): they must still read as zero,
  // for a large image (fresh pages) and for small ones that reuse freed heap memory.
  for (const int side : {2048, 64, 3}) {
    {
      Image used(side, side);
      for (Rgba8& p : used.pixels()) p = Rgba8{9, 8, 7, 200};
    }
    const Image fresh(side, side);
    const bool transparent = std::all_of(fresh.pixels().begin(), fresh.pixels().end(),
                                         [](const Rgba8& p) { return p == Rgba8{}; });
    CHECK(transparent);
  }
  // A copy copies the pixels.
  Image a(5, 4);
  a.at(3, 2) = Rgba8{1, 2, 3, 4};
  const Image b = a;
  CHECK(b.at(3, 2) == Rgba8{1, 2, 3, 4});
  CHECK(b == a);
}
