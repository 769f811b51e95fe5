// The Ghostscript tiger through each library's drawing API: curvescan's Canvas::fill / Canvas::stroke
// against cairo_fill / cairo_stroke in the same process, on a 512 x 512 canvas (the 200 x 200 viewBox
// scaled by 2.56), white, at the same tolerance (0.1 px, both libraries' default). This is the tiger
// without the SVG reader: the paths are read from the file once, before timing, and each frame draws all
// 138 of them in document order (fill then stroke, as SVG paints them; stroke-miterlimit 4, butt caps
// and miter joins, SVG's initial values), so both sides do only geometry, rasterization and compositing.
// Cairo gets each path as a cairo_path_t made once and appended per frame (cairo_append_path), curvescan
// its Path. Reported as the ratio of medians (Cairo CPU time / curvescan CPU time: above 1 means curvescan
// is faster); CPU time because the machine may be shared.
//
// The tiger is read from ../shared/bench/tiger.svg beside the checkout, or from the path given as the
// first argument; it is never committed. Without it the benchmark says so and exits 0.
// Run: tiger_bench [tiger.svg] [--benchmark_...]
// Profile: tiger_bench --profile [tiger.svg] [--iterations=N] draws N frames on curvescan's side only.
// Look: tiger_bench --dump=DIR writes one frame of each side as DIR/tiger_curvescan.png, tiger_cairo.png.
#include <benchmark/benchmark.h>
#include <cairo.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/png_io.h"
#include "curvescan/raster/stroke.h"
#include "curvescan/svg/color.h"
#include "curvescan/svg/path_data.h"
#include "side_by_side.h"

namespace {

using namespace curvescan;

constexpr int kSize = 512;
constexpr double kScale = kSize / 200.0;  // the tiger's viewBox is 0 0 200 200

/// One <path> of the tiger: its outline and how it is painted (a paint is absent for "none").
struct TigerShape {
  Path path;
  std::optional<Color> fill;
  std::optional<Color> stroke;
  double stroke_width = 1.0;
};

/// A fill or stroke attribute as a colour; "none" (or no attribute when `initial` is none) gives nullopt.
std::optional<Color> paint_of(const pugi::xml_node& node, const char* name, std::optional<Color> initial) {
  const pugi::xml_attribute attribute = node.attribute(name);
  if (!attribute) return initial;
  const std::string_view text = attribute.value();
  if (text == "none") return std::nullopt;
  Result<Color> color = svg::parse_color(text);
  return color ? std::optional<Color>(*color) : initial;
}

/// The tiger's paths, or an empty list when the file is absent or not the tiger's shape (paths in
/// groups, with fill, stroke and stroke-width attributes; no transforms).
std::vector<TigerShape> read_tiger(const std::string& file) {
  pugi::xml_document document;
  if (!document.load_file(file.c_str())) return {};
  std::vector<TigerShape> shapes;
  for (const pugi::xpath_node& found : document.select_nodes("//*[local-name()='path']")) {
    const pugi::xml_node node = found.node();
    // The group's fill="none" is the tiger's only inherited paint; its paths set their own.
    const std::optional<Color> inherited_fill = paint_of(node.parent(), "fill", Color{0.0, 0.0, 0.0});
    PathBuilder builder;
    if (svg::append_path_data(node.attribute("d").value(), builder)) return {};
    Result<Path> path = builder.build();
    if (!path) return {};
    shapes.push_back({std::move(path).value(), paint_of(node, "fill", inherited_fill),
                      paint_of(node, "stroke", std::nullopt), node.attribute("stroke-width").as_double(1.0)});
  }
  return shapes;
}

void draw_curvescan(Canvas& canvas, const std::vector<TigerShape>& shapes) {
  canvas.clear(Paint::solid(Color{1.0, 1.0, 1.0}));
  const Affine transform = Affine::scale(kScale);
  for (const TigerShape& shape : shapes) {
    if (shape.fill) {
      const Status status = canvas.fill(shape.path, Paint::solid(*shape.fill), FillRule::kNonZero, transform);
      benchmark::DoNotOptimize(status.is_ok());
    }
    if (shape.stroke) {
      StrokeStyle style;
      style.width = shape.stroke_width;
      const Status status = canvas.stroke(shape.path, Paint::solid(*shape.stroke), style, transform);
      benchmark::DoNotOptimize(status.is_ok());
    }
  }
}

/// `path` as a Cairo path (the tiger has moves, lines, cubics, closes and a few arcs; a quadratic is its
/// exact cubic). nullptr for a verb Cairo has no form for.
cairo_path_t* cairo_path_of(cairo_t* cr, const Path& path) {
  cairo_new_path(cr);
  for (const PathElement& element : path) {
    const std::span<const Point> p = element.points;
    switch (element.verb) {
      case PathVerb::kMove:
        cairo_move_to(cr, p[0].x, p[0].y);
        break;
      case PathVerb::kLine:
        cairo_line_to(cr, p[1].x, p[1].y);
        break;
      case PathVerb::kQuad:
        cairo_curve_to(cr, p[0].x + 2.0 / 3.0 * (p[1].x - p[0].x), p[0].y + 2.0 / 3.0 * (p[1].y - p[0].y),
                       p[2].x + 2.0 / 3.0 * (p[1].x - p[2].x), p[2].y + 2.0 / 3.0 * (p[1].y - p[2].y), p[2].x,
                       p[2].y);
        break;
      case PathVerb::kCubic:
        cairo_curve_to(cr, p[1].x, p[1].y, p[2].x, p[2].y, p[3].x, p[3].y);
        break;
      case PathVerb::kConic: {
        // An SVG arc's piece (at most a quarter ellipse): the cubic whose handles go 4w / (3(1 + w)) of the
        // way to the control point, Cairo's own kind of arc (for w = cos 45° the classic 0.5523; off by
        // ~3e-4 of the radius, far below a pixel here).
        const double w = element.weights[1];
        const double k = 4.0 * w / (3.0 * (1.0 + w));
        cairo_curve_to(cr, p[0].x + k * (p[1].x - p[0].x), p[0].y + k * (p[1].y - p[0].y),
                       p[2].x + k * (p[1].x - p[2].x), p[2].y + k * (p[1].y - p[2].y), p[2].x, p[2].y);
        break;
      }
      case PathVerb::kClose:
        cairo_close_path(cr);
        break;
      default:
        return nullptr;
    }
  }
  cairo_path_t* copy = cairo_copy_path(cr);
  cairo_new_path(cr);
  return copy;
}

class CairoTiger {
 public:
  explicit CairoTiger(const std::vector<TigerShape>& shapes)
      : surface_(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kSize, kSize)), cr_(cairo_create(surface_)) {
    cairo_scale(cr_, kScale, kScale);
    cairo_set_miter_limit(cr_, 4.0);  // SVG's initial stroke-miterlimit (Cairo's is 10)
    for (const TigerShape& shape : shapes) paths_.push_back({cairo_path_of(cr_, shape.path), &shape});
  }
  ~CairoTiger() {
    for (const auto& [path, shape] : paths_) cairo_path_destroy(path);
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
  }
  CairoTiger(const CairoTiger&) = delete;
  CairoTiger& operator=(const CairoTiger&) = delete;

  void draw() {
    cairo_set_source_rgb(cr_, 1.0, 1.0, 1.0);
    cairo_paint(cr_);
    for (const auto& [path, shape] : paths_) {
      if (path == nullptr) continue;
      if (shape->fill) {
        cairo_append_path(cr_, path);
        set_source(*shape->fill);
        cairo_fill(cr_);
      }
      if (shape->stroke) {
        cairo_append_path(cr_, path);
        set_source(*shape->stroke);
        cairo_set_line_width(cr_, shape->stroke_width);
        cairo_stroke(cr_);
      }
    }
    cairo_surface_flush(surface_);
  }
  [[nodiscard]] const unsigned char* data() const { return cairo_image_surface_get_data(surface_); }
  [[nodiscard]] bool write_png(const std::string& file) const {
    return cairo_surface_write_to_png(surface_, file.c_str()) == CAIRO_STATUS_SUCCESS;
  }

 private:
  void set_source(const Color& c) { cairo_set_source_rgba(cr_, c.r, c.g, c.b, c.a); }

  cairo_surface_t* surface_;
  cairo_t* cr_;
  std::vector<std::pair<cairo_path_t*, const TigerShape*>> paths_;
};

/// Both sides must draw the same tiger: the largest channel difference of one frame each, and how many
/// pixels differ by more than 32 levels. Cairo's sampled coverage moves edge pixels by up to ~25 levels
/// against the exact one, and more where a spike thinner than its sample spacing ends (measured: 9 such
/// pixels, the largest 115 levels); a path drawn by one side only moves whole areas (before arcs were
/// passed to Cairo, 1 521 pixels).
std::pair<int, long> compare_frames(const std::vector<TigerShape>& shapes) {
  Canvas canvas = std::move(Canvas::create(kSize, kSize).value());
  draw_curvescan(canvas, shapes);
  CairoTiger tiger(shapes);
  tiger.draw();
  int worst = 0;
  long beyond = 0;
  for (int y = 0; y < kSize; ++y) {
    const Rgba8* ours = canvas.image().row(y);
    for (int x = 0; x < kSize; ++x) {
      std::uint32_t argb = 0;
      std::memcpy(&argb, tiger.data() + std::size_t{4} * (std::size_t(y) * kSize + x), 4);
      const int theirs[4] = {int(argb >> 16 & 255), int(argb >> 8 & 255), int(argb & 255), int(argb >> 24)};
      const int mine[4] = {ours[x].r, ours[x].g, ours[x].b, ours[x].a};
      int pixel = 0;
      for (int i = 0; i < 4; ++i) pixel = std::max(pixel, std::abs(mine[i] - theirs[i]));
      worst = std::max(worst, pixel);
      if (pixel > 32) ++beyond;
    }
  }
  return {worst, beyond};
}

}  // namespace

int main(int argc, char** argv) {
  std::string file = std::string(CURVESCAN_SOURCE_DIR) + "/../shared/bench/tiger.svg";
  bool profile = false;
  std::string dump;
  long iterations = 20;
  std::vector<char*> benchmark_args{argv[0]};
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--profile") {
      profile = true;
    } else if (arg.starts_with("--dump=")) {
      dump = std::string(arg.substr(7));
    } else if (arg.starts_with("--iterations=")) {
      iterations = std::atol(argv[i] + 13);
    } else if (arg.starts_with("--")) {
      benchmark_args.push_back(argv[i]);
    } else {
      file = arg;
    }
  }
  if (!std::filesystem::exists(file)) {
    std::printf("tiger_bench: skipped, %s is absent\n", file.c_str());
    return 0;
  }
  const std::vector<TigerShape> shapes = read_tiger(file);
  if (shapes.empty()) {
    std::fprintf(stderr, "tiger_bench: %s has no paths this benchmark can read\n", file.c_str());
    return 1;
  }
  if (!dump.empty()) {  // both sides' frames as PNG files, to look at what compare_frames counts
    Canvas canvas = std::move(Canvas::create(kSize, kSize).value());
    draw_curvescan(canvas, shapes);
    CairoTiger tiger(shapes);
    tiger.draw();
    const bool written = write_png(canvas.image(), dump + "/tiger_curvescan.png").is_ok() &&
                         tiger.write_png(dump + "/tiger_cairo.png");
    return written ? 0 : 1;
  }
  if (profile) {
    Canvas canvas = std::move(Canvas::create(kSize, kSize).value());
    for (long i = 0; i < iterations; ++i) draw_curvescan(canvas, shapes);
    std::printf("tiger: %zu paths, %ld frames\n", shapes.size(), iterations);
    return 0;
  }
  curvescan::bench::register_side_by_side(
      "tiger_512",
      [&shapes](benchmark::State& state) {
        Canvas canvas = std::move(Canvas::create(kSize, kSize).value());
        for (auto _ : state) {
          draw_curvescan(canvas, shapes);
          benchmark::DoNotOptimize(canvas.image().row(0));
          benchmark::ClobberMemory();
        }
      },
      [&shapes](benchmark::State& state) {
        CairoTiger tiger(shapes);
        for (auto _ : state) {
          tiger.draw();
          benchmark::DoNotOptimize(tiger.data());
          benchmark::ClobberMemory();
        }
      });
  int benchmark_argc = static_cast<int>(benchmark_args.size());
  const curvescan::bench::SideBySideMedians medians =
      curvescan::bench::run_side_by_side(benchmark_argc, benchmark_args.data());
  double ours = 0.0, cairo = 0.0;
  if (medians.find("tiger_512", ours, cairo)) {
    const auto [worst, beyond] = compare_frames(shapes);
    std::printf("\nscene          curvescan us       cairo us      ratio   max |d|   px > 32\n");
    std::printf("%-12s %14.1f %14.1f %9.2fx %9d %9ld\n", "tiger_512", ours, cairo, cairo / ours, worst,
                beyond);
  }
  benchmark::Shutdown();
  return 0;
}
