// Polygon fill benchmark: curvescan against Cairo in the same process, on the same canvas and scenes,
// both including the compositing of a solid, translucent colour. Reported as ratios of medians over
// repetitions (Cairo time / curvescan time: above 1 means curvescan is faster).
//
// curvescan composites the polygon scenes' spans through the library's own solid-colour compositor
// (SolidSpanCompositor, what Canvas::fill uses for a solid paint) into an RGBA8 image; Cairo fills an ARGB32
// image surface with CAIRO_OPERATOR_OVER and CAIRO_ANTIALIAS_DEFAULT. Both sides rebuild the path each
// iteration (curvescan: add_polyline per contour; Cairo: move_to/line_to), so path construction is measured
// on both.
//
// Ratios use CPU time: the machine is shared, and wall time of a single-threaded fill measures the
// neighbours as much as the fill.
//
// Two kinds of scene:
//  - polygon scenes drive the Rasterizer directly (add_polyline per contour) into the library's compositor;
//  - pipeline scenes ("canvas_*") go through Canvas::fill with a real Path (PathBuilder, cubic circles):
//    transform, flatten, edges, rasterizer and the library's own compositor, against Cairo's cairo_fill of
//    the same cubics. These measure what a user of the library pays.
// Run: fill_bench [--canvas=transparent] [--benchmark_filter=...]; the ratio table is printed after Google
// Benchmark's own output.
// Profile: fill_bench --profile=SCENE [--iterations=N] runs only curvescan's side of one scene N times
// (default 20), without Google Benchmark, for valgrind --tool=callgrind (deterministic instruction counts).
// --profile_cairo with it runs Cairo's side instead.
// Output: fill_bench --output_hashes [--canvas=transparent] prints a hash of curvescan's canvas of every
// scene after three frames (no timing), to compare a change's output before and after.
#include <benchmark/benchmark.h>
#include <cairo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"
#include "paint/solid_span_compositor.h"
#include "side_by_side.h"

namespace {

using curvescan::Point;
using Contour = std::vector<Point>;
using Shape = std::vector<Contour>;

// ---- scenes ---------------------------------------------------------------------------------------------

Contour star(Point c, double r_outer, double r_inner, int vertices) {
  Contour out;
  for (int i = 0; i < vertices; ++i) {
    const double a = std::numbers::pi * 2.0 * i / vertices;
    const double r = i % 2 == 0 ? r_outer : r_inner;
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return out;
}

Contour regular(Point c, double r, int vertices) {
  Contour out;
  for (int i = 0; i < vertices; ++i) {
    const double a = std::numbers::pi * 2.0 * i / vertices + 0.1;
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return out;
}

Shape many_small_shapes(int size, int count) {
  std::mt19937 rng(31337);
  std::uniform_real_distribution<double> pos(0.0, size), radius(2.0, 10.0);
  std::uniform_int_distribution<int> sides(3, 12);
  Shape shape;
  for (int i = 0; i < count; ++i) shape.push_back(regular({pos(rng), pos(rng)}, radius(rng), sides(rng)));
  return shape;
}

/// A closed polyline through `count` random points of the canvas: Θ(count²) crossings (issue 8's hang
/// class before the band sweep).
Shape random_polyline(int size, int count) {
  std::mt19937 rng(8080);
  std::uniform_real_distribution<double> pos(0.0, size);
  Contour c;
  for (int i = 0; i < count; ++i) {
    const double x = pos(rng);
    c.push_back({x, pos(rng)});
  }
  return Shape{c};
}

/// A circle drawn as four cubics (the usual kappa = 4/3·(√2 - 1) quarter arcs), as Blend2D's and Cairo's
/// benchmarks draw it.
struct Circle {
  Point c;
  double r = 0.0;
};
/// Circles filled in groups: every group is one path and one fill call.
using CircleGroups = std::vector<std::vector<Circle>>;

constexpr double kKappa = 0.5522847498307936;

curvescan::Path circle_path(const std::vector<Circle>& circles) {
  curvescan::PathBuilder builder;
  for (const Circle& k : circles) {
    const double r = k.r;
    const double t = kKappa * r;
    const Point c = k.c;
    builder.move_to({c.x + r, c.y});
    builder.cubic_to({c.x + r, c.y + t}, {c.x + t, c.y + r}, {c.x, c.y + r});
    builder.cubic_to({c.x - t, c.y + r}, {c.x - r, c.y + t}, {c.x - r, c.y});
    builder.cubic_to({c.x - r, c.y - t}, {c.x - t, c.y - r}, {c.x, c.y - r});
    builder.cubic_to({c.x + t, c.y - r}, {c.x + r, c.y - t}, {c.x + r, c.y});
    builder.close();
  }
  return *builder.build();  // finite input: build() cannot fail
}

void cairo_circles(cairo_t* cr, const std::vector<Circle>& circles) {
  for (const Circle& k : circles) {
    const double r = k.r;
    const double t = kKappa * r;
    const Point c = k.c;
    cairo_move_to(cr, c.x + r, c.y);
    cairo_curve_to(cr, c.x + r, c.y + t, c.x + t, c.y + r, c.x, c.y + r);
    cairo_curve_to(cr, c.x - t, c.y + r, c.x - r, c.y + t, c.x - r, c.y);
    cairo_curve_to(cr, c.x - r, c.y - t, c.x - t, c.y - r, c.x, c.y - r);
    cairo_curve_to(cr, c.x + t, c.y - r, c.x + r, c.y - t, c.x + r, c.y);
    cairo_close_path(cr);
  }
}

CircleGroups small_circles(int size, int count, bool one_fill_each) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> pos(0.0, size), radius(2.0, 10.0);
  CircleGroups groups(one_fill_each ? count : 1);
  for (int i = 0; i < count; ++i) {
    const Circle k{{pos(rng), pos(rng)}, radius(rng)};
    groups[one_fill_each ? static_cast<std::size_t>(i) : 0].push_back(k);
  }
  return groups;
}

// ---- curvescan side ---------------------------------------------------------------------------------------

/// --canvas=transparent: every scene starts from a transparent canvas instead of a white one (both sides;
/// the frames then blend onto what the earlier frames left, as on white).
bool g_transparent = false;

// Premultiplied translucent red-ish: alpha 0.8, so every pixel is a real blend on both sides.
constexpr std::uint8_t kColour[4] = {163, 20, 41, 204};

/// One scene: either a polygon (`shape`, drawn by the rasterizer directly) or, when `pipeline` is set,
/// groups of cubic circles drawn through Canvas::fill, one fill per group.
struct Case {
  std::string name;
  int size = 0;
  Shape shape;
  CircleGroups circles;
  bool pipeline = false;
  bool even_odd = false;  ///< polygon scenes: filled even-odd instead of nonzero (both sides)
};

/// State of curvescan's side of a case, kept across iterations (as an application keeps its canvas).
class CurvescanRenderer {
 public:
  explicit CurvescanRenderer(const Case& c)
      : case_(c),
        image_(c.pipeline ? 1 : c.size, c.pipeline ? 1 : c.size),
        sink_(image_, curvescan::Rgba8{kColour[0], kColour[1], kColour[2], kColour[3]}),
        canvas_(curvescan::Image(c.pipeline ? c.size : 1, c.pipeline ? c.size : 1)),
        paint_(curvescan::Paint::solid(
            {kColour[0] / 204.0, kColour[1] / 204.0, kColour[2] / 204.0, kColour[3] / 255.0})) {
    const std::uint8_t background = g_transparent ? 0 : 255;
    for (curvescan::Rgba8& p : image_.pixels()) p = {background, background, background, background};
    canvas_.clear(curvescan::Paint::solid(g_transparent ? curvescan::Color{0.0, 0.0, 0.0, 0.0}
                                                        : curvescan::Color{1.0, 1.0, 1.0, 1.0}));
  }

  /// One frame: the path is rebuilt every time, as Cairo's side rebuilds it.
  void draw() {
    if (case_.pipeline) {
      for (const std::vector<Circle>& group : case_.circles) {
        const curvescan::Path path = circle_path(group);
        if (!canvas_.fill(path, paint_, curvescan::FillRule::kNonZero)) std::abort();
      }
      return;
    }
    rasterizer_.reset({0, 0, case_.size, case_.size});
    // Each contour through the rasterizer's polyline door (as Canvas::fill hands it a path's contours),
    // closed by its last edge.
    for (const Contour& c : case_.shape) {
      rasterizer_.add_polyline(c);
      rasterizer_.add_line(c.back(), c.front());
    }
    rasterizer_.rasterize(case_.even_odd ? curvescan::FillRule::kEvenOdd : curvescan::FillRule::kNonZero,
                          curvescan::Antialias::kExact, sink_);
  }

  const void* data() const {
    return case_.pipeline ? canvas_.image().pixels().data() : image_.pixels().data();
  }
  /// Pixel (x, y) as R, G, B, A.
  std::array<int, 4> rgba(int x, int y) const {
    const curvescan::Rgba8 p = case_.pipeline ? canvas_.image().at(x, y) : image_.at(x, y);
    return {p.r, p.g, p.b, p.a};
  }

 private:
  const Case& case_;
  curvescan::Image image_;  ///< the polygon scenes' canvas
  curvescan::detail::SolidSpanCompositor sink_;
  curvescan::Rasterizer rasterizer_;
  curvescan::Canvas canvas_;
  curvescan::Paint paint_;
};

/// Cairo's side: an ARGB32 surface painted white, the same translucent colour, the same fill rule.
class CairoRenderer {
 public:
  explicit CairoRenderer(const Case& c) : case_(c) {
    surface_ = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, c.size, c.size);
    cr_ = cairo_create(surface_);
    if (!g_transparent) {  // a new image surface is transparent (all channels 0)
      cairo_set_source_rgb(cr_, 1, 1, 1);
      cairo_paint(cr_);
    }
    cairo_set_source_rgba(cr_, kColour[0] / 204.0, kColour[1] / 204.0, kColour[2] / 204.0,
                          kColour[3] / 255.0);
    cairo_set_fill_rule(cr_, c.even_odd ? CAIRO_FILL_RULE_EVEN_ODD : CAIRO_FILL_RULE_WINDING);
    cairo_set_antialias(cr_, CAIRO_ANTIALIAS_DEFAULT);
  }
  ~CairoRenderer() {
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
  }
  CairoRenderer(const CairoRenderer&) = delete;
  CairoRenderer& operator=(const CairoRenderer&) = delete;

  void draw() {
    if (case_.pipeline) {
      for (const std::vector<Circle>& group : case_.circles) {
        cairo_new_path(cr_);
        cairo_circles(cr_, group);
        cairo_fill(cr_);
      }
    } else {
      cairo_new_path(cr_);
      for (const Contour& c : case_.shape) {
        cairo_move_to(cr_, c[0].x, c[0].y);
        for (std::size_t i = 1; i < c.size(); ++i) cairo_line_to(cr_, c[i].x, c[i].y);
        cairo_close_path(cr_);
      }
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
  const Case& case_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

/// Both sides must do the same work: renders the case once each way onto the canvas and returns the largest
/// channel difference (Cairo's coverage differs from the exact one by up to ~17/255 on edges).
int max_channel_difference(const Case& c) {
  CurvescanRenderer ours(c);
  CairoRenderer theirs(c);
  ours.draw();
  theirs.draw();
  int worst = 0;
  for (int y = 0; y < c.size; ++y) {
    for (int x = 0; x < c.size; ++x) {
      const std::array<int, 4> a = ours.rgba(x, y);
      const std::array<int, 4> b = theirs.rgba(x, y);
      for (int i = 0; i < 4; ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
    }
  }
  return worst;
}

/// Every scene, or only the one named `only` when it is not empty (profiling builds nothing else, so the
/// instruction counts are the fill's).
std::vector<Case> all_cases(const std::string& only) {
  std::vector<Case> cases;
  const auto add = [&](const std::string& name, int size, const std::function<Shape()>& polygon,
                       const std::function<CircleGroups()>& circles) {
    if (!only.empty() && name != only) return;
    cases.push_back({name, size, polygon ? polygon() : Shape{}, circles ? circles() : CircleGroups{},
                     static_cast<bool>(circles)});
  };
  const Point mid{256.0, 256.0};
  add(
      "star_1000v_r250_100", 512, [&] { return Shape{star(mid, 250, 100, 1000)}; }, nullptr);
  add(
      "regular_1000gon_r250", 512, [&] { return Shape{regular(mid, 250, 1000)}; }, nullptr);
  add(
      "star_10v", 512, [&] { return Shape{star(mid, 250, 100, 10)}; }, nullptr);
  add(
      "many_small_shapes_1000", 512, [] { return many_small_shapes(512, 1000); }, nullptr);
  for (const int size : {256, 512, 1024, 2048, 4096}) {
    const double s = size / 512.0;
    add(
        "canvas_" + std::to_string(size) + "_star_1000v", size,
        [&] {
          return Shape{star({256.0 * s, 256.0 * s}, 250 * s, 100 * s, 1000)};
        },
        nullptr);
  }
  for (const int edges : {10, 100, 1000, 10000, 100000, 1000000}) {
    add(
        "edges_" + std::to_string(edges) + "_regular", 512, [&] { return Shape{regular(mid, 250, edges)}; },
        nullptr);
  }
  for (const int count : {1000, 10000, 100000}) {
    add(
        "random_polyline_" + std::to_string(count), 512, [count] { return random_polyline(512, count); },
        nullptr);
  }
  add(
      "random_polyline_1000_evenodd", 512, [] { return random_polyline(512, 1000); }, nullptr);
  if (!cases.empty() && cases.back().name == "random_polyline_1000_evenodd") cases.back().even_odd = true;
  // Through Canvas::fill: one circle of four cubics (Blend2D's scene), and 1000 small circles drawn as
  // 1000 fills (per-fill overhead) and as one fill of 1000 contours.
  add("canvas_fill_circle_4cubics", 512, nullptr, [&] { return CircleGroups{{{mid, 250.0}}}; });
  add("canvas_fill_1000_circles_1000_fills", 512, nullptr, [] { return small_circles(512, 1000, true); });
  add("canvas_fill_1000_circles_one_fill", 512, nullptr, [] { return small_circles(512, 1000, false); });
  return cases;
}

/// FNV-1a over `bytes` bytes.
std::uint64_t fnv1a(const void* data, std::size_t bytes) {
  std::uint64_t h = 14695981039346656037ull;
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}

/// --output_hashes: curvescan's canvas of every scene after three frames (so the later frames blend onto
/// what the first left, as in the timed loop), hashed, to show a change leaves the output byte for byte.
/// The canvas is white or, with --canvas=transparent, transparent, as in the timed runs.
void print_output_hashes(const std::vector<Case>& cases) {
  std::printf("canvas: %s\n", g_transparent ? "transparent" : "white");
  for (const Case& c : cases) {
    CurvescanRenderer renderer(c);
    for (int i = 0; i < 3; ++i) renderer.draw();
    const std::size_t bytes = static_cast<std::size_t>(c.size) * c.size * 4;
    std::printf("%-36s %016llx\n", c.name.c_str(),
                static_cast<unsigned long long>(fnv1a(renderer.data(), bytes)));
  }
}

/// --profile=SCENE [--iterations=N]: curvescan's side only, for callgrind. Returns the exit code.
/// Renderer = CairoRenderer: Cairo's side instead (--profile_cairo: where Cairo's time goes, on either
/// canvas).
template <class Renderer>
int profile(const std::vector<Case>& cases, const std::string& scene, long iterations) {
  for (const Case& c : cases) {
    if (c.name != scene) continue;
    Renderer renderer(c);
    for (long i = 0; i < iterations; ++i) renderer.draw();
    std::printf("%s: %ld iterations\n", scene.c_str(), iterations);
    return 0;
  }
  std::fprintf(stderr, "fill_bench: no scene named '%s'\n", scene.c_str());
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string profile_scene;
  long iterations = 20;
  bool hashes = false;
  bool profile_cairo = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.starts_with("--profile=")) profile_scene = arg.substr(10);
    if (arg.starts_with("--iterations=")) iterations = std::atol(arg.c_str() + 13);
    if (arg == "--canvas=transparent") g_transparent = true;
    if (arg == "--output_hashes") hashes = true;
    if (arg == "--profile_cairo") profile_cairo = true;
  }
  if (hashes) {
    print_output_hashes(all_cases(""));
    return 0;
  }
  if (!profile_scene.empty()) {
    const std::vector<Case> cases = all_cases(profile_scene);
    return profile_cairo ? profile<CairoRenderer>(cases, profile_scene, iterations)
                         : profile<CurvescanRenderer>(cases, profile_scene, iterations);
  }
  const std::vector<Case> cases = all_cases("");

  for (const Case& c : cases) {
    curvescan::bench::register_side_by_side(
        c.name, [&c](benchmark::State& st) { curvescan::bench::time_frames<CurvescanRenderer>(st, c); },
        [&c](benchmark::State& st) { curvescan::bench::time_frames<CairoRenderer>(st, c); });
  }
  std::vector<char*> args;  // Google Benchmark's flags only
  for (int i = 0; i < argc; ++i) {
    if (std::string(argv[i]) != "--canvas=transparent") args.push_back(argv[i]);
  }
  std::printf("canvas: %s\n", g_transparent ? "transparent" : "white");
  const curvescan::bench::SideBySideMedians reporter =
      curvescan::bench::run_side_by_side(static_cast<int>(args.size()), args.data());

  std::printf("\n%-36s %14s %14s %10s %12s\n", "scene", "curvescan us", "cairo us", "ratio", "max |d| px");
  for (const Case& c : cases) {
    double ours = 0.0, cairo = 0.0;
    if (!reporter.find(c.name, ours, cairo)) continue;
    std::printf("%-36s %14.1f %14.1f %9.2fx %12d\n", c.name.c_str(), ours, cairo, cairo / ours,
                max_channel_difference(c));
  }
  benchmark::Shutdown();
  return 0;
}
