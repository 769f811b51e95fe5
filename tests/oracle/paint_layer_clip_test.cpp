// Group opacity and clip masks against Cairo (cairo_push_group / cairo_paint_with_alpha, cairo_clip).
//
// Metrics and thresholds:
//  - group opacity over pixel-aligned content: bit-exact (max |Δ| = 0). Both sides composite the layer
//    with pixman's OVER through a constant alpha converted as cairo_paint_with_alpha converts it
//    (layer.h), and the content is the same bytes (tests/oracle/compositing_test.cpp).
//  - antialiased content and clips: our coverage differs from Cairo's by up to 20/255 on edge pixels
//    (cairo_oracle_test.cpp). Where a clip edge and a shape edge cross the same pixel, Cairo intersects
//    the two polygons while we multiply two coverages (mask.h); for a pixel half covered by each, that
//    is 0.5 vs 0.25 (or 0), up to ~64 levels on those few pixels. So: max |Δ| <= 80 with at most 1 % of
//    pixels off by more than 20, and mean |Δ| <= 0.5 levels.
#include <cairo.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"
#include "paint_oracle.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr int kWidth = 80, kHeight = 64;
constexpr double kPi = 3.14159265358979323846;

Path rect_path(double x, double y, double w, double h) {
  return *PathBuilder()
              .move_to({x, y})
              .line_to({x + w, y})
              .line_to({x + w, y + h})
              .line_to({x, y + h})
              .close()
              .build();
}

Path circle_path(double cx, double cy, double r) {
  return *PathBuilder().arc({cx, cy}, r, r, 0.0, 0.0, 2.0 * kPi).close().build();
}

int count_over(const Image& a, const Image& b, int threshold) {
  int count = 0;
  for (std::size_t i = 0; i < a.pixels().size(); ++i) {
    const Rgba8 p = a.pixels()[i], q = b.pixels()[i];
    if (std::abs(p.r - q.r) > threshold || std::abs(p.g - q.g) > threshold ||
        std::abs(p.b - q.b) > threshold || std::abs(p.a - q.a) > threshold) {
      ++count;
    }
  }
  return count;
}

Image background() {
  Image image(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      image.at(x, y) = ((x / 8 + y / 8) % 2 == 0) ? Rgba8{200, 200, 200, 255} : Rgba8{40, 60, 80, 255};
    }
  }
  return image;
}

}  // namespace

TEST_CASE("group opacity over pixel-aligned shapes equals cairo_push_group + cairo_paint_with_alpha",
          "[oracle][paint][layer]") {
  for (const double opacity : {1.0, 0.75, 0.5, 0.3, 0.01, 0.0}) {
    Canvas canvas(background());
    REQUIRE(canvas.push_layer().is_ok());
    REQUIRE(
        canvas.fill(rect_path(5, 5, 40, 30), Paint::solid({0.9, 0.1, 0.1, 1.0}), FillRule::kNonZero).is_ok());
    REQUIRE(canvas.fill(rect_path(25, 20, 40, 30), Paint::solid({0.1, 0.2, 0.9, 0.6}), FillRule::kNonZero)
                .is_ok());
    REQUIRE(canvas.push_layer().is_ok());  // a nested group at half opacity
    REQUIRE(canvas.fill(rect_path(10, 40, 60, 15), Paint::solid({0.1, 0.8, 0.2, 0.9}), FillRule::kNonZero)
                .is_ok());
    REQUIRE(canvas.pop_layer(0.5).is_ok());
    REQUIRE(canvas.pop_layer(opacity).is_ok());

    cairo_surface_t* surface = argb_surface_of(background());
    cairo_t* cr = cairo_create(surface);
    cairo_push_group(cr);
    cairo_set_source_rgba(cr, 0.9, 0.1, 0.1, 1.0);
    cairo_rectangle(cr, 5, 5, 40, 30);
    cairo_fill(cr);
    cairo_set_source_rgba(cr, 0.1, 0.2, 0.9, 0.6);
    cairo_rectangle(cr, 25, 20, 40, 30);
    cairo_fill(cr);
    cairo_push_group(cr);
    cairo_set_source_rgba(cr, 0.1, 0.8, 0.2, 0.9);
    cairo_rectangle(cr, 10, 40, 60, 15);
    cairo_fill(cr);
    cairo_pop_group_to_source(cr);
    cairo_paint_with_alpha(cr, 0.5);
    cairo_pop_group_to_source(cr);
    cairo_paint_with_alpha(cr, opacity);
    cairo_destroy(cr);
    const Image cairo = image_of_surface(surface);
    cairo_surface_destroy(surface);

    const PixelDiff diff = pixel_diff(canvas.image(), cairo);
    std::printf("layer oracle opacity %.2f: max |d| %d, mean |d| %.4f\n", opacity, diff.max_channel,
                diff.mean_channel);
    INFO("opacity " << opacity);
    CHECK(diff.max_channel == 0);
  }
}

TEST_CASE("antialiased clip paths (nested, both rules, transformed) match cairo_clip",
          "[oracle][paint][clip]") {
  const Path ring = *PathBuilder()
                         .arc({40, 32}, 30, 30, 0.0, 0.0, 2.0 * kPi)
                         .close()
                         .move_to({55, 32})
                         .arc({40, 32}, 15, 15, 0.0, 0.0, 2.0 * kPi)
                         .close()
                         .build();
  const Affine skew = Affine::translate(3.3, 1.7) * Affine::skew_x(0.15);
  for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
    Canvas canvas(background());
    REQUIRE(canvas.push_clip(ring, rule, skew).is_ok());
    REQUIRE(canvas.push_clip(rect_path(12.5, 6.25, 50, 40), FillRule::kNonZero).is_ok());
    REQUIRE(
        canvas.fill(circle_path(45, 30, 28), Paint::solid({0.9, 0.5, 0.1, 0.8}), FillRule::kNonZero).is_ok());
    REQUIRE(canvas.push_layer().is_ok());  // a group inside the clips: drawn through them once
    REQUIRE(canvas.fill(rect_path(0, 25, 80, 10), Paint::solid({0.1, 0.3, 0.9, 1.0}), FillRule::kNonZero)
                .is_ok());
    REQUIRE(canvas.pop_layer(0.6).is_ok());
    REQUIRE(canvas.pop_clip().is_ok());
    REQUIRE(canvas.pop_clip().is_ok());

    cairo_surface_t* surface = argb_surface_of(background());
    cairo_t* cr = cairo_create(surface);
    const cairo_matrix_t m = cairo_matrix_of(skew);
    cairo_save(cr);
    cairo_set_matrix(cr, &m);
    cairo_new_sub_path(cr);
    cairo_arc(cr, 40, 32, 30, 0, 2 * kPi);
    cairo_close_path(cr);
    cairo_new_sub_path(cr);
    cairo_arc(cr, 40, 32, 15, 0, 2 * kPi);
    cairo_close_path(cr);
    cairo_restore(cr);
    cairo_set_fill_rule(cr, rule == FillRule::kNonZero ? CAIRO_FILL_RULE_WINDING : CAIRO_FILL_RULE_EVEN_ODD);
    cairo_clip(cr);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    cairo_rectangle(cr, 12.5, 6.25, 50, 40);
    cairo_clip(cr);
    cairo_set_source_rgba(cr, 0.9, 0.5, 0.1, 0.8);
    cairo_arc(cr, 45, 30, 28, 0, 2 * kPi);
    cairo_fill(cr);
    // Cairo keeps the clip while drawing into the group and applies it again when painting the group,
    // squaring antialiased clip edges; a group inside a clip is therefore drawn unclipped and clipped
    // once at the paint, which is our semantics (layer_stack.cpp).
    cairo_push_group(cr);
    cairo_reset_clip(cr);
    cairo_set_source_rgba(cr, 0.1, 0.3, 0.9, 1.0);
    cairo_rectangle(cr, 0, 25, 80, 10);
    cairo_fill(cr);
    cairo_pop_group_to_source(cr);
    cairo_paint_with_alpha(cr, 0.6);
    cairo_destroy(cr);
    const Image cairo = image_of_surface(surface);
    cairo_surface_destroy(surface);

    const PixelDiff diff = pixel_diff(canvas.image(), cairo);
    const int over_20 = count_over(canvas.image(), cairo, 20);
    std::printf("clip oracle (%s): max |d| %d, mean |d| %.4f, pixels |d| > 20: %d\n",
                rule == FillRule::kNonZero ? "nonzero" : "evenodd", diff.max_channel, diff.mean_channel,
                over_20);
    CHECK(diff.max_channel <= 80);
    CHECK(over_20 <= kWidth * kHeight / 100);
    CHECK(diff.mean_channel <= 0.5);
  }
}
