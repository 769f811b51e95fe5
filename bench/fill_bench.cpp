// Polygon fill benchmark: curvescan against Cairo in the same process, on the same canvas and scenes,
// both including the compositing of a solid, translucent colour. Reported as ratios of medians over
// repetitions (Cairo time / curvescan time: above 1 means curvescan is faster).
//
// curvescan composites through a minimal bench-local SpanSink that blends premultiplied RGBA into an RGBA8
// buffer (the real Canvas lives elsewhere); Cairo fills an ARGB32 image surface with CAIRO_OPERATOR_OVER and
// CAIRO_ANTIALIAS_DEFAULT. Both sides rebuild the path each iteration (curvescan: add_line per edge; Cairo:
// move_to/line_to), so path construction is measured on both.
//
// Ratios use CPU time: the machine is shared, and wall time of a single-threaded fill measures the
// neighbours as much as the fill.
// Run: fill_bench [--benchmark_filter=...]; the ratio table is printed after Google Benchmark's own output.
#include <benchmark/benchmark.h>
#include <cairo.h>
#include <emmintrin.h>

#include <algorithm>
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

#include "curvescan/raster/rasterizer.h"

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

// ---- curvescan side: rasterizer + a minimal solid-colour compositor --------------------------------------

/// Blends a solid premultiplied colour into RGBA8 pixels stored as little-endian 32-bit words
/// (R | G<<8 | B<<16 | A<<24), two channels per multiply as pixman's UN8x4_MUL_UN8_ADD_UN8x4 does:
/// dst = src·cov + dst·(1 - alpha(src·cov)), each product rounded as x·y/255.
class SolidBlendSink final : public curvescan::SpanSink {
 public:
  SolidBlendSink(std::vector<std::uint32_t>& pixels, int width, const std::uint8_t colour[4])
      : pixels_(pixels), width_(width) {
    for (int i = 0; i < 4; ++i) colour_ |= std::uint32_t{colour[i]} << (8 * i);
  }
  void blend(std::span<const curvescan::Span> spans) override {
    for (const curvescan::Span& s : spans) {
      const std::uint32_t src = mul_un8x4(colour_, s.coverage);
      const std::uint32_t inv = 255 - (src >> 24);
      std::uint32_t* p = pixels_.data() + static_cast<std::size_t>(s.y) * width_ + s.x;
      if (inv == 0) {
        std::fill(p, p + s.len, src);
        continue;
      }
      int k = 0;
      // Four pixels at a time with SSE2 (baseline on x86-64), as pixman's solid OVER does; the same
      // rounding as mul_un8x4: t = x·a + 128, (t + (t >> 8)) >> 8 fits 16 bits for 8-bit x and a.
      const __m128i zero = _mm_setzero_si128();
      const __m128i inv16 = _mm_set1_epi16(static_cast<short>(inv));
      const __m128i half = _mm_set1_epi16(0x80);
      const __m128i src4 = _mm_set1_epi32(static_cast<int>(src));
      const auto scale = [&](__m128i x) {
        const __m128i t = _mm_add_epi16(_mm_mullo_epi16(x, inv16), half);
        return _mm_srli_epi16(_mm_add_epi16(t, _mm_srli_epi16(t, 8)), 8);
      };
      for (; k + 4 <= s.len; k += 4) {
        const __m128i d = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + k));
        const __m128i lo = scale(_mm_unpacklo_epi8(d, zero));
        const __m128i hi = scale(_mm_unpackhi_epi8(d, zero));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(p + k), _mm_add_epi8(_mm_packus_epi16(lo, hi), src4));
      }
      for (; k < s.len; ++k) p[k] = src + mul_un8x4(p[k], inv);
    }
  }

 private:
  /// Each 8-bit channel of x times a, divided by 255 with rounding.
  static std::uint32_t mul_un8x4(std::uint32_t x, std::uint32_t a) {
    std::uint32_t rb = (x & 0x00ff00ffu) * a + 0x00800080u;
    rb = ((rb + ((rb >> 8) & 0x00ff00ffu)) >> 8) & 0x00ff00ffu;
    std::uint32_t ag = ((x >> 8) & 0x00ff00ffu) * a + 0x00800080u;
    ag = (ag + ((ag >> 8) & 0x00ff00ffu)) & 0xff00ff00u;
    return rb | ag;
  }
  std::vector<std::uint32_t>& pixels_;
  int width_;
  std::uint32_t colour_ = 0;
};

// Premultiplied translucent red-ish: alpha 0.8, so every pixel is a real blend on both sides.
constexpr std::uint8_t kColour[4] = {163, 20, 41, 204};

void bench_curvescan(benchmark::State& state, const Shape& shape, int size) {
  std::vector<std::uint32_t> pixels(static_cast<std::size_t>(size) * size, 0xffffffffu);
  SolidBlendSink sink(pixels, size, kColour);
  curvescan::Rasterizer rasterizer;
  for (auto _ : state) {
    rasterizer.reset({0, 0, size, size});
    for (const Contour& c : shape) {
      for (std::size_t i = 0; i < c.size(); ++i) rasterizer.add_line(c[i], c[(i + 1) % c.size()]);
    }
    rasterizer.rasterize(curvescan::FillRule::kNonZero, curvescan::Antialias::kExact, sink);
    benchmark::DoNotOptimize(pixels.data());
    benchmark::ClobberMemory();
  }
}

void bench_cairo(benchmark::State& state, const Shape& shape, int size) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, size, size);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgba(cr, kColour[0] / 204.0, kColour[1] / 204.0, kColour[2] / 204.0, kColour[3] / 255.0);
  cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  for (auto _ : state) {
    cairo_new_path(cr);
    for (const Contour& c : shape) {
      cairo_move_to(cr, c[0].x, c[0].y);
      for (std::size_t i = 1; i < c.size(); ++i) cairo_line_to(cr, c[i].x, c[i].y);
      cairo_close_path(cr);
    }
    cairo_fill(cr);
    cairo_surface_flush(surface);
    benchmark::DoNotOptimize(cairo_image_surface_get_data(surface));
    benchmark::ClobberMemory();
  }
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
}

/// Both sides must do the same work: renders `shape` once each way onto white and returns the largest
/// channel difference (Cairo's coverage differs from the exact one by up to ~17/255 on edges).
int max_channel_difference(const Shape& shape, int size) {
  std::vector<std::uint32_t> ours(static_cast<std::size_t>(size) * size, 0xffffffffu);
  SolidBlendSink sink(ours, size, kColour);
  curvescan::Rasterizer rasterizer({0, 0, size, size});
  for (const Contour& c : shape) {
    for (std::size_t i = 0; i < c.size(); ++i) rasterizer.add_line(c[i], c[(i + 1) % c.size()]);
  }
  rasterizer.rasterize(curvescan::FillRule::kNonZero, curvescan::Antialias::kExact, sink);
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, size, size);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_set_source_rgba(cr, kColour[0] / 204.0, kColour[1] / 204.0, kColour[2] / 204.0, kColour[3] / 255.0);
  for (const Contour& c : shape) {
    cairo_move_to(cr, c[0].x, c[0].y);
    for (std::size_t i = 1; i < c.size(); ++i) cairo_line_to(cr, c[i].x, c[i].y);
    cairo_close_path(cr);
  }
  cairo_fill(cr);
  cairo_surface_flush(surface);
  const unsigned char* data = cairo_image_surface_get_data(surface);
  const int stride = cairo_image_surface_get_stride(surface);
  int worst = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      std::uint32_t argb = 0;
      std::memcpy(&argb, data + static_cast<std::size_t>(y) * stride + 4 * static_cast<std::size_t>(x), 4);
      const std::uint32_t rgba = ours[static_cast<std::size_t>(y) * size + x];
      const int theirs[4] = {static_cast<int>((argb >> 16) & 255), static_cast<int>((argb >> 8) & 255),
                             static_cast<int>(argb & 255), static_cast<int>(argb >> 24)};
      for (int i = 0; i < 4; ++i)
        worst = std::max(worst, std::abs(static_cast<int>((rgba >> (8 * i)) & 255) - theirs[i]));
    }
  }
  cairo_destroy(cr);
  cairo_surface_destroy(surface);
  return worst;
}

// ---- ratio table -----------------------------------------------------------------------------------------

/// Keeps the median of every benchmark while the console reporter prints as usual.
class MedianCollector final : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") {
        medians[run.run_name.function_name] = run.GetAdjustedCPUTime();
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
  std::map<std::string, double> medians;
};

}  // namespace

int main(int argc, char** argv) {
  struct Case {
    std::string name;
    Shape shape;
    int size;
  };
  std::vector<Case> cases;
  const Point mid{256.0, 256.0};
  cases.push_back({"star_1000v_r250_100", {star(mid, 250, 100, 1000)}, 512});
  cases.push_back({"regular_1000gon_r250", {regular(mid, 250, 1000)}, 512});
  cases.push_back({"star_10v", {star(mid, 250, 100, 10)}, 512});
  cases.push_back({"many_small_shapes_1000", many_small_shapes(512, 1000), 512});
  for (const int size : {256, 512, 1024, 2048, 4096}) {
    const double s = size / 512.0;
    cases.push_back({"canvas_" + std::to_string(size) + "_star_1000v",
                     {star({256.0 * s, 256.0 * s}, 250 * s, 100 * s, 1000)},
                     size});
  }
  for (const int edges : {10, 100, 1000, 10000, 100000, 1000000}) {
    cases.push_back({"edges_" + std::to_string(edges) + "_regular", {regular(mid, 250, edges)}, 512});
  }
  for (const Case& c : cases) {
    benchmark::RegisterBenchmark(("curvescan/" + c.name).c_str(), [&c](benchmark::State& st) {
      bench_curvescan(st, c.shape, c.size);
    })->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(("cairo/" + c.name).c_str(), [&c](benchmark::State& st) {
      bench_cairo(st, c.shape, c.size);
    })->Unit(benchmark::kMicrosecond);
  }
  // Medians of repetitions unless the caller chose otherwise.
  std::vector<char*> args(argv, argv + argc);
  std::string repetitions = "--benchmark_repetitions=5";
  bool has_repetitions = false;
  for (int i = 1; i < argc; ++i)
    has_repetitions |= std::string(argv[i]).starts_with("--benchmark_repetitions");
  if (!has_repetitions) args.push_back(repetitions.data());
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  MedianCollector reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);

  std::printf("\n%-32s %14s %14s %10s %12s\n", "scene", "curvescan us", "cairo us", "ratio", "max |d| px");
  for (const Case& c : cases) {
    const auto ours = reporter.medians.find("curvescan/" + c.name);
    const auto cairo = reporter.medians.find("cairo/" + c.name);
    if (ours == reporter.medians.end() || cairo == reporter.medians.end()) continue;
    std::printf("%-32s %14.1f %14.1f %9.2fx %12d\n", c.name.c_str(), ours->second, cairo->second,
                cairo->second / ours->second, max_channel_difference(c.shape, c.size));
  }
  benchmark::Shutdown();
  return 0;
}
