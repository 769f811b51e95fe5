// The compositing fast paths against the plain per-pixel blend they replace: pixel_fill.h (clear, opaque
// spans), solid_span_compositor.h (a run of one colour, SSE2), color_span_blend.h (a run of colours
// through one coverage, SSE2), the gradient span compositor
// (parameters two pixels at a time, the pad colour table, the constant-row case) against
// gradient_span_reference.h, and Canvas::fill end to end with and without a clip mask.
//
// Metric: bytes must be identical (maximum difference 0) everywhere. Every fast path claims the reference
// arithmetic exactly — pixman's rounding for the blend, the walker's floats for the colour table (which
// holds one entry per 16.16 position, so it quantizes nothing) — so no tolerance is justified.
#include <array>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <random>
#include <span>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/limits.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"
#include "paint/color_span_blend.h"
#include "paint/gradient_color_table.h"
#include "paint/gradient_parameter.h"
#include "paint/gradient_span_compositor.h"
#include "paint/gradient_span_reference.h"
#include "paint/gradient_table_cache.h"
#include "paint/gradient_walker.h"
#include "paint/masked_span_sink.h"
#include "paint/pixel_fill.h"
#include "paint/solid_span_compositor.h"

using namespace curvescan;

namespace {

std::uint8_t random_byte(std::mt19937& rng) {
  return static_cast<std::uint8_t>(std::uniform_int_distribution<int>(0, 255)(rng));
}

/// A random valid premultiplied pixel (r, g, b <= a); opaque or transparent a quarter of the time each.
Rgba8 random_premultiplied(std::mt19937& rng) {
  const int pick = std::uniform_int_distribution<int>(0, 3)(rng);
  const int a = pick == 0 ? 0 : (pick == 1 ? 255 : random_byte(rng));
  std::uniform_int_distribution<int> channel(0, a);
  return {static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(channel(rng)),
          static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(a)};
}

Image random_image(std::mt19937& rng, int width, int height) {
  Image image(width, height);
  for (Rgba8& p : image.pixels()) p = random_premultiplied(rng);
  return image;
}

/// A mask of rectangular blocks of 0, 255 and random values, so that MaskedSpanSink cuts spans into runs
/// of full, partial and no coverage.
ClipMask blocky_mask(std::mt19937& rng, int width, int height) {
  std::vector<std::uint8_t> values(static_cast<std::size_t>(width) * height);
  std::vector<std::uint8_t> block_values(64);
  for (std::uint8_t& v : block_values) {
    const int pick = std::uniform_int_distribution<int>(0, 2)(rng);
    v = pick == 0 ? 0 : (pick == 1 ? 255 : random_byte(rng));
  }
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      values[static_cast<std::size_t>(y) * width + x] =
          block_values[static_cast<std::size_t>((y / 9) * 8 + x / 11) % 64];
    }
  }
  return ClipMask::from_values(width, height, std::move(values));
}

/// The plain path: every pixel of every span blended alone, with the coverage times the mask (MUL_UN8,
/// masked_span_sink.h) and the division reference of paint.h.
class ReferenceSolidSink final : public SpanSink {
 public:
  ReferenceSolidSink(Image& image, Rgba8 color, const ClipMask* mask)
      : image_(image), color_(color), mask_(mask) {}
  void blend(std::span<const Span> spans) override {
    for (const Span& s : spans) {
      for (int i = 0; i < s.len; ++i) {
        std::uint8_t coverage = s.coverage;
        if (mask_ != nullptr) coverage = multiply_coverage(coverage, mask_->row(s.y)[s.x + i]);
        Rgba8& d = image_.at(s.x + i, s.y);
        d = composite_source_over_reference(d, color_, coverage);
      }
    }
  }

 private:
  Image& image_;
  Rgba8 color_;
  const ClipMask* mask_;
};

struct Polygon {
  std::vector<Point> points;
  [[nodiscard]] Path path() const {
    PathBuilder builder;
    builder.move_to(points[0]);
    for (std::size_t i = 1; i < points.size(); ++i) builder.line_to(points[i]);
    builder.close();
    return *builder.build();
  }
  void add_to(Rasterizer& rasterizer) const {
    for (std::size_t i = 0; i < points.size(); ++i)
      rasterizer.add_line(points[i], points[(i + 1) % points.size()]);
  }
};

/// Shapes with long full-coverage runs and every kind of edge: a pixel-aligned rectangle (coverage 255
/// only), a rectangle with fractional edges, random polygons (partial coverage, crossings).
std::vector<Polygon> test_polygons(std::mt19937& rng, int width, int height) {
  const double w = width, h = height;
  std::vector<Polygon> list{
      {{{0, 0}, {w, 0}, {w, h}, {0, h}}},
      {{{2, 3}, {w - 1, 3}, {w - 1, h - 2}, {2, h - 2}}},
      {{{1.3, 0.6}, {w - 2.7, 2.2}, {w - 0.4, h - 1.1}, {3.1, h - 3.5}}},
  };
  std::uniform_real_distribution<double> x(-5.0, w + 5.0), y(-5.0, h + 5.0);
  for (int k = 0; k < 6; ++k) {
    Polygon p;
    const int n = std::uniform_int_distribution<int>(3, 9)(rng);
    for (int i = 0; i < n; ++i) p.points.push_back({x(rng), y(rng)});
    list.push_back(p);
  }
  return list;
}

std::vector<GradientStop> random_stops(std::mt19937& rng, bool hard_stop) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<GradientStop> stops;
  const int n = std::uniform_int_distribution<int>(2, 5)(rng);
  double offset = 0.0;
  for (int i = 0; i < n; ++i) {
    offset = std::min(1.0, offset + unit(rng) * 0.5);
    const double alpha = i % 3 == 0 ? 1.0 : unit(rng);
    stops.push_back({offset, {unit(rng), unit(rng), unit(rng), alpha}});
    if (hard_stop && i == 0) stops.push_back({offset, {unit(rng), unit(rng), unit(rng), 1.0}});
  }
  return stops;
}

/// Gradient paints of every shape, spread and kind of mapping, including a vertical linear gradient (t
/// constant along rows) and radial ones with a focal radius and with A = 0.
std::vector<Paint> test_gradients(std::mt19937& rng, int width, int height) {
  std::vector<Paint> paints;
  const double w = width, h = height;
  for (const SpreadMethod spread : {SpreadMethod::kPad, SpreadMethod::kRepeat, SpreadMethod::kReflect}) {
    paints.push_back(
        linear_gradient_paint({{3.5, 2.0}, {w - 4.0, h * 0.7}}, random_stops(rng, false), spread));
    paints.push_back(linear_gradient_paint({{0.0, 10.0}, {0.0, h - 10.0}}, random_stops(rng, true), spread));
    paints.push_back(linear_gradient_paint(
        {{0, 0}, {1, 0.3}}, random_stops(rng, true), spread,
        Affine::translate(w / 2, h / 3) * Affine::rotate(0.7) * Affine::scale(w / 4, h / 5)));
    paints.push_back(radial_gradient_paint({{w / 2, h / 2}, w / 3, {w / 2 - 7, h / 2 + 4}, 0.0},
                                           random_stops(rng, false), spread));
    paints.push_back(radial_gradient_paint({{0.5, 0.5}, 0.3, {0.4, 0.55}, 0.05}, random_stops(rng, true),
                                           spread, Affine::scale(w, h) * Affine::skew_x(0.2)));
    // Focal circle touching the end circle from inside: A = |c − f|² − (r − fr)² = 0.
    paints.push_back(radial_gradient_paint({{w / 2, h / 2}, 30.0, {w / 2 + 10.0, h / 2}, 20.0},
                                           random_stops(rng, false), spread));
  }
  return paints;
}

}  // namespace

TEST_CASE("fill_pixels writes exactly the run, for any colour, length and alignment", "[paint][fast path]") {
  const std::vector<Rgba8> colors{
      {0, 0, 0, 0}, {255, 255, 255, 255}, {10, 20, 30, 40}, {1, 2, 3, 255}, {7, 7, 7, 7}};
  // Every SSE2 tail up to 70 pixels, and runs around and past the string-store threshold.
  std::vector<std::size_t> counts;
  for (std::size_t count = 0; count < 70; ++count) counts.push_back(count);
  for (const std::size_t count : {detail::kStringStorePixels - 1, detail::kStringStorePixels,
                                  detail::kStringStorePixels + 1, detail::kStringStorePixels + 37,
                                  std::size_t{4099}}) {
    counts.push_back(count);
  }
  for (const Rgba8 color : colors) {
    for (std::size_t offset = 0; offset < 4; ++offset) {
      for (const std::size_t count : counts) {
        const Rgba8 guard{9, 8, 7, 6};
        std::vector<Rgba8> pixels(count + 8, guard);
        detail::fill_pixels(pixels.data() + offset, count, color);
        for (std::size_t i = 0; i < pixels.size(); ++i) {
          const bool inside = i >= offset && i < offset + count;
          INFO("offset " << offset << " count " << count << " index " << i);
          REQUIRE(pixels[i] == (inside ? color : guard));
        }
      }
    }
  }
}

TEST_CASE("Canvas::clear sets every pixel to the colour, transparent and opaque", "[paint][fast path]") {
  for (const Rgba8 color : {Rgba8{0, 0, 0, 0}, Rgba8{255, 255, 255, 255}, Rgba8{12, 34, 56, 200}}) {
    Canvas canvas{Image(37, 5)};
    canvas.clear(Paint{{9, 9, 9, 9}, nullptr});
    canvas.clear(Paint{color, nullptr});
    for (const Rgba8 p : canvas.image().pixels()) REQUIRE(p == color);
  }
}

TEST_CASE("blend_color_span equals composite_source_over pixel by pixel", "[paint][fast path]") {
  std::mt19937 rng(2718);
  const std::vector<int> coverages{0, 1, 127, 128, 254, 255};
  for (int trial = 0; trial < 3000; ++trial) {
    const int len = std::uniform_int_distribution<int>(0, 37)(rng);
    std::vector<Rgba8> colors(static_cast<std::size_t>(len));
    // Runs of four opaque or four transparent sources (the SSE2 loop's shortcuts), at any alignment.
    const int kind = trial % 4;
    for (Rgba8& c : colors) {
      c = kind == 0 ? Rgba8{random_byte(rng), random_byte(rng), random_byte(rng), 255}
                    : (kind == 1 ? Rgba8{} : random_premultiplied(rng));
    }
    // Not premultiplied (r > a) now and then: the saturating add must agree too.
    if (trial % 7 == 0 && len > 0) colors[0] = {200, 250, 90, 60};
    const std::uint8_t coverage =
        trial % 3 == 0 ? random_byte(rng) : static_cast<std::uint8_t>(coverages[trial % 6]);
    std::vector<Rgba8> row(static_cast<std::size_t>(len) + 3);
    for (Rgba8& p : row) p = random_premultiplied(rng);
    std::vector<Rgba8> expected = row;
    const std::size_t offset = static_cast<std::size_t>(trial % 3);
    for (int i = 0; i < len; ++i) {
      Rgba8& d = expected[offset + static_cast<std::size_t>(i)];
      d = composite_source_over_reference(d, colors[static_cast<std::size_t>(i)], coverage);
    }
    detail::blend_color_span(row.data() + offset, colors.data(), len, coverage);
    INFO("trial " << trial << " len " << len << " coverage " << int{coverage});
    REQUIRE(row == expected);
  }
}

namespace {

// `row` with its pixels offset .. offset + len composited by the reference, the others as they were.
std::vector<Rgba8> blended_by_reference(std::vector<Rgba8> row, std::size_t offset, int len, Rgba8 color,
                                        std::uint8_t coverage) {
  for (int i = 0; i < len; ++i) {
    Rgba8& d = row[offset + static_cast<std::size_t>(i)];
    d = composite_source_over_reference(d, color, coverage);
  }
  return row;
}

}  // namespace

TEST_CASE("blend_solid_span equals composite_source_over_reference for every coverage and short length",
          "[paint][fast path]") {
  // Thin strokes blend spans of one to three pixels, which take the one-pixel lanes after the four-pixel
  // loop; every coverage 0..255 at every length 0..9 and three alignments, on random backgrounds, random
  // premultiplied colours and a not-premultiplied one (the saturating add must agree too).
  std::mt19937 rng(5150);
  for (int trial = 0; trial < 24; ++trial) {
    const Rgba8 color = trial == 0 ? Rgba8{200, 250, 90, 60} : random_premultiplied(rng);
    for (int coverage = 0; coverage <= 255; ++coverage) {
      for (int len = 0; len <= 9; ++len) {
        for (std::size_t offset = 0; offset < 3; ++offset) {
          std::vector<Rgba8> row(static_cast<std::size_t>(len) + 3);
          for (Rgba8& p : row) p = random_premultiplied(rng);
          const auto cov = static_cast<std::uint8_t>(coverage);
          const std::vector<Rgba8> expected = blended_by_reference(row, offset, len, color, cov);
          detail::blend_solid_span(row.data() + offset, len, color, cov);
          INFO("trial " << trial << " len " << len << " offset " << offset << " coverage " << coverage);
          REQUIRE(row == expected);  // the pixels around the span are compared too: left untouched
        }
      }
    }
  }
}

TEST_CASE("blend_solid_span's groups of eight and of four equal composite_source_over_reference",
          "[paint][fast path]") {
  // Spans of up to 40 pixels take the AVX2 groups of eight (where the processor has AVX2), then at most
  // one group of four and the last pixels; the SSE2-only form takes groups of four. Both are held to the
  // reference at every length, at eight alignments (a 32-byte group starts at every pixel of a cache
  // line's half), for coverages at the ends and the middle and for random ones.
  std::mt19937 rng(2611);
  for (int trial = 0; trial < 16; ++trial) {
    const Rgba8 color = trial == 0 ? Rgba8{200, 250, 90, 60} : random_premultiplied(rng);
    std::vector<int> coverages = {0, 1, 2, 127, 128, 129, 254, 255};
    for (int k = 0; k < 8; ++k) coverages.push_back(static_cast<int>(rng() % 256));
    for (const int coverage : coverages) {
      for (int len = 0; len <= 40; ++len) {
        for (std::size_t offset = 0; offset < 8; ++offset) {
          std::vector<Rgba8> row(static_cast<std::size_t>(len) + 8);
          for (Rgba8& p : row) p = random_premultiplied(rng);
          const auto cov = static_cast<std::uint8_t>(coverage);
          const std::vector<Rgba8> expected = blended_by_reference(row, offset, len, color, cov);
          std::vector<Rgba8> sse2_only = row;
          detail::blend_solid_span(row.data() + offset, len, color, cov);
          detail::blend_solid_span_without_avx2(sse2_only.data() + offset, len, color, cov);
          INFO("trial " << trial << " len " << len << " offset " << offset << " coverage " << coverage);
          REQUIRE(row == expected);  // the pixels around the span are compared too: left untouched
          REQUIRE(sse2_only == expected);
        }
      }
    }
  }
}

TEST_CASE("solid fills: fast paths equal the per-pixel blend, with and without a clip mask",
          "[paint][fast path]") {
  std::mt19937 rng(1618);
  constexpr int kWidth = 83, kHeight = 47;  // odd width: spans end at every offset modulo 4
  const std::vector<Polygon> polygons = test_polygons(rng, kWidth, kHeight);
  for (int trial = 0; trial < 4 * static_cast<int>(polygons.size()); ++trial) {
    const Polygon& polygon = polygons[static_cast<std::size_t>(trial) % polygons.size()];
    const int kind = trial / static_cast<int>(polygons.size());  // opaque / translucent × no mask / mask
    const bool masked = kind >= 2;
    Rgba8 color = random_premultiplied(rng);
    color.a = kind % 2 == 0 ? 255 : static_cast<std::uint8_t>(std::max<int>(color.a % 255, 1));
    color.r = std::min(color.r, color.a);
    color.g = std::min(color.g, color.a);
    color.b = std::min(color.b, color.a);
    const Image background = random_image(rng, kWidth, kHeight);
    ClipMask mask = blocky_mask(rng, kWidth, kHeight);

    Canvas canvas(background);
    if (masked) REQUIRE(canvas.push_clip_mask(mask).is_ok());
    REQUIRE(canvas.fill(polygon.path(), Paint{color, nullptr}, FillRule::kNonZero).is_ok());

    Image expected = background;
    Rasterizer rasterizer(IntRect{0, 0, kWidth, kHeight});
    polygon.add_to(rasterizer);
    ReferenceSolidSink sink(expected, color, masked ? &mask : nullptr);
    rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
    INFO("trial " << trial << " masked " << masked << " alpha " << int{color.a});
    REQUIRE(canvas.image() == expected);
  }
}

TEST_CASE("gradient fills: the span compositor equals the per-pixel reference, with and without a mask",
          "[paint][fast path][gradient]") {
  std::mt19937 rng(31415);
  // 200 × 150 = 30 000 pixels: a full-canvas fill passes kTableAfterPixels, so the pad gradients are
  // painted partly by the walker and partly from the colour table.
  constexpr int kWidth = 201, kHeight = 150;
  static_assert(kWidth * kHeight > detail::GradientSpanCompositor::kTableAfterPixels);
  std::vector<Polygon> polygons = test_polygons(rng, kWidth, kHeight);
  polygons.resize(4);
  const std::vector<Paint> paints = test_gradients(rng, kWidth, kHeight);
  int scene = 0;
  for (const Paint& paint : paints) {
    REQUIRE(paint.gradient != nullptr);
    for (const Polygon& polygon : polygons) {
      for (const bool masked : {false, true}) {
        ++scene;
        const Image background = random_image(rng, kWidth, kHeight);
        ClipMask mask = blocky_mask(rng, kWidth, kHeight);
        const Affine user_to_device = scene % 3 == 0 ? Affine::translate(1.25, -0.5) : Affine::identity();

        Canvas canvas(background);
        if (masked) REQUIRE(canvas.push_clip_mask(mask).is_ok());
        REQUIRE(canvas.fill(polygon.path(), paint, FillRule::kNonZero, user_to_device).is_ok());

        Image expected = background;
        Rasterizer rasterizer(IntRect{0, 0, kWidth, kHeight});
        Polygon device = polygon;
        for (Point& p : device.points) p = user_to_device.apply(p);
        device.add_to(rasterizer);
        const Affine device_to_gradient = *(user_to_device * paint.gradient->gradient_to_user()).inverse();
        detail::GradientSpanReference reference(expected, 0, 0, *paint.gradient, device_to_gradient);
        if (masked) {
          detail::MaskedSpanSink through_mask(reference, mask);
          rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, through_mask);
        } else {
          rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, reference);
        }
        INFO("scene " << scene << " masked " << masked);
        REQUIRE(canvas.image() == expected);
      }
    }
  }
}

TEST_CASE("gradient tables shared between bands and fills paint the reference's bytes, on 1 and 2 threads",
          "[paint][fast path][gradient]") {
  // One canvas draws many fills in a row: the six pad gradients of test_gradients (more than the canvas
  // keeps tables for, GradientTableCache::kMaxSlots, so slots are evicted and built again), each several
  // times, every fill cut into bands of Canvas::kBandRows rows that share the gradient's table. The first
  // fills of a gradient shade with the walker, the later ones from the table built by an earlier band or
  // fill; every byte must still be the per-pixel reference's, fill after fill, in the same order.
  std::mt19937 rng(2718);
  constexpr int kWidth = 203, kHeight = 300;  // three bands of 128 rows, 61 000 pixels
  static_assert(kWidth * kHeight > 2 * detail::GradientSpanCompositor::kTableAfterPixels);
  std::vector<Paint> pads;
  for (const Paint& paint : test_gradients(rng, kWidth, kHeight)) {
    if (paint.gradient->spread() == SpreadMethod::kPad) pads.push_back(paint);
  }
  REQUIRE(pads.size() > detail::GradientTableCache::kMaxSlots);
  std::vector<Polygon> polygons = test_polygons(rng, kWidth, kHeight);
  polygons.resize(3);  // the whole canvas, a fractional rectangle, a quadrilateral
  const Image background = random_image(rng, kWidth, kHeight);

  Image expected = background;
  struct Draw {
    const Paint* paint;
    const Polygon* polygon;
  };
  std::vector<Draw> draws;
  for (int round = 0; round < 3; ++round) {
    for (std::size_t i = 0; i < pads.size(); ++i) {
      draws.push_back({&pads[i], &polygons[(i + static_cast<std::size_t>(round)) % polygons.size()]});
    }
  }
  for (const Draw& draw : draws) {
    Rasterizer rasterizer(IntRect{0, 0, kWidth, kHeight});
    draw.polygon->add_to(rasterizer);
    const Affine device_to_gradient = *draw.paint->gradient->gradient_to_user().inverse();
    detail::GradientSpanReference reference(expected, 0, 0, *draw.paint->gradient, device_to_gradient);
    rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, reference);
  }
  for (const int threads : {1, 2}) {
    Canvas canvas(background);
    canvas.set_threads(threads);
    const std::int64_t memory_before = canvas.memory_bytes();
    for (const Draw& draw : draws) {
      REQUIRE(canvas.fill(draw.polygon->path(), *draw.paint, FillRule::kNonZero).is_ok());
    }
    INFO("threads " << threads);
    REQUIRE(canvas.image() == expected);
    // The tables kept count against the render's memory: at most kMaxSlots of them.
    CHECK(canvas.memory_bytes() > memory_before);
    const auto most_tables = static_cast<std::int64_t>(detail::GradientTableCache::kMaxSlots);
    CHECK(canvas.memory_bytes() <= memory_before + most_tables * detail::PadColorTable::kBytes);
  }
}

TEST_CASE("gradient table slots: at most kMaxSlots, none while every one is held by queued bands",
          "[paint][fast path][gradient]") {
  // Every table the canvas builds lives in a kept slot, so that memory_bytes() sees it: when all the
  // slots are held (as by bands still queued on other threads), a fill of another gradient gets none.
  std::mt19937 rng(99);
  std::vector<Paint> pads;
  for (const Paint& paint : test_gradients(rng, 64, 64)) {
    if (paint.gradient->spread() == SpreadMethod::kPad) pads.push_back(paint);
  }
  REQUIRE(pads.size() > detail::GradientTableCache::kMaxSlots);
  detail::GradientTableCache cache;
  std::vector<std::shared_ptr<detail::GradientTableSlot>> held;
  for (std::size_t i = 0; i < detail::GradientTableCache::kMaxSlots; ++i) {
    held.push_back(cache.slot_for(pads[i].gradient, true));
    REQUIRE(held.back() != nullptr);
    CHECK(cache.slot_for(pads[i].gradient, true) == held.back());  // the same gradient, the same slot
  }
  const auto& extra = pads[detail::GradientTableCache::kMaxSlots].gradient;
  CHECK(cache.slot_for(extra, true) == nullptr);
  CHECK(cache.slot_for(extra, false) == nullptr);
  held[1].reset();  // its bands are done: that entry may be reused
  const std::shared_ptr<detail::GradientTableSlot> reused = cache.slot_for(extra, true);
  CHECK(reused != nullptr);
  CHECK(cache.slot_for(pads[1].gradient, true) == nullptr);  // evicted, and no entry is free now
}

TEST_CASE("gradient span compositor equals the reference in a layer's coordinates",
          "[paint][fast path][gradient]") {
  // A layer's pixel (0, 0) is canvas pixel (origin_x, origin_y); spans stay in canvas coordinates.
  std::mt19937 rng(4242);
  constexpr int kOriginX = 13, kOriginY = 7, kWidth = 180, kHeight = 140;
  for (const Paint& paint : test_gradients(rng, kWidth, kHeight)) {
    const Image background = random_image(rng, kWidth, kHeight);
    std::vector<Span> spans;
    for (int y = kOriginY; y < kOriginY + kHeight; ++y) {
      const int x0 = kOriginX + (y * 7) % 5;
      spans.push_back(
          {x0, y, kWidth - (x0 - kOriginX) - (y % 3), static_cast<std::uint8_t>(y % 4 == 0 ? 255 : y)});
    }
    const Affine device_to_gradient = *paint.gradient->gradient_to_user().inverse();
    Image fast = background, expected = background;
    detail::GradientSpanCompositor compositor(fast, kOriginX, kOriginY, *paint.gradient, device_to_gradient);
    detail::GradientSpanReference reference(expected, kOriginX, kOriginY, *paint.gradient,
                                            device_to_gradient);
    compositor.blend(spans);
    reference.blend(spans);
    REQUIRE(fast == expected);
  }
}

TEST_CASE("the radial parameter's two-lane solve equals GradientShader::parameter_at bit for bit",
          "[paint][fast path][gradient]") {
  std::mt19937 rng(777);
  const std::vector<GradientStop> stops{{0, {1, 0, 0, 1}}, {1, {0, 0, 1, 1}}};
  const std::vector<RadialGradient> geometries{
      {{50, 40}, 30, {55, 42}, 0}, {{50, 40}, 30, {55, 42}, 8}, {{0, 0}, 30, {10, 0}, 20},  // A = 0
      {{0, 0}, 10, {0, 0}, 25},    {{5, 5}, 4, {5, 5}, 1},      {{0, 0}, 1, {0.999, 0}, 0},
  };
  const std::vector<Affine> mappings{Affine::identity(), Affine::scale(0.37, 1.9) * Affine::rotate(1.1),
                                     Affine::translate(-20, 13) * Affine::skew_x(0.4), Affine::scale(1e300),
                                     Affine::scale(1e-300)};
  for (const RadialGradient& geometry : geometries) {
    const Paint paint = radial_gradient_paint(geometry, stops, SpreadMethod::kPad);
    REQUIRE(paint.gradient != nullptr);
    const GradientShader& shader = *paint.gradient;
    for (const Affine& m : mappings) {
      const detail::RadialParameter parameter(shader, m);
      for (int row = 0; row < 40; ++row) {
        const int x = std::uniform_int_distribution<int>(-100, 100)(rng);
        const double center_y = std::uniform_int_distribution<int>(-100, 100)(rng) + 0.5;
        std::vector<double> values(37);
        parameter.fill(x, center_y, 37, values.data());
        for (int i = 0; i < 37; ++i) {
          const double expected = shader.parameter_at(m.apply(Point{x + i + 0.5, center_y}));
          const double got = values[static_cast<std::size_t>(i)];
          INFO("x " << x + i << " y " << center_y << " expected " << expected << " got " << got);
          // NaN (no circle through the point) on both sides, or the same double.
          REQUIRE(((std::isnan(expected) && std::isnan(got)) || expected == got));
          if (!std::isnan(expected)) REQUIRE(std::signbit(expected) == std::signbit(got));
        }
      }
    }
  }
}

TEST_CASE("the pad colour table is the walker's colour at every position", "[paint][fast path][gradient]") {
  std::mt19937 rng(99);
  const std::vector<GradientStop> stops{{0.0, {1, 0, 0, 1}},
                                        {0.3, {1, 1, 0, 0.4}},
                                        {0.3, {0, 0, 1, 0.7}},
                                        {0.31, {0, 1, 1, 1}},
                                        {1.0, {0.2, 0.2, 0.2, 0.0}}};
  const Paint paint = linear_gradient_paint({{0, 0}, {1, 0}}, stops, SpreadMethod::kPad);
  detail::GradientWalker walker(*paint.gradient);
  detail::GradientWalker table_walker(*paint.gradient);
  const detail::PadColorTable table(table_walker);
  // Every 16.16 position of the ramp and beyond both ends.
  for (std::int64_t pos = -3; pos <= detail::kFixedOne + 3; ++pos) {
    const double t = static_cast<double>(pos) / 65536.0;
    INFO("pos " << pos);
    REQUIRE(table.color_at(t) == walker.color_at(t));
  }
  // t just off the 16.16 grid (the snapping of fixed_position), far outside, infinite and NaN.
  std::vector<double> ts{std::numeric_limits<double>::quiet_NaN(),
                         std::numeric_limits<double>::infinity(),
                         -std::numeric_limits<double>::infinity(),
                         1e300,
                         -1e300,
                         3e9,
                         -3e9,
                         0.0,
                         -0.0,
                         1.0};
  for (int k = 0; k < 20000; ++k) {
    const double grid = std::uniform_int_distribution<int>(-70000, 140000)(rng) / 65536.0;
    ts.push_back(grid);
    ts.push_back(std::nextafter(grid, 10.0));
    ts.push_back(std::nextafter(grid, -10.0));
    ts.push_back(grid + 1e-11);
    ts.push_back(grid - 1e-11);
    ts.push_back(std::uniform_real_distribution<double>(-3.0, 3.0)(rng));
  }
  std::vector<Rgba8> batch(ts.size());
  table.colors_at(ts.data(), static_cast<int>(ts.size()), batch.data());
  for (std::size_t i = 0; i < ts.size(); ++i) {
    INFO("t " << ts[i]);
    REQUIRE(table.color_at(ts[i]) == walker.color_at(ts[i]));
    REQUIRE(batch[i] == walker.color_at(ts[i]));
  }
}

TEST_CASE("the walker's run of consecutive positions equals one position at a time, for every spread",
          "[paint][fast path][gradient]") {
  const std::vector<GradientStop> stops{
      {0.0, {1, 0, 0, 1}}, {0.5, {0, 1, 0, 0.25}}, {0.5, {0, 0, 1, 1}}, {1.0, {1, 1, 1, 0.5}}};
  for (const SpreadMethod spread : {SpreadMethod::kPad, SpreadMethod::kRepeat, SpreadMethod::kReflect}) {
    const Paint paint = linear_gradient_paint({{0, 0}, {1, 0}}, stops, spread);
    for (const std::int64_t first :
         {std::int64_t{-70000}, std::int64_t{-1}, std::int64_t{30000}, std::int64_t{200000}}) {
      detail::GradientWalker run_walker(*paint.gradient), one_walker(*paint.gradient);
      std::vector<Rgba8> run(140000);
      run_walker.colors_at_fixed(first, run.size(), run.data());
      for (std::size_t i = 0; i < run.size(); ++i) {
        INFO("spread " << static_cast<int>(spread) << " pos " << first + static_cast<std::int64_t>(i));
        REQUIRE(run[i] == one_walker.color_at_fixed(first + static_cast<std::int64_t>(i)));
      }
    }
  }
}

TEST_CASE("the walker's four-channel SSE2 evaluation equals pixman's scalar one at every position",
          "[paint][fast path][gradient]") {
  // Random stops (translucent, hard stops, stops close together: steep ramps where float rounding
  // matters) under every spread, over three periods on each side of [0, 1].
  std::mt19937 rng(5150);
  for (int trial = 0; trial < 12; ++trial) {
    const SpreadMethod spread =
        std::array{SpreadMethod::kPad, SpreadMethod::kRepeat, SpreadMethod::kReflect}[trial % 3];
    std::vector<GradientStop> stops = random_stops(rng, trial % 2 == 0);
    if (trial % 4 == 1)
      stops.insert(stops.begin() + 1, GradientStop{stops[0].offset + 1e-4, {0.5, 0.25, 1.0, 0.125}});
    const Paint paint = linear_gradient_paint({{0, 0}, {1, 0}}, stops, spread);
    REQUIRE(paint.gradient != nullptr);
    detail::GradientWalker fast(*paint.gradient), plain(*paint.gradient);
    for (std::int64_t pos = -3 * detail::kFixedOne; pos <= 4 * detail::kFixedOne; ++pos) {
      const Rgba8 expected = plain.color_at_fixed_plain(pos);
      if (fast.color_at_fixed(pos) != expected) {
        INFO("trial " << trial << " pos " << pos);
        REQUIRE(fast.color_at_fixed(pos) == expected);
      }
    }
  }
}

TEST_CASE("a gradient fill whose memory budget has no room for the colour table paints the same bytes",
          "[paint][fast path][gradient]") {
  // The budget holds the image and the fill's few edges but not PadColorTable::kBytes more, so every
  // colour comes from the walker; the direct compositor without the table agrees with the reference too.
  constexpr int kWidth = 201, kHeight = 150;
  static_assert(kWidth * kHeight > detail::GradientSpanCompositor::kTableAfterPixels);
  const std::vector<GradientStop> stops{{0.0, {1, 0, 0, 1}}, {0.5, {0, 1, 0, 0.5}}, {1.0, {0, 0, 1, 1}}};
  const Paint paint = linear_gradient_paint({{10, 20}, {190, 130}}, stops, SpreadMethod::kPad);
  RenderLimits tight;
  tight.max_memory_bytes = std::int64_t{kWidth} * kHeight * 4 + detail::PadColorTable::kBytes / 2;
  Result<Canvas> limited = Canvas::create(kWidth, kHeight, tight);
  REQUIRE(limited);
  Result<Canvas> unlimited = Canvas::create(kWidth, kHeight);
  REQUIRE(unlimited);
  const Path rectangle = Polygon{{{0, 0}, {kWidth, 0}, {kWidth, kHeight}, {0, kHeight}}}.path();
  REQUIRE(limited->fill(rectangle, paint, FillRule::kNonZero).is_ok());
  REQUIRE(unlimited->fill(rectangle, paint, FillRule::kNonZero).is_ok());
  CHECK(limited->image() == unlimited->image());

  std::vector<Span> spans;
  for (int y = 0; y < kHeight; ++y) spans.push_back({0, y, kWidth, 255});
  Image walker_only(kWidth, kHeight), expected(kWidth, kHeight);
  detail::GradientSpanCompositor compositor(walker_only, 0, 0, *paint.gradient, Affine::identity(), false);
  detail::GradientSpanReference reference(expected, 0, 0, *paint.gradient, Affine::identity());
  compositor.blend(spans);
  reference.blend(spans);
  CHECK(walker_only == expected);
  CHECK(walker_only == unlimited->image());
}
