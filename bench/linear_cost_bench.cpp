// Linear-cost benchmark: inputs within the documented limits (docs/limits.md) must cost time close to
// linear in their size. Each case runs at 10^3, 10^4 and 10^5 so that the growth is visible: time per item
// (the `per_item` counter, seconds per point or mark) should stay flat across the three sizes.
//
// - bspline_to_beziers / nurbs_to_rational_beziers: the Bézier decomposition behind `curvescan curve` and
//   the <cs:bspline>/<cs:nurbs> elements, on a clamped cubic (quadratic NURBS) with n random points.
// - bspline_decompose_and_flatten: the same plus flattening every piece at the default tolerance, the
//   library side of `curvescan curve` on a B-spline.
// - bspline_to_beziers_reference: the old whole-curve insertion, kept as the test oracle, at 10^3 and
//   10^4 only (quadratic: 10^5 took about five minutes) — the "before" of the table in docs/benchmarks.md.
// - text_layout_marks / text_path_marks: "a" followed by n U+0301 COMBINING ACUTE ACCENT, shaped with
//   DejaVu Sans (layout_text), and turned into one Path of outlines (text_path).
//
// CPU time, as the machine is shared. Run: linear_cost_bench [--benchmark_filter=...].
#include <benchmark/benchmark.h>

#include <random>
#include <string>
#include <vector>

#include "curvescan/curves/bspline.h"
#include "curvescan/curves/flatten.h"
#include "curvescan/curves/knot_vector.h"
#include "curvescan/curves/nurbs.h"
#include "curvescan/text/font.h"
#include "curvescan/text/text_layout.h"

namespace {

using namespace curvescan;

constexpr const char* kDejaVuSansFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

std::vector<Point> random_points(std::size_t count) {
  std::mt19937_64 rng(20261125);
  std::uniform_real_distribution<double> coordinate(0.0, 1000.0);
  std::vector<Point> points(count);
  for (Point& point : points) point = {coordinate(rng), coordinate(rng)};
  return points;
}

void set_per_item(benchmark::State& state) {
  state.SetItemsProcessed(state.iterations() * state.range(0));
  state.counters["per_item"] = benchmark::Counter(static_cast<double>(state.iterations() * state.range(0)),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void bspline_to_beziers(benchmark::State& state) {
  const auto spline = BSpline::clamped(random_points(static_cast<std::size_t>(state.range(0))), 3);
  for (auto _ : state) benchmark::DoNotOptimize(spline->to_beziers());
  set_per_item(state);
}

void bspline_to_beziers_reference(benchmark::State& state) {
  const auto spline = BSpline::clamped(random_points(static_cast<std::size_t>(state.range(0))), 3);
  for (auto _ : state) benchmark::DoNotOptimize(spline->to_beziers_reference());
  set_per_item(state);
}

void bspline_decompose_and_flatten(benchmark::State& state) {
  const auto spline = BSpline::clamped(random_points(static_cast<std::size_t>(state.range(0))), 3);
  std::vector<Point> polyline;
  for (auto _ : state) {
    polyline.clear();
    for (const Bezier& piece : spline->to_beziers()) {
      benchmark::DoNotOptimize(flatten_bezier(piece.points(), kDefaultFlattenTolerance, polyline));
    }
    benchmark::DoNotOptimize(polyline.data());
  }
  set_per_item(state);
}

void nurbs_to_rational_beziers(benchmark::State& state) {
  const std::size_t count = static_cast<std::size_t>(state.range(0));
  std::vector<double> weights(count);
  for (std::size_t i = 0; i < count; ++i) weights[i] = i % 2 == 0 ? 1.0 : 0.5;
  const auto nurbs = Nurbs::create(random_points(count), std::move(weights), *clamped_knots(count, 2), 2);
  for (auto _ : state) benchmark::DoNotOptimize(nurbs->to_rational_beziers());
  set_per_item(state);
}

std::u32string marks(std::size_t count) {
  std::u32string text = U"a";
  text.append(count, U'\u0301');
  return text;
}

void text_layout_marks(benchmark::State& state) {
  const auto font = Font::open(kDejaVuSansFile);
  const std::u32string text = marks(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(layout_text(*font, text, {0.0, 0.0}, {}));
  set_per_item(state);
}

void text_path_marks(benchmark::State& state) {
  const auto font = Font::open(kDejaVuSansFile);
  std::string utf8 = "a";
  for (std::int64_t i = 0; i < state.range(0); ++i) utf8 += "\xCC\x81";  // U+0301 in UTF-8
  for (auto _ : state) benchmark::DoNotOptimize(text_path(*font, utf8, {0.0, 0.0}, {}));
  set_per_item(state);
}

BENCHMARK(bspline_to_beziers)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(bspline_to_beziers_reference)
    ->RangeMultiplier(10)
    ->Range(1000, 10000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(bspline_decompose_and_flatten)
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(nurbs_to_rational_beziers)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(text_layout_marks)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(text_path_marks)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
