// Compositing against Cairo: curvescan's source-over with coverage and its colour conversion must produce
// Cairo's bytes exactly (maximum difference 0), since both claim pixman's rounding (paint.h).
#include <cairo.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/pixel_format.h"
#include "paint_oracle.h"

using namespace curvescan;
using curvescan::testing::argb_surface_of;
using curvescan::testing::image_of_surface;

namespace {

constexpr int kSide = 256;  // 65536 random triples per run


Rgba8 random_premultiplied(std::mt19937& rng) {
  std::uniform_int_distribution<int> byte(0, 255);
  // A third of the alphas at the extremes, where fast paths and special cases live.
  const int pick = byte(rng) % 6;
  const int a = pick == 0 ? 255 : (pick == 1 ? 0 : byte(rng));
  std::uniform_int_distribution<int> channel(0, a);
  return {static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(channel(rng)),
          static_cast<std::uint8_t>(channel(rng)), static_cast<std::uint8_t>(a)};
}

}  // namespace

TEST_CASE("composite_source_over matches Cairo's OVER through an A8 mask bit for bit",
          "[oracle][composite]") {
  std::mt19937 rng(20240229);
  std::uniform_int_distribution<int> byte(0, 255);
  Image destination(kSide, kSide), source(kSide, kSide);
  std::vector<std::uint8_t> coverage(static_cast<std::size_t>(kSide) * kSide);
  for (int i = 0; i < kSide * kSide; ++i) {
    destination.pixels()[static_cast<std::size_t>(i)] = random_premultiplied(rng);
    source.pixels()[static_cast<std::size_t>(i)] = random_premultiplied(rng);
    const int pick = byte(rng) % 4;
    coverage[static_cast<std::size_t>(i)] =
        static_cast<std::uint8_t>(pick == 0 ? 255 : (pick == 1 ? 0 : byte(rng)));
  }

  cairo_surface_t* target = argb_surface_of(destination);
  cairo_surface_t* paint = argb_surface_of(source);
  cairo_surface_t* mask = cairo_image_surface_create(CAIRO_FORMAT_A8, kSide, kSide);
  cairo_surface_flush(mask);
  unsigned char* mask_data = cairo_image_surface_get_data(mask);
  const int mask_stride = cairo_image_surface_get_stride(mask);
  for (int y = 0; y < kSide; ++y) {
    std::memcpy(mask_data + static_cast<std::ptrdiff_t>(y) * mask_stride,
                &coverage[static_cast<std::size_t>(y) * kSide], kSide);
  }
  cairo_surface_mark_dirty(mask);
  cairo_t* cr = cairo_create(target);
  cairo_set_operator(cr, CAIRO_OPERATOR_OVER);
  cairo_set_source_surface(cr, paint, 0, 0);
  cairo_mask_surface(cr, mask, 0, 0);
  cairo_destroy(cr);
  const Image cairo_result = image_of_surface(target);
  cairo_surface_destroy(mask);
  cairo_surface_destroy(paint);
  cairo_surface_destroy(target);

  int mismatches = 0;
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) {
      const Rgba8 ours = composite_source_over(destination.at(x, y), source.at(x, y),
                                               coverage[static_cast<std::size_t>(y) * kSide + x]);
      if (!(ours == cairo_result.at(x, y)) && ++mismatches <= 5) {
        const Rgba8 d = destination.at(x, y), s = source.at(x, y), c = cairo_result.at(x, y);
        INFO("dst " << +d.r << "," << +d.g << "," << +d.b << "," << +d.a << " src " << +s.r << "," << +s.g
                    << "," << +s.b << "," << +s.a << " cov "
                    << +coverage[static_cast<std::size_t>(y) * kSide + x] << " ours " << +ours.r << ","
                    << +ours.g << "," << +ours.b << "," << +ours.a << " cairo " << +c.r << "," << +c.g << ","
                    << +c.b << "," << +c.a);
        CHECK(ours == c);
      }
    }
  }
  CHECK(mismatches == 0);
}

TEST_CASE("Paint::solid gives the bytes cairo_set_source_rgba paints", "[oracle][paint]") {
  std::mt19937 rng(8080);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  cairo_surface_t* target = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 1, 1);
  int mismatches = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double r = unit(rng), g = unit(rng), b = unit(rng);
    const double a = trial % 5 == 0 ? 1.0 : unit(rng);
    cairo_t* cr = cairo_create(target);
    cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
    cairo_set_source_rgba(cr, r, g, b, a);
    cairo_paint(cr);
    cairo_destroy(cr);
    const Rgba8 cairo_pixel = image_of_surface(target).at(0, 0);
    const Rgba8 ours = Paint::solid({r, g, b, a}).color;
    if (!(ours == cairo_pixel) && ++mismatches <= 5) {
      INFO("rgba " << r << " " << g << " " << b << " " << a);
      CHECK(ours == cairo_pixel);
    }
  }
  cairo_surface_destroy(target);
  CHECK(mismatches == 0);
}

TEST_CASE("Canvas::fill of a pixel-aligned rectangle equals cairo_fill on the same background",
          "[oracle][canvas]") {
  std::mt19937 rng(1999);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Image background(40, 30);
  for (Rgba8& p : background.pixels()) p = random_premultiplied(rng);
  for (int trial = 0; trial < 20; ++trial) {
    const double r = unit(rng), g = unit(rng), b = unit(rng), a = trial % 4 == 0 ? 1.0 : unit(rng);
    Canvas canvas(background);
    const Path rect =
        *PathBuilder().move_to({3, 4}).line_to({33, 4}).line_to({33, 27}).line_to({3, 27}).close().build();
    REQUIRE(canvas.fill(rect, Paint::solid({r, g, b, a}), FillRule::kNonZero).is_ok());

    cairo_surface_t* target = argb_surface_of(background);
    cairo_t* cr = cairo_create(target);
    cairo_set_source_rgba(cr, r, g, b, a);
    cairo_rectangle(cr, 3, 4, 30, 23);
    cairo_fill(cr);
    cairo_destroy(cr);
    CHECK(canvas.image() == image_of_surface(target));
    cairo_surface_destroy(target);
  }
}
