// Image paints (image_pattern.h) against Cairo: the same image as a surface pattern, with the same
// extend, filter, pattern matrix and CTM, painted over a rectangle of the canvas.
//
// Metric and thresholds. Nearest sampling picks the same pixel as pixman wherever a pixel centre does not
// fall within Cairo's 16.16 fixed-point error (~2^-16) of a texel edge; the scenes keep centres away
// from edges (offsets of a quarter pixel, scales of 2 and 3) and the filled rectangle on whole device
// pixels (so coverage is 255 or 0 in both), so the bytes must agree exactly. Bilinear:
// pixman quantizes the weights to 7 bits (1/128), so a channel may differ by up to 255/128 ≈ 2 levels;
// max |Δ| <= 2 and mean |Δ| <= 0.5.
#include <cairo.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <string>
#include <utility>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/image_pattern.h"
#include "curvescan/raster/path_builder.h"
#include "paint_oracle.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr int kSize = 48;

// A 5 x 3 tile of distinct colours, some translucent (premultiplied).
Image tile() {
  Image image(5, 3);
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 5; ++x) {
      const auto a = static_cast<std::uint8_t>(y == 1 ? 128 : 255);
      image.at(x, y) =
          Rgba8{static_cast<std::uint8_t>((x * 50) * a / 255), static_cast<std::uint8_t>((y * 100) * a / 255),
                static_cast<std::uint8_t>(((4 - x) * 60) * a / 255), a};
    }
  }
  return image;
}

Path rect_path(double x, double y, double w, double h) {
  return *PathBuilder()
              .move_to({x, y})
              .line_to({x + w, y})
              .line_to({x + w, y + h})
              .line_to({x, y + h})
              .close()
              .build();
}

Image cairo_render(const Image& source, const Affine& image_to_user, const Affine& user_to_device,
                   cairo_extend_t extend, cairo_filter_t filter, double opacity) {
  cairo_surface_t* target = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kSize, kSize);
  cairo_t* cr = cairo_create(target);
  const cairo_matrix_t ctm = cairo_matrix_of(user_to_device);
  cairo_set_matrix(cr, &ctm);
  cairo_surface_t* surface = argb_surface_of(source);
  cairo_pattern_t* pattern = cairo_pattern_create_for_surface(surface);
  // Cairo's pattern matrix maps user space to pattern space: the inverse of image_to_user.
  const cairo_matrix_t to_pattern = cairo_matrix_of(*image_to_user.inverse());
  cairo_pattern_set_matrix(pattern, &to_pattern);
  cairo_pattern_set_extend(pattern, extend);
  cairo_pattern_set_filter(pattern, filter);
  cairo_set_source(cr, pattern);
  cairo_rectangle(cr, 2, 2, 20, 20);
  cairo_clip(cr);
  cairo_paint_with_alpha(cr, opacity);
  Image result = image_of_surface(target);
  cairo_pattern_destroy(pattern);
  cairo_surface_destroy(surface);
  cairo_destroy(cr);
  cairo_surface_destroy(target);
  return result;
}

Image our_render(const Image& source, const Affine& image_to_user, const Affine& user_to_device,
                 PatternExtend extend, PatternFilter filter, double opacity) {
  Canvas canvas{Image(kSize, kSize)};
  const Paint paint = image_pattern_paint(source, image_to_user, extend, filter, opacity);
  REQUIRE(canvas.fill(rect_path(2, 2, 20, 20), paint, FillRule::kNonZero, user_to_device).is_ok());
  return std::move(canvas).take_image();
}

}  // namespace

TEST_CASE("image pattern, nearest: the same bytes as Cairo's repeat and none extends", "[oracle][pattern]") {
  const Image source = tile();
  struct Scene {
    const char* name;
    Affine image_to_user, user_to_device;
  };
  const Scene scenes[] = {
      {"translated", Affine::translate(1.25, 2.25), Affine::identity()},
      {"scaled 2", Affine::translate(0.25, 0.25) * Affine::scale(2.0), Affine::identity()},
      {"scaled 3 by 2, then a ctm of 2", Affine::scale(3.0, 2.0), Affine::scale(2.0)},
  };
  for (const Scene& scene : scenes) {
    for (const bool repeat : {true, false}) {
      INFO(scene.name << (repeat ? " repeat" : " none"));
      const Image ours =
          our_render(source, scene.image_to_user, scene.user_to_device,
                     repeat ? PatternExtend::kRepeat : PatternExtend::kNone, PatternFilter::kNearest, 1.0);
      const Image cairo =
          cairo_render(source, scene.image_to_user, scene.user_to_device,
                       repeat ? CAIRO_EXTEND_REPEAT : CAIRO_EXTEND_NONE, CAIRO_FILTER_NEAREST, 1.0);
      const PixelDiff diff = pixel_diff(ours, cairo);
      CHECK(diff.max_channel == 0);
    }
  }
}

TEST_CASE("image pattern, bilinear with opacity: within pixman's weight quantization of Cairo",
          "[oracle][pattern]") {
  const Image source = tile();
  const std::pair<PatternExtend, cairo_extend_t> extends[] = {{PatternExtend::kRepeat, CAIRO_EXTEND_REPEAT},
                                                              {PatternExtend::kNone, CAIRO_EXTEND_NONE},
                                                              {PatternExtend::kPad, CAIRO_EXTEND_PAD}};
  for (const auto& [ours_extend, cairo_extend] : extends) {
    INFO(static_cast<int>(ours_extend));
    const Affine image_to_user = Affine::translate(3.0, 1.0) * Affine::rotate(0.3) * Affine::scale(2.5);
    const Image ours =
        our_render(source, image_to_user, Affine::identity(), ours_extend, PatternFilter::kBilinear, 0.5);
    const Image cairo =
        cairo_render(source, image_to_user, Affine::identity(), cairo_extend, CAIRO_FILTER_BILINEAR, 0.5);
    const PixelDiff diff = pixel_diff(ours, cairo);
    std::printf("image pattern bilinear, extend %d: max |delta| %d, mean %.4f\n",
                static_cast<int>(ours_extend), diff.max_channel, diff.mean_channel);
    CHECK(diff.max_channel <= 2);
    CHECK(diff.mean_channel <= 0.5);
  }
}

TEST_CASE("image pattern: degenerate input paints nothing", "[pattern]") {
  CHECK(image_pattern_paint(Image(), Affine::identity(), PatternExtend::kRepeat, PatternFilter::kNearest)
            .pattern == nullptr);
  CHECK(image_pattern_paint(tile(), Affine::scale(0.0), PatternExtend::kRepeat, PatternFilter::kNearest)
            .pattern == nullptr);
  CHECK(image_pattern_paint(tile(), Affine::identity(), PatternExtend::kRepeat, PatternFilter::kNearest, 0.0)
            .pattern == nullptr);
  CHECK(image_pattern_paint(tile(), Affine::identity(), PatternExtend::kRepeat, PatternFilter::kNearest)
            .kind() == PaintKind::kImagePattern);
}
