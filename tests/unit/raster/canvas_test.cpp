// Canvas: creation limits, clear, clip, and fill() end to end (transform, flatten, rasterize, composite).
#include "curvescan/raster/canvas.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>

#include "curvescan/raster/limits.h"
#include "curvescan/raster/path_builder.h"

using namespace curvescan;

namespace {

Path rectangle(double x0, double y0, double x1, double y1) {
  return *PathBuilder()
              .move_to({x0, y0})
              .line_to({x1, y0})
              .line_to({x1, y1})
              .line_to({x0, y1})
              .close()
              .build();
}

Canvas make_canvas(int width, int height) {
  return std::move(Canvas::create(width, height)).value();
}

double total_alpha(const Image& image) {
  double sum = 0.0;
  for (const Rgba8& p : image.pixels()) sum += p.a;
  return sum / 255.0;
}

}  // namespace

TEST_CASE("Canvas::create checks sizes against limits.h", "[canvas]") {
  CHECK(Canvas::create(0, 10).error().kind == ErrorKind::kInvalidArgument);
  CHECK(Canvas::create(kMaxImageDimension + 1, 1).error().kind == ErrorKind::kLimitExceeded);
  CHECK(Canvas::create(30000, 30000).error().kind == ErrorKind::kLimitExceeded);  // 9e8 > kMaxImagePixels
  const Result<Canvas> canvas = Canvas::create(7, 3);
  REQUIRE(canvas.is_ok());
  CHECK(canvas->image() == Image(7, 3));
  CHECK(canvas->clip() == IntRect{0, 0, 7, 3});
}

TEST_CASE("Canvas::clear sets every pixel, clip or not", "[canvas]") {
  Canvas canvas = make_canvas(4, 4);
  canvas.set_clip({1, 1, 2, 2});
  canvas.clear(Paint::solid(Color::from_rgba8(255, 0, 0, 128)));
  for (const Rgba8& p : canvas.image().pixels()) CHECK(p == Rgba8{128, 0, 0, 128});
}

TEST_CASE("fill of a pixel-aligned rectangle composites exact full coverage", "[canvas]") {
  std::mt19937 rng(5150);
  std::uniform_int_distribution<int> byte(0, 255);
  Image background(12, 10);
  for (Rgba8& p : background.pixels()) {
    const int a = byte(rng);
    p = {static_cast<std::uint8_t>(byte(rng) * a / 255), static_cast<std::uint8_t>(byte(rng) * a / 255),
         static_cast<std::uint8_t>(byte(rng) * a / 255), static_cast<std::uint8_t>(a)};
  }
  // Opaque (fast path: a plain store) and translucent (per-pixel blend): both must equal the per-pixel
  // formula with coverage 255 inside and leave the outside untouched.
  for (const Paint& paint : {Paint::solid(Color::from_rgba8(20, 40, 60, 255)),
                             Paint::solid(Color::from_rgba8(200, 100, 50, 77))}) {
    Canvas canvas(background);
    REQUIRE(canvas.fill(rectangle(2, 3, 9, 8), paint, FillRule::kNonZero).is_ok());
    for (int y = 0; y < 10; ++y) {
      for (int x = 0; x < 12; ++x) {
        const bool inside = x >= 2 && x < 9 && y >= 3 && y < 8;
        const Rgba8 expected =
            inside ? composite_source_over(background.at(x, y), paint.color, 255) : background.at(x, y);
        CHECK(canvas.image().at(x, y) == expected);
      }
    }
  }
}

TEST_CASE("fill applies the transform and the clip", "[canvas]") {
  const Paint black = Paint::solid(Color::from_rgba8(0, 0, 0, 255));
  Canvas canvas = make_canvas(20, 20);
  canvas.set_clip({5, 0, 100, 20});  // clipped to the image on the right
  CHECK(canvas.clip() == IntRect{5, 0, 20, 20});
  // The unit square scaled by 10 and moved by (2, 4): pixels [2, 12) x [4, 14), clipped to x >= 5.
  REQUIRE(
      canvas
          .fill(rectangle(0, 0, 1, 1), black, FillRule::kNonZero, Affine::translate(2, 4) * Affine::scale(10))
          .is_ok());
  for (int y = 0; y < 20; ++y) {
    for (int x = 0; x < 20; ++x) {
      const bool inside = x >= 5 && x < 12 && y >= 4 && y < 14;
      CHECK(canvas.image().at(x, y).a == (inside ? 255 : 0));
    }
  }
}

TEST_CASE("fill of arcs and curves covers their area", "[canvas]") {
  // A circle of radius 20 from exact conics: the total coverage is its area, up to the flattening loss
  // (an inscribed polygon within tolerance t loses at most perimeter·t = 2πr·t) and coverage quantization
  // (at most 0.5/255 per boundary pixel, ~ 4·2r pixels).
  constexpr double kRadius = 20.0, kTolerance = 0.01;
  const Path circle =
      *PathBuilder().arc({32, 32}, kRadius, kRadius, 0, 0, 2 * std::numbers::pi).close().build();
  Canvas canvas = make_canvas(64, 64);
  FillOptions options;
  options.tolerance = kTolerance;
  REQUIRE(canvas
              .fill(circle, Paint::solid(Color::from_rgba8(0, 0, 0, 255)), FillRule::kNonZero,
                    Affine::identity(), options)
              .is_ok());
  const double area = std::numbers::pi * kRadius * kRadius;
  const double bound = 2 * std::numbers::pi * kRadius * kTolerance + 8 * kRadius * 0.5 / 255.0;
  CHECK(std::fabs(total_alpha(canvas.image()) - area) <= bound);
  CHECK(canvas.image().at(32, 32).a == 255);
  CHECK(canvas.image().at(2, 2).a == 0);

  // An open contour is closed implicitly: a quadratic "lens" from (0, 0) to (40, 0) bulging to y = 20
  // (control point (20, 40)) has area 2/3 · base · height = 2/3 · 40 · 20.
  const Path lens = *PathBuilder().move_to({4, 4}).quad_to({24, 44}, {44, 4}).build();
  Canvas second = make_canvas(64, 64);
  REQUIRE(second
              .fill(lens, Paint::solid(Color::from_rgba8(0, 0, 0, 255)), FillRule::kEvenOdd,
                    Affine::identity(), options)
              .is_ok());
  CHECK(total_alpha(second.image()) == Approx(2.0 / 3.0 * 40 * 20).margin(2 * 40 * kTolerance + 1.0));
}

TEST_CASE("fill refuses bad transforms and tolerances and draws nothing", "[canvas]") {
  Canvas canvas = make_canvas(8, 8);
  const Path square = rectangle(1, 1, 6, 6);
  const Paint black = Paint::solid(Color::from_rgba8(0, 0, 0, 255));
  CHECK_FALSE(canvas.fill(square, black, FillRule::kNonZero, Affine::scale(std::nan(""))).is_ok());
  CHECK_FALSE(canvas.fill(square, black, FillRule::kNonZero, Affine::scale(1e308)).is_ok());
  FillOptions zero_tolerance;
  zero_tolerance.tolerance = 0.0;
  CHECK_FALSE(canvas.fill(square, black, FillRule::kNonZero, Affine::identity(), zero_tolerance).is_ok());
  CHECK(canvas.image() == Image(8, 8));
  CHECK(canvas.fill(Path(), black, FillRule::kNonZero).is_ok());  // the empty path draws nothing
  CHECK(canvas.image() == Image(8, 8));
}
