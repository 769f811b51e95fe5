// Gradients against Cairo: the same gradient (cairo_pattern_create_linear/radial with the normalized
// stops, the same extend, gradient matrix and CTM) painted over the whole canvas, compared per channel.
//
// Metric and thresholds. We evaluate t in double at each pixel centre; Cairo hands pixman a 16.16
// fixed-point matrix and 16.16 end points (after _cairo_gradient_pattern_fit_to_range), so the two t
// differ by a few 2^-16. Colour arithmetic is pixman's own (gradient_walker.h), so away from hard stops
// that t difference moves a channel by far less than a level and the bytes agree up to one level where
// a value sits on a rounding boundary: max |Δ| <= 1 everywhere except at hard stops (two stops at the
// same offset), where a pixel whose t lies within ~2^-15 of the stop may take either side's colour.
// Scenes with a hard stop allow such pixels: at most 1 % of the canvas. Mean |Δ| <= 0.05 levels
// everywhere (measured figures are printed).
#include <cairo.h>

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/path_builder.h"
#include "paint_oracle.h"

using namespace curvescan;
using namespace curvescan::testing;

namespace {

constexpr int kWidth = 120, kHeight = 90;
// Pixels whose t lies within this of a discontinuity may take either side's colour. Cairo hands pixman
// the device-to-pattern matrix in 16.16 fixed point: each entry is off by up to 2^-17, times pixel
// coordinates up to 120, i.e. ~1e-3 gradient units, which over the smallest gradient period of these
// scenes (a radius of 0.3 units) is ~3e-3 in t; 1/128 covers that with margin.
constexpr double kDiscontinuityBand = 1.0 / 128;

struct GradientScene {
  std::string name;
  bool radial = false;
  LinearGradient linear;
  RadialGradient radial_geometry;
  std::vector<GradientStop> stops;
  SpreadMethod spread = SpreadMethod::kPad;
  Affine gradient_to_user;
  Affine user_to_device;
  bool hard_stop = false;
};

cairo_extend_t extend_of(SpreadMethod spread) {
  switch (spread) {
    case SpreadMethod::kPad:
      return CAIRO_EXTEND_PAD;
    case SpreadMethod::kReflect:
      return CAIRO_EXTEND_REFLECT;
    case SpreadMethod::kRepeat:
      return CAIRO_EXTEND_REPEAT;
  }
  return CAIRO_EXTEND_PAD;
}

// A square far larger than the canvas in user space: after any of the scenes' transforms it covers
// every pixel fully, so coverage is 255 everywhere and only the gradient is compared.
Path covering_square() {
  return *PathBuilder()
              .move_to({-1e4, -1e4})
              .line_to({1e4, -1e4})
              .line_to({1e4, 1e4})
              .line_to({-1e4, 1e4})
              .close()
              .build();
}

Image render_ours(const GradientScene& scene, const Image& background) {
  Canvas canvas(background);
  const Paint paint =
      scene.radial
          ? radial_gradient_paint(scene.radial_geometry, scene.stops, scene.spread, scene.gradient_to_user)
          : linear_gradient_paint(scene.linear, scene.stops, scene.spread, scene.gradient_to_user);
  REQUIRE(paint.gradient != nullptr);
  REQUIRE(canvas.fill(covering_square(), paint, FillRule::kNonZero, scene.user_to_device).is_ok());
  return std::move(canvas).take_image();
}

Image render_cairo(const GradientScene& scene, const Image& background) {
  // Cairo is given exactly what the shader uses: normalized stops and the clamped focal point.
  const Paint paint =
      scene.radial
          ? radial_gradient_paint(scene.radial_geometry, scene.stops, scene.spread, scene.gradient_to_user)
          : linear_gradient_paint(scene.linear, scene.stops, scene.spread, scene.gradient_to_user);
  const GradientShader& shader = *paint.gradient;
  cairo_pattern_t* pattern = nullptr;
  if (scene.radial) {
    const RadialGradient& g = shader.radial();
    pattern =
        cairo_pattern_create_radial(g.focal.x, g.focal.y, g.focal_radius, g.center.x, g.center.y, g.radius);
  } else {
    pattern = cairo_pattern_create_linear(scene.linear.start.x, scene.linear.start.y, scene.linear.end.x,
                                          scene.linear.end.y);
  }
  for (const GradientStop& stop : shader.stops()) {
    cairo_pattern_add_color_stop_rgba(pattern, stop.offset, stop.color.r, stop.color.g, stop.color.b,
                                      stop.color.a);
  }
  cairo_pattern_set_extend(pattern, extend_of(scene.spread));
  const cairo_matrix_t user_to_gradient = cairo_matrix_of(*scene.gradient_to_user.inverse());
  cairo_pattern_set_matrix(pattern, &user_to_gradient);

  cairo_surface_t* surface = argb_surface_of(background);
  cairo_t* cr = cairo_create(surface);
  const cairo_matrix_t ctm = cairo_matrix_of(scene.user_to_device);
  cairo_set_matrix(cr, &ctm);
  cairo_set_source(cr, pattern);  // the pattern's user space is locked to this CTM
  cairo_identity_matrix(cr);
  cairo_rectangle(cr, 0, 0, kWidth, kHeight);
  cairo_fill(cr);
  cairo_destroy(cr);
  cairo_pattern_destroy(pattern);
  Image image = image_of_surface(surface);
  cairo_surface_destroy(surface);
  return image;
}

std::vector<GradientScene> scenes() {
  const std::vector<GradientStop> three{
      {0.0, {1.0, 0.2, 0.0, 1.0}}, {0.4, {0.1, 0.8, 0.3, 0.6}}, {1.0, {0.0, 0.1, 1.0, 1.0}}};
  const std::vector<GradientStop> translucent{{0.1, {0.9, 0.9, 0.1, 0.25}}, {0.7, {0.2, 0.0, 0.9, 1.0}}};
  const std::vector<GradientStop> hard{
      {0.0, {1, 0, 0, 1}}, {0.5, {1, 1, 0, 1}}, {0.5, {0, 0, 1, 0.7}}, {0.8, {0, 1, 1, 1}}};
  std::vector<GradientScene> list;
  GradientScene s;

  s = {};
  s.name = "linear pad, axis-aligned, integer end points";
  s.linear = {{10, 0}, {110, 0}};
  s.stops = three;
  list.push_back(s);

  s = {};
  s.name = "linear reflect, rotated and scaled gradientTransform";
  s.linear = {{0, 0}, {1, 0.25}};
  s.stops = translucent;
  s.spread = SpreadMethod::kReflect;
  s.gradient_to_user = Affine::translate(30, 20) * Affine::rotate(0.6) * Affine::scale(35, 20);
  list.push_back(s);

  s = {};
  s.name = "linear repeat, hard stop, scaled and translated fill";
  s.linear = {{5, 5}, {25, 15}};
  s.stops = hard;
  s.spread = SpreadMethod::kRepeat;
  s.user_to_device = Affine::translate(7.25, -3.5) * Affine::scale(1.5, 1.25);
  s.hard_stop = true;
  list.push_back(s);

  s = {};
  s.name = "linear pad, objectBoundingBox-like mapping with skew";
  s.linear = {{0, 0}, {1, 1}};
  s.stops = three;
  s.gradient_to_user = Affine::translate(20, 10) * Affine::skew_x(0.3) * Affine::scale(80, 60);
  list.push_back(s);

  s = {};
  s.name = "radial pad, centred focal point";
  s.radial = true;
  s.radial_geometry = {{60, 45}, 40, {60, 45}, 0};
  s.stops = three;
  list.push_back(s);

  s = {};
  s.name = "radial repeat, focal point inside";
  s.radial = true;
  s.radial_geometry = {{0.5, 0.5}, 0.3, {0.35, 0.6}, 0};
  s.stops = translucent;
  s.spread = SpreadMethod::kRepeat;
  s.gradient_to_user = Affine::scale(120, 90);
  s.hard_stop = true;  // the repeat wraps from the last colour to the first: a discontinuity
  list.push_back(s);

  s = {};
  s.name = "radial reflect, SVG 2 focal radius, skewed fill transform";
  s.radial = true;
  s.radial_geometry = {{50, 40}, 30, {55, 42}, 8};
  s.stops = three;
  s.spread = SpreadMethod::kReflect;
  s.user_to_device = Affine::skew_x(0.2) * Affine::scale(1.1);
  list.push_back(s);

  s = {};
  s.name = "radial pad, focal point outside (clamped as SVG 1.1)";
  s.radial = true;
  s.radial_geometry = {{60, 45}, 30, {110, 80}, 0};
  s.stops = three;
  list.push_back(s);

  s = {};
  s.name = "radial repeat, hard stop, rotated gradientTransform";
  s.radial = true;
  s.radial_geometry = {{0, 0}, 1, {0.2, 0.1}, 0};
  s.stops = hard;
  s.spread = SpreadMethod::kRepeat;
  s.gradient_to_user = Affine::translate(60, 45) * Affine::rotate(0.4) * Affine::scale(25, 15);
  s.hard_stop = true;
  list.push_back(s);
  return list;
}

// Distance in t from the pixel's parameter to the nearest discontinuity of the spread colour ramp: a
// hard stop, or, under repeat, the wrap from the last colour back to the first.
double distance_to_discontinuity(const GradientShader& shader, double t) {
  const std::vector<GradientStop>& stops = shader.stops();
  std::vector<double> jumps;
  for (std::size_t i = 1; i < stops.size(); ++i) {
    if (stops[i].offset == stops[i - 1].offset) jumps.push_back(stops[i].offset);
  }
  if (shader.spread() == SpreadMethod::kRepeat && !(stops.front() == GradientStop{0.0, stops.back().color})) {
    jumps.push_back(0.0);
    jumps.push_back(1.0);
  }
  double nearest = 1e9;
  if (shader.spread() == SpreadMethod::kPad) t = std::clamp(t, 0.0, 1.0);
  for (const double jump : jumps) {
    for (double period = std::floor(t) - 1; period <= std::floor(t) + 1; period += 1.0) {
      nearest = std::min(nearest, std::fabs(t - (period + jump)));
    }
  }
  return nearest;
}

void compare_scenes(const Image& background, const char* label, int max_away_from_jumps) {
  for (const GradientScene& scene : scenes()) {
    const Image ours = render_ours(scene, background);
    const Image cairo = render_cairo(scene, background);
    const PixelDiff diff = pixel_diff(ours, cairo);
    // Where the pixels that differ by more than one level lie, in t from a discontinuity.
    const Paint paint =
        scene.radial
            ? radial_gradient_paint(scene.radial_geometry, scene.stops, scene.spread, scene.gradient_to_user)
            : linear_gradient_paint(scene.linear, scene.stops, scene.spread, scene.gradient_to_user);
    const Affine device_to_gradient = *(scene.user_to_device * scene.gradient_to_user).inverse();
    double farthest = 0.0;
    int worst_away = 0;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const Rgba8 p = ours.at(x, y), q = cairo.at(x, y);
        const int d = std::max(std::max(std::abs(p.r - q.r), std::abs(p.g - q.g)),
                               std::max(std::abs(p.b - q.b), std::abs(p.a - q.a)));
        const double t = paint.gradient->parameter_at(device_to_gradient.apply(Point{x + 0.5, y + 0.5}));
        const double distance = distance_to_discontinuity(*paint.gradient, t);
        if (distance > kDiscontinuityBand) {
          worst_away = std::max(worst_away, d);
        } else if (d > 1) {
          farthest = std::max(farthest, distance);
        }
      }
    }
    std::printf(
        "gradient oracle [%s] %s: max |d| %d (%d away from jumps), mean |d| %.4f, pixels |d| > 1: %d "
        "(farthest %.2g in t from a jump)\n",
        label, scene.name.c_str(), diff.max_channel, worst_away, diff.mean_channel, diff.pixels_over_one,
        farthest);
    INFO(scene.name << " (" << label << "): max " << diff.max_channel << " away " << worst_away << " mean "
                    << diff.mean_channel << " over one " << diff.pixels_over_one);
    CHECK(worst_away <= max_away_from_jumps);
    CHECK(diff.pixels_over_one <= kWidth * kHeight / 100);
    CHECK(diff.mean_channel <= (scene.hard_stop ? 0.5 : 0.05));
  }
}

}  // namespace

TEST_CASE("gradients paint Cairo's bytes on a transparent canvas", "[oracle][paint][gradient]") {
  compare_scenes(Image(kWidth, kHeight), "transparent", 1);
}

TEST_CASE("gradients composite over a background as Cairo does", "[oracle][paint][gradient]") {
  Image background(kWidth, kHeight);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const auto a = static_cast<std::uint8_t>(96 + (x * 7 + y * 3) % 160);
      background.at(x, y) = {static_cast<std::uint8_t>(a * (x % 5) / 4), static_cast<std::uint8_t>(a / 2),
                             static_cast<std::uint8_t>(a * (y % 3) / 2), a};
    }
  }
  compare_scenes(background, "background", 2);
}
