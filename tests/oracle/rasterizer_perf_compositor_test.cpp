// The solid compositor's span fast path (solid_span_compositor.h, blend_solid_span in composite.cpp: the
// source side once per span, four pixels at a time with SSE2) against the per-pixel reference blend.
//
// Canvas::fill composites through that fast path. The reference here renders the same edges with its own
// Rasterizer (same clip, same edges in the same order, so the same spans) and blends every pixel of every
// span with composite_source_over_reference (integer division, paint.h). Metric: bytes must be identical
// (maximum difference 0) — the fast path claims pixman's rounding exactly, so no tolerance is justified.
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"

using namespace curvescan;

namespace {

/// Blends every pixel of every span with the division reference.
class ReferenceBlendSink final : public SpanSink {
 public:
  ReferenceBlendSink(Image& image, Rgba8 color) : image_(image), color_(color) {}
  void blend(std::span<const Span> spans) override {
    for (const Span& s : spans) {
      for (int i = 0; i < s.len; ++i) {
        Rgba8& d = image_.at(s.x + i, s.y);
        d = composite_source_over_reference(d, color_, s.coverage);
      }
    }
  }

 private:
  Image& image_;
  Rgba8 color_;
};

/// A random valid premultiplied pixel (r, g, b <= a), alpha 0 and 255 included.
Rgba8 random_premultiplied(std::mt19937& rng) {
  std::uniform_int_distribution<int> byte(0, 255);
  const int a = byte(rng) % 4 == 0 ? (byte(rng) % 2) * 255 : byte(rng);  // extremes a quarter of the time
  std::uniform_int_distribution<int> channel(0, a);
  return {static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(channel(rng)),
          static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(a)};
}

Image random_image(std::mt19937& rng, int width, int height) {
  Image image(width, height);
  for (Rgba8& p : image.pixels()) p = random_premultiplied(rng);
  return image;
}

}  // namespace

TEST_CASE("solid span fast path equals per-pixel reference compositing on random shapes and backgrounds",
          "[oracle][perf][compositor]") {
  std::mt19937 rng(8128);
  std::uniform_real_distribution<double> coordinate(-8.0, 72.0);
  std::uniform_int_distribution<int> vertex_count(3, 12);
  constexpr int kWidth = 67;  // odd, so spans end at every offset modulo 4 (the SSE2 loop's tail)
  constexpr int kHeight = 41;
  for (int scene = 0; scene < 200; ++scene) {
    PathBuilder builder;
    std::vector<Point> polygon;
    const int n = vertex_count(rng);
    for (int i = 0; i < n; ++i) polygon.push_back({coordinate(rng), coordinate(rng) * 0.6});
    builder.move_to(polygon[0]);
    for (int i = 1; i < n; ++i) builder.line_to(polygon[static_cast<std::size_t>(i)]);
    builder.close();
    const Path path = *builder.build();
    const Rgba8 color = scene % 10 == 0 ? Rgba8{0, 0, 0, 0} : random_premultiplied(rng);
    const FillRule rule = scene % 2 == 0 ? FillRule::kNonZero : FillRule::kEvenOdd;
    const Image background = random_image(rng, kWidth, kHeight);

    Canvas canvas(background);
    REQUIRE(canvas.fill(path, Paint{color, nullptr}, rule).is_ok());

    Image expected = background;
    Rasterizer rasterizer(IntRect{0, 0, kWidth, kHeight});
    for (int i = 0; i < n; ++i)
      rasterizer.add_line(polygon[static_cast<std::size_t>(i)], polygon[static_cast<std::size_t>((i + 1) % n)]);
    ReferenceBlendSink sink(expected, color);
    rasterizer.rasterize(rule, Antialias::kExact, sink);

    INFO("scene " << scene << " colour " << int{color.r} << "," << int{color.g} << "," << int{color.b} << ","
                  << int{color.a});
    REQUIRE(canvas.image() == expected);
  }
}

TEST_CASE("solid span fast path: every coverage over long spans on every destination alpha",
          "[oracle][perf][compositor]") {
  // A rectangle covering whole rows gives long spans of coverage 255 (the SSE2 loop's body); a ramp of
  // fractional left edges gives every partial coverage. Background: every alpha with random channels.
  std::mt19937 rng(65537);
  constexpr int kWidth = 131;
  constexpr int kHeight = 256;
  for (int trial = 0; trial < 8; ++trial) {
    const Rgba8 color = random_premultiplied(rng);
    Image background = random_image(rng, kWidth, kHeight);
    PathBuilder builder;
    // Row y starts at x = 1 + y/256: its first pixel has coverage 1 - y/256, which walks every 8-bit step.
    builder.move_to({1.0, 0.0}).line_to({2.0, static_cast<double>(kHeight)});
    builder.line_to({static_cast<double>(kWidth) - 0.5, static_cast<double>(kHeight)});
    builder.line_to({static_cast<double>(kWidth) - 0.5, 0.0}).close();
    const Path path = *builder.build();
    Canvas canvas(background);
    REQUIRE(canvas.fill(path, Paint{color, nullptr}, FillRule::kNonZero).is_ok());

    Image expected = background;
    Rasterizer rasterizer(IntRect{0, 0, kWidth, kHeight});
    rasterizer.add_line({1.0, 0.0}, {2.0, kHeight});
    rasterizer.add_line({2.0, kHeight}, {kWidth - 0.5, kHeight});
    rasterizer.add_line({kWidth - 0.5, kHeight}, {kWidth - 0.5, 0.0});
    rasterizer.add_line({kWidth - 0.5, 0.0}, {1.0, 0.0});
    ReferenceBlendSink sink(expected, color);
    rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
    INFO("trial " << trial);
    REQUIRE(canvas.image() == expected);
  }
}
