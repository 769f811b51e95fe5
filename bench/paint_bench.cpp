// Paint benchmark: the compositing side of drawing (clearing, opaque fills, gradients) against Cairo in the
// same process, on the same 512×512 canvas. Reported as ratios of medians over repetitions (Cairo time /
// curvescan time: above 1 means curvescan is faster), CPU time as in fill_bench.cpp.
//
// Scenes:
//  - clear_*: Canvas::clear to transparent (Cairo: CAIRO_OPERATOR_CLEAR + cairo_paint) and to opaque white
//    (Cairo: CAIRO_OPERATOR_SOURCE + cairo_paint), of a canvas that was drawn on (Cairo skips clearing a
//    surface it knows is clear, so its surface is marked dirty first);
//  - rect_opaque_*: an opaque colour over the whole canvas through Canvas::fill of a rectangle path
//    (Cairo: cairo_rectangle + cairo_fill, OVER);
//  - linear_* / radial_*: a gradient with a translucent middle stop (so part of the fill is a real blend and
//    part is opaque) filling the whole canvas as a rectangle, or a circle of radius 250 made of four cubics.
//  Each on a transparent and on a white canvas. Every frame of a gradient or rectangle scene first clears
//  the canvas to its background on both sides (otherwise the "transparent" canvas is no longer transparent
//  after one frame); the clear_* scenes give what that part costs.
// Both sides build their paint (gradient) once, as an application keeps its paint, and rebuild the path
// every frame.
//
// Run: paint_bench [--benchmark_filter=...]; the ratio table is printed after Google Benchmark's output.
// Profile: paint_bench --profile=SCENE [--iterations=N] runs only curvescan's side of one scene N times
// (default 20), without Google Benchmark, for valgrind --tool=callgrind.
#include <benchmark/benchmark.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/gradient.h"
#include "curvescan/raster/path_builder.h"

#include "side_by_side.h"

namespace {

using curvescan::Point;

constexpr int kSize = 512;
constexpr double kKappa = 0.5522847498307936;  // quarter circle as one cubic: 4/3·(√2 − 1)
constexpr Point kCentre{256.0, 256.0};
constexpr double kRadius = 250.0;

enum class Operation { kClear, kRectOpaque, kLinear, kRadial };
enum class Shape { kRect, kCircle };

struct Scene {
  std::string name;
  Operation operation = Operation::kClear;
  Shape shape = Shape::kRect;
  bool white = false;  // the background (clear colour): white or transparent
};

// Straight-alpha stops: opaque red, translucent green in the middle, opaque blue.
const std::vector<curvescan::GradientStop> kStops{
    {0.0, {0.9, 0.1, 0.1, 1.0}}, {0.5, {0.1, 0.8, 0.2, 0.5}}, {1.0, {0.1, 0.2, 0.9, 1.0}}};
constexpr curvescan::LinearGradient kLinear{{40.0, 60.0}, {470.0, 450.0}};
constexpr curvescan::RadialGradient kRadial{kCentre, kRadius, {200.0, 220.0}, 0.0};
constexpr double kOpaque[3] = {0.2, 0.4, 0.6};

curvescan::Path scene_path(Shape shape) {
  curvescan::PathBuilder builder;
  if (shape == Shape::kRect) {
    builder.move_to({0, 0}).line_to({kSize, 0}).line_to({kSize, kSize}).line_to({0, kSize}).close();
    return *builder.build();
  }
  const double r = kRadius, t = kKappa * kRadius;
  const Point c = kCentre;
  builder.move_to({c.x + r, c.y});
  builder.cubic_to({c.x + r, c.y + t}, {c.x + t, c.y + r}, {c.x, c.y + r});
  builder.cubic_to({c.x - t, c.y + r}, {c.x - r, c.y + t}, {c.x - r, c.y});
  builder.cubic_to({c.x - r, c.y - t}, {c.x - t, c.y - r}, {c.x, c.y - r});
  builder.cubic_to({c.x + t, c.y - r}, {c.x + r, c.y - t}, {c.x + r, c.y});
  builder.close();
  return *builder.build();  // finite input: build() cannot fail
}

void cairo_scene_path(cairo_t* cr, Shape shape) {
  cairo_new_path(cr);
  if (shape == Shape::kRect) {
    cairo_rectangle(cr, 0, 0, kSize, kSize);
    return;
  }
  const double r = kRadius, t = kKappa * kRadius;
  const Point c = kCentre;
  cairo_move_to(cr, c.x + r, c.y);
  cairo_curve_to(cr, c.x + r, c.y + t, c.x + t, c.y + r, c.x, c.y + r);
  cairo_curve_to(cr, c.x - t, c.y + r, c.x - r, c.y + t, c.x - r, c.y);
  cairo_curve_to(cr, c.x - r, c.y - t, c.x - t, c.y - r, c.x, c.y - r);
  cairo_curve_to(cr, c.x + t, c.y - r, c.x + r, c.y - t, c.x + r, c.y);
  cairo_close_path(cr);
}

class CurvescanRenderer {
 public:
  explicit CurvescanRenderer(const Scene& scene)
      : scene_(scene), canvas_(curvescan::Image(kSize, kSize)), background_(curvescan::Paint::none()) {
    if (scene.white) background_ = curvescan::Paint::solid({1, 1, 1, 1});
    switch (scene.operation) {
      case Operation::kClear:
        break;
      case Operation::kRectOpaque:
        paint_ = curvescan::Paint::solid({kOpaque[0], kOpaque[1], kOpaque[2], 1.0});
        break;
      case Operation::kLinear:
        paint_ = curvescan::linear_gradient_paint(kLinear, kStops, curvescan::SpreadMethod::kPad);
        break;
      case Operation::kRadial:
        paint_ = curvescan::radial_gradient_paint(kRadial, kStops, curvescan::SpreadMethod::kPad);
        break;
    }
  }

  void draw() {
    canvas_.clear(background_);
    if (scene_.operation == Operation::kClear) return;
    const curvescan::Path path = scene_path(scene_.shape);
    if (!canvas_.fill(path, paint_, curvescan::FillRule::kNonZero)) std::abort();
  }

  const void* data() const { return canvas_.image().pixels().data(); }
  std::array<int, 4> rgba(int x, int y) const {
    const curvescan::Rgba8 p = canvas_.image().at(x, y);
    return {p.r, p.g, p.b, p.a};
  }

 private:
  const Scene& scene_;
  curvescan::Canvas canvas_;
  curvescan::Paint background_;
  curvescan::Paint paint_;
};

class CairoRenderer {
 public:
  explicit CairoRenderer(const Scene& scene) : scene_(scene) {
    surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kSize, kSize);
    cr_ = cairo_create(surface_);
    cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_WINDING);
    switch (scene.operation) {
      case Operation::kClear:
        break;
      case Operation::kRectOpaque:
        pattern_ = cairo_pattern_create_rgb(kOpaque[0], kOpaque[1], kOpaque[2]);
        break;
      case Operation::kLinear:
        pattern_ =
            cairo_pattern_create_linear(kLinear.start.x, kLinear.start.y, kLinear.end.x, kLinear.end.y);
        break;
      case Operation::kRadial:
        pattern_ = cairo_pattern_create_radial(kRadial.focal.x, kRadial.focal.y, kRadial.focal_radius,
                                               kRadial.center.x, kRadial.center.y, kRadial.radius);
        break;
    }
    if (scene.operation == Operation::kLinear || scene.operation == Operation::kRadial) {
      for (const curvescan::GradientStop& s : kStops)
        cairo_pattern_add_color_stop_rgba(pattern_, s.offset, s.color.r, s.color.g, s.color.b, s.color.a);
      cairo_pattern_set_extend(pattern_, CAIRO_EXTEND_PAD);
    }
  }
  ~CairoRenderer() {
    if (pattern_ != nullptr) cairo_pattern_destroy(pattern_);
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
  }
  CairoRenderer(const CairoRenderer&) = delete;
  CairoRenderer& operator=(const CairoRenderer&) = delete;

  void draw() {
    // Cairo skips a clear of a surface it knows to be clear; a clear scene measures clearing a canvas that
    // was drawn on, so the surface is marked as changed (the gradient and rectangle scenes draw on it).
    if (scene_.operation == Operation::kClear) cairo_surface_mark_dirty(surface_);
    if (scene_.white) {
      cairo_set_operator(cr_, CAIRO_OPERATOR_SOURCE);
      cairo_set_source_rgb(cr_, 1, 1, 1);
    } else {
      cairo_set_operator(cr_, CAIRO_OPERATOR_CLEAR);
    }
    cairo_paint(cr_);
    if (scene_.operation != Operation::kClear) {
      cairo_set_operator(cr_, CAIRO_OPERATOR_OVER);
      cairo_set_source(cr_, pattern_);
      cairo_scene_path(cr_, scene_.shape);
      cairo_fill(cr_);
    }
    cairo_surface_flush(surface_);
  }

  const void* data() { return cairo_image_surface_get_data(surface_); }
  /// Pixel (x, y) as R, G, B, A (Cairo stores native-endian ARGB words).
  std::array<int, 4> rgba(int x, int y) {
    std::uint32_t argb = 0;
    const unsigned char* row = cairo_image_surface_get_data(surface_) +
                               static_cast<std::size_t>(y) * cairo_image_surface_get_stride(surface_);
    std::memcpy(&argb, row + 4 * static_cast<std::size_t>(x), 4);
    return {static_cast<int>((argb >> 16) & 255), static_cast<int>((argb >> 8) & 255),
            static_cast<int>(argb & 255), static_cast<int>(argb >> 24)};
  }

 private:
  const Scene& scene_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
  cairo_pattern_t* pattern_ = nullptr;
};

/// Both sides must do the same work: the largest channel difference of one frame each (Cairo's sampled
/// coverage on the circle's edge, and Cairo's 16.16 gradient geometry, differ from ours by a few levels).
int max_channel_difference(const Scene& scene) {
  CurvescanRenderer ours(scene);
  CairoRenderer theirs(scene);
  ours.draw();
  theirs.draw();
  int worst = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const std::array<int, 4> a = ours.rgba(x, y);
      const std::array<int, 4> b = theirs.rgba(x, y);
      for (int i = 0; i < 4; ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    }
  }
  return worst;
}

std::vector<Scene> all_scenes() {
  std::vector<Scene> scenes;
  for (const bool white : {false, true}) {
    const std::string background = white ? "white" : "transparent";
    scenes.push_back({"clear_" + background, Operation::kClear, Shape::kRect, white});
    scenes.push_back({"rect_opaque_on_" + background, Operation::kRectOpaque, Shape::kRect, white});
    for (const Operation operation : {Operation::kLinear, Operation::kRadial}) {
      for (const Shape shape : {Shape::kRect, Shape::kCircle}) {
        scenes.push_back({std::string(operation == Operation::kLinear ? "linear_" : "radial_") +
                              (shape == Shape::kRect ? "rect" : "circle") + "_on_" + background,
                          operation, shape, white});
      }
    }
  }
  return scenes;
}


}  // namespace

int main(int argc, char** argv) {
  std::string profile_scene;
  long iterations = 20;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.starts_with("--profile=")) profile_scene = arg.substr(10);
    if (arg.starts_with("--iterations=")) iterations = std::atol(arg.c_str() + 13);
  }
  const std::vector<Scene> scenes = all_scenes();
  if (!profile_scene.empty()) {
    for (const Scene& scene : scenes) {
      if (scene.name != profile_scene) continue;
      CurvescanRenderer renderer(scene);
      for (long i = 0; i < iterations; ++i) renderer.draw();
      std::printf("%s: %ld iterations\n", scene.name.c_str(), iterations);
      return 0;
    }
    std::fprintf(stderr, "paint_bench: no scene named '%s'\n", profile_scene.c_str());
    return 2;
  }

  for (const Scene& scene : scenes) {
    curvescan::bench::register_side_by_side(
        scene.name, [&scene](benchmark::State& st) { curvescan::bench::time_frames<CurvescanRenderer>(st, scene); },
        [&scene](benchmark::State& st) { curvescan::bench::time_frames<CairoRenderer>(st, scene); });
  }
  const curvescan::bench::SideBySideMedians reporter = curvescan::bench::run_side_by_side(argc, argv);

  std::printf("\n%-32s %14s %14s %10s %12s\n", "scene", "curvescan us", "cairo us", "ratio", "max |d| px");
  for (const Scene& scene : scenes) {
    double ours = 0.0, cairo = 0.0;
    if (!reporter.find(scene.name, ours, cairo)) continue;
    std::printf("%-32s %14.1f %14.1f %9.2fx %12d\n", scene.name.c_str(), ours, cairo,
                cairo / ours, max_channel_difference(scene));
  }
  benchmark::Shutdown();
  return 0;
}
