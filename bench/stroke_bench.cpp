// Stroke benchmark: curvescan's Canvas::stroke against cairo_stroke in the same process, on the same
// 512 x 512 canvas and paths, 1 px and 20 px, solid and dashed, polylines and curves. Both include path
// construction, stroking, rasterization and source-over compositing of a translucent solid colour, at the
// same tolerance (0.1 px, both libraries' default). Reported as ratios of medians over repetitions (Cairo
// CPU time / curvescan CPU time: above 1 means curvescan is faster); CPU time because the machine is
// shared. Run: stroke_bench [--benchmark_filter=...]; the ratio table follows Google Benchmark's output.
// Profile: stroke_bench --profile=SCENE [--iterations=N] strokes one scene N times on curvescan only.
#include <benchmark/benchmark.h>
#include <cairo.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/rasterizer.h"
#include "curvescan/raster/stroke.h"
#include "side_by_side.h"

namespace {

using namespace curvescan;

constexpr int kSize = 512;

struct Segment {
  bool cubic;
  Point c1, c2, end;
};

struct Scene {
  std::string name;
  Point start;
  std::vector<Segment> segments;
  double width;
  bool dashed;
};

std::vector<Segment> random_polyline(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> in(16.0, kSize - 16.0);
  std::vector<Segment> out;
  for (int i = 0; i < count; ++i) out.push_back({false, {}, {}, {in(rng), in(rng)}});
  return out;
}

std::vector<Segment> random_curves(std::mt19937& rng, int count) {
  std::uniform_real_distribution<double> in(16.0, kSize - 16.0);
  std::vector<Segment> out;
  for (int i = 0; i < count; ++i)
    out.push_back({true, {in(rng), in(rng)}, {in(rng), in(rng)}, {in(rng), in(rng)}});
  return out;
}

Path build_path(const Scene& s) {
  PathBuilder b;
  b.move_to(s.start);
  for (const Segment& g : s.segments) {
    if (g.cubic) {
      b.cubic_to(g.c1, g.c2, g.end);
    } else {
      b.line_to(g.end);
    }
  }
  return *b.build();
}

StrokeStyle scene_style(const Scene& scene) {
  StrokeStyle style;
  style.width = scene.width;
  style.join = LineJoin::kRound;
  style.cap = LineCap::kRound;
  if (scene.dashed) style.dash_array = {12.0, 6.0};
  return style;
}

void bench_curvescan(benchmark::State& state, const Scene& scene) {
  Canvas canvas = std::move(Canvas::create(kSize, kSize).value());
  const StrokeStyle style = scene_style(scene);
  const Paint paint = Paint::solid({0.1, 0.3, 0.8, 0.7});
  for (auto _ : state) {
    const Path path = build_path(scene);
    const Status status = canvas.stroke(path, paint, style);
    benchmark::DoNotOptimize(status.is_ok());
  }
}

void bench_cairo(benchmark::State& state, const Scene& scene) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, kSize, kSize);
  cairo_t* cr = cairo_create(surface);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  cairo_set_source_rgba(cr, 0.1, 0.3, 0.8, 0.7);
  cairo_set_line_width(cr, scene.width);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  const double dashes[] = {12.0, 6.0};
  cairo_set_dash(cr, dashes, scene.dashed ? 2 : 0, 0.0);
  for (auto _ : state) {
    cairo_move_to(cr, scene.start.x, scene.start.y);
    for (const Segment& g : scene.segments) {
      if (g.cubic) {
        cairo_curve_to(cr, g.c1.x, g.c1.y, g.c2.x, g.c2.y, g.end.x, g.end.y);
      } else {
        cairo_line_to(cr, g.end.x, g.end.y);
      }
    }
    cairo_stroke(cr);
    cairo_surface_flush(surface);
    benchmark::DoNotOptimize(cairo_image_surface_get_data(surface));
  }
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
}

class NullSink final : public SpanSink {
 public:
  void blend(std::span<const Span> spans) override { covered += spans.size(); }
  std::size_t covered = 0;
};

/// What the stroke of each scene hands the rasterizer and what resolving it costs (machine-independent:
/// the outline's contours and edges, RasterizerStats of filling it nonzero at the bench's tolerance).
void print_outline_stats(const std::vector<Scene>& scenes) {
  std::printf("\n%-28s %9s %9s %12s %12s %9s %9s %7s %9s\n", "scene", "contours", "edges", "crossings",
              "visited", "s.bands", "s.rows", "swept", "sweep.x");
  Rasterizer rasterizer;
  for (const Scene& s : scenes) {
    const Result<Path> outline = stroke_path(build_path(s), scene_style(s), 0.1);
    if (!outline) continue;
    rasterizer.reset({0, 0, kSize, kSize});
    std::size_t contours = 0, edges = 0;
    for (const PathElement& e : *outline) {
      if (e.verb == PathVerb::kMove) {
        ++contours;
      } else if (e.verb == PathVerb::kLine || e.verb == PathVerb::kClose) {
        rasterizer.add_line(e.start, e.end);
        ++edges;
      }
    }
    NullSink sink;
    rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
    const RasterizerStats stats = rasterizer.stats();
    std::printf("%-28s %9zu %9zu %12llu %12llu %9llu %9llu %7llu %9llu\n", s.name.c_str(), contours, edges,
                static_cast<unsigned long long>(stats.crossings),
                static_cast<unsigned long long>(stats.pieces_visited),
                static_cast<unsigned long long>(stats.sampled_bands),
                static_cast<unsigned long long>(stats.sampled_rows),
                static_cast<unsigned long long>(stats.planar_fills),
                static_cast<unsigned long long>(stats.sweep_crossings));
  }
}

/// FNV-1a over the bytes of a value.
template <class T>
void hash_bytes(std::uint64_t& h, const T& value) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
  for (std::size_t i = 0; i < sizeof(T); ++i) h = (h ^ bytes[i]) * 1099511628211ull;
}

class HashSink final : public SpanSink {
 public:
  void blend(std::span<const Span> spans) override {
    for (const Span& span : spans) {
      hash_bytes(hash, span.x);
      hash_bytes(hash, span.y);
      hash_bytes(hash, span.len);
      hash_bytes(hash, span.coverage);
    }
  }
  std::uint64_t hash = 14695981039346656037ull;
};

/// The output of each scene, to show that a change to the rasterizer leaves it byte for byte: an FNV-1a hash
/// of the spans of its outline filled nonzero (both rules' results differ only where windings exceed 1,
/// so even-odd is hashed too), and of the canvas after two strokes through Canvas::stroke.
void print_output_hashes(const std::vector<Scene>& scenes) {
  std::printf("%-28s %16s %16s %16s\n", "scene", "spans nonzero", "spans even-odd", "canvas");
  Rasterizer rasterizer;
  for (const Scene& s : scenes) {
    const Result<Path> outline = stroke_path(build_path(s), scene_style(s), 0.1);
    if (!outline) continue;
    std::uint64_t spans[2] = {};
    for (const FillRule rule : {FillRule::kNonZero, FillRule::kEvenOdd}) {
      rasterizer.reset({0, 0, kSize, kSize});
      for (const PathElement& e : *outline) {
        if (e.verb == PathVerb::kLine || e.verb == PathVerb::kClose) rasterizer.add_line(e.start, e.end);
      }
      HashSink sink;
      rasterizer.rasterize(rule, Antialias::kExact, sink);
      spans[rule == FillRule::kNonZero ? 0 : 1] = sink.hash;
    }
    Canvas canvas = std::move(Canvas::create(kSize, kSize).value());
    const Paint paint = Paint::solid({0.1, 0.3, 0.8, 0.7});
    for (int i = 0; i < 2; ++i) {
      if (!canvas.stroke(build_path(s), paint, scene_style(s)).is_ok()) return;
    }
    std::uint64_t pixels = 14695981039346656037ull;
    for (const Rgba8& p : canvas.image().pixels()) hash_bytes(pixels, p);
    std::printf("%-28s %016llx %016llx %016llx\n", s.name.c_str(), static_cast<unsigned long long>(spans[0]),
                static_cast<unsigned long long>(spans[1]), static_cast<unsigned long long>(pixels));
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::mt19937 rng(4242);
  const std::vector<Segment> polyline = random_polyline(rng, 200);
  const std::vector<Segment> curves = random_curves(rng, 50);
  std::vector<Scene> scenes;
  for (const double width : {1.0, 20.0}) {
    for (const bool dashed : {false, true}) {
      const std::string suffix =
          "_w" + std::to_string(static_cast<int>(width)) + (dashed ? "_dashed" : "_solid");
      scenes.push_back({"polyline200" + suffix, {256, 256}, polyline, width, dashed});
      scenes.push_back({"cubics50" + suffix, {256, 256}, curves, width, dashed});
    }
  }
  for (const Scene& s : scenes) {
    curvescan::bench::register_side_by_side(
        s.name, [&s](benchmark::State& st) { bench_curvescan(st, s); },
        [&s](benchmark::State& st) { bench_cairo(st, s); });
  }
  // --outline_stats: only the outline and rasterizer counts (no timing).
  // --output_hashes: only hashes of each scene's spans and canvas (a change's output before and after).
  // --profile=SCENE [--iterations=N]: only curvescan's side of one scene, N strokes (default 20), without
  // Google Benchmark, for valgrind --tool=callgrind (deterministic instruction counts).
  std::string profile_scene;
  long iterations = 20;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--output_hashes") {
      print_output_hashes(scenes);
      return 0;
    }
    if (arg == "--outline_stats") {
      print_outline_stats(scenes);
      return 0;
    }
    if (arg.starts_with("--profile=")) profile_scene = arg.substr(10);
    if (arg.starts_with("--iterations=")) iterations = std::atol(arg.c_str() + 13);
  }
  if (!profile_scene.empty()) {
    for (const Scene& s : scenes) {
      if (s.name != profile_scene) continue;
      Canvas canvas = std::move(Canvas::create(kSize, kSize).value());
      const StrokeStyle style = scene_style(s);
      const Paint paint = Paint::solid({0.1, 0.3, 0.8, 0.7});
      for (long i = 0; i < iterations; ++i) {
        if (!canvas.stroke(build_path(s), paint, style).is_ok()) return 1;
      }
      std::printf("%s: %ld iterations\n", profile_scene.c_str(), iterations);
      return 0;
    }
    std::fprintf(stderr, "stroke_bench: no scene named '%s'\n", profile_scene.c_str());
    return 2;
  }
  const curvescan::bench::SideBySideMedians reporter = curvescan::bench::run_side_by_side(argc, argv);
  std::printf("\n%-28s %14s %14s %10s\n", "scene", "curvescan us", "cairo us", "ratio");
  std::vector<Scene> measured;  // the scenes both sides of which ran (--benchmark_filter)
  for (const Scene& s : scenes) {
    double ours = 0.0, cairo = 0.0;
    if (!reporter.find(s.name, ours, cairo)) continue;
    measured.push_back(s);
    std::printf("%-28s %14.1f %14.1f %9.2fx\n", s.name.c_str(), ours, cairo, cairo / ours);
  }
  print_outline_stats(measured);
  benchmark::Shutdown();
  return 0;
}
