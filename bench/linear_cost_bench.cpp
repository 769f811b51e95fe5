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
// - text_layout_bidi_words: n characters of alternating Latin and Hebrew words, so that every word is a
//   bidi run of its own (bidi.h: levels, runs, rule L2 over the runs).
// - svg_text_chunks / svg_text_tspans: an SVG <text> of n characters, each with its own x (n text chunks),
//   or in n/2 tspans each with unicode-bidi, textLength and text-decoration; unfilled, so the time is the
//   document's parse and text layout, not rasterization of overlapping glyphs.
// - svg_text_marks: an SVG <text> of "a" followed by n U+0301, filled (the whole path from the text to the
//   pixels of a document).
// - text_layout_repeated_words: n characters of the same few words on one line, each word its own run
//   (every word is followed by a Hebrew one): the shaped-run cache (raster/text/shaping_p.h) shapes
//   each distinct word once.
// - fill_random_segments: one closed polyline through n random points of a 512 x 512 canvas, filled
//   nonzero with exact coverage (Rasterizer, spans counted, not composited): its segments cross each other
//   Θ(n²) times, so past the rows' work budget the crossing bands and rows are sampled (the essay of
//   raster/scan/rasterizer.cpp, step 7); run at 10^4, 10^5 and 10^6 (the goal: 10^6 at most 15× 10^5).
// - svg_path_markers: an SVG path of n vertices with a marker (using context-stroke) on each: the marked
//   element's box is computed once, not once per marker.
// - svg_sibling_selectors: n sibling elements under :nth-child / :nth-last-child rules and `~` chains
//   that never match (each would walk every earlier sibling): positions and `~` answers are cached per
//   parent (raster/svg/css/matching.h).
// - svg_filter_huge_blur: three feGaussianBlur with stdDeviation 1e30 and edgeMode duplicate (mode 1) or
//   wrap (mode 2) in a userSpaceOnUse filter region of n x n user units on a 200 x 200 canvas. Not linear
//   but bounded: past 4096 x 4096 units the filter image is capped by the pixel limit (docs/limits.md), and
//   a blur that wide makes each line one value (raster/svg/filter/gaussian_blur.h), so the time stays flat
//   from n = 10^4 to 10^7 and no σ makes it grow.
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
#include "curvescan/raster/rasterizer.h"
#include "curvescan/svg/document.h"
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

/// Counts the spans of a fill (the rasterizer's work without compositing).
class SpanCounter final : public SpanSink {
 public:
  void blend(std::span<const Span> spans) override { count += spans.size(); }
  std::size_t count = 0;
};

void fill_random_segments(benchmark::State& state) {
  std::mt19937_64 rng(20261126);
  std::uniform_real_distribution<double> coordinate(0.0, 512.0);
  std::vector<Point> points(static_cast<std::size_t>(state.range(0)));
  for (Point& point : points) point = {coordinate(rng), coordinate(rng)};
  Rasterizer rasterizer;
  SpanCounter spans;
  for (auto _ : state) {
    rasterizer.reset({0, 0, 512, 512});
    for (std::size_t i = 0; i < points.size(); ++i)
      rasterizer.add_line(points[i], points[(i + 1) % points.size()]);
    rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, spans);
  }
  benchmark::DoNotOptimize(spans.count);
  set_per_item(state);
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

void text_layout_bidi_words(benchmark::State& state) {
  const auto font = Font::open(kDejaVuSansFile);
  std::u32string text;
  while (text.size() < static_cast<std::size_t>(state.range(0)))
    text += text.size() % 16 == 0 ? U"abc " : U"\u05d0\u05d1\u05d2 ";
  for (auto _ : state) benchmark::DoNotOptimize(layout_text(*font, text, {0.0, 0.0}, {}));
  set_per_item(state);
}

void text_layout_repeated_words(benchmark::State& state) {
  const auto font = Font::open(kDejaVuSansFile);
  std::u32string text;
  const std::u32string words[] = {U"lorem ", U"ipsum ", U"dolor ", U"sit ", U"amet "};
  for (std::size_t i = 0; text.size() < static_cast<std::size_t>(state.range(0)); ++i) {
    text += words[i % 5];
    text += U"\u05e9\u05dc\u05d5\u05dd ";
  }
  for (auto _ : state) benchmark::DoNotOptimize(layout_text(*font, text, {0.0, 0.0}, {}));
  set_per_item(state);
}

void render_unfilled_text(benchmark::State& state, const std::string& text_element) {
  const std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"64\" height=\"64\">" + text_element + "</svg>";
  svg::RenderOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(svg::render_svg_document(document, options));
  set_per_item(state);
}

void svg_text_chunks(benchmark::State& state) {
  std::string x, characters;
  for (std::int64_t i = 0; i < state.range(0); ++i) {
    x += std::to_string(i % 64) + " ";
    characters += "a";
  }
  render_unfilled_text(state, "<text fill=\"none\" font-family=\"DejaVu Sans\" y=\"30\" x=\"" + x + "\">" +
                                  characters + "</text>");
}

void svg_text_marks(benchmark::State& state) {
  std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"64\" height=\"64\">"
      "<text font-family=\"DejaVu Sans\" x=\"10\" y=\"40\">a";
  for (std::int64_t i = 0; i < state.range(0); ++i) document += "\xCC\x81";  // U+0301 in UTF-8
  document += "</text></svg>";
  svg::RenderOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(svg::render_svg_document(document, options));
  set_per_item(state);
}

void svg_text_tspans(benchmark::State& state) {
  std::string content;
  for (std::int64_t i = 0; i < state.range(0) / 2; ++i) {
    content += "<tspan unicode-bidi=\"embed\" textLength=\"5\" text-decoration=\"underline\">ab</tspan>";
  }
  render_unfilled_text(state,
                       "<text fill=\"none\" font-family=\"DejaVu Sans\" y=\"30\">" + content + "</text>");
}

void svg_path_markers(benchmark::State& state) {
  // A zigzag path of n vertices, each with a small mid marker that uses context-stroke.
  std::string d = "M0 0";
  for (std::int64_t i = 0; i < state.range(0); ++i) d += i % 2 == 0 ? " l1 1" : " l1 -1";
  const std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"64\" height=\"64\">"
      "<marker id=\"m\" markerWidth=\"2\" markerHeight=\"2\"><rect width=\"1\" height=\"1\" "
      "fill=\"context-stroke\"/></marker>"
      "<path stroke=\"blue\" fill=\"none\" marker-mid=\"url(#m)\" d=\"" +
      d + "\"/></svg>";
  svg::RenderOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(svg::render_svg_document(document, options));
  set_per_item(state);
}

void svg_sibling_selectors(benchmark::State& state) {
  // n sibling rects under rules with a structural pseudo-class and with `~` chains that never match.
  std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"64\" height=\"64\"><style>"
      "rect:nth-child(3n+1) { fill: red } rect:nth-last-child(2) { fill: blue } "
      ".x ~ rect { fill: green } .y ~ .z ~ rect { fill: gray }</style>";
  for (std::int64_t i = 0; i < state.range(0); ++i) document += "<rect width=\"1\" height=\"1\"/>";
  document += "</svg>";
  svg::RenderOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(svg::render_svg_document(document, options));
  set_per_item(state);
}

void svg_filter_huge_blur(benchmark::State& state) {
  const std::string n = std::to_string(state.range(0)), half = std::to_string(state.range(0) / 2);
  const std::string blur = std::string("<feGaussianBlur stdDeviation=\"1e30\" edgeMode=\"") +
                           (state.range(1) == 1 ? "duplicate" : "wrap") + "\"/>";
  const std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"200\" height=\"200\">"
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"-" +
      half + "\" y=\"-" + half + "\" width=\"" + n + "\" height=\"" + n + "\">" + blur + blur + blur +
      "</filter><rect x=\"20\" y=\"20\" width=\"160\" height=\"160\" fill=\"green\" "
      "filter=\"url(#f)\"/></svg>";
  svg::RenderOptions options;
  for (auto _ : state) benchmark::DoNotOptimize(svg::render_svg_document(document, options));
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
BENCHMARK(text_layout_bidi_words)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(text_layout_repeated_words)
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(svg_text_marks)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(svg_text_chunks)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(svg_text_tspans)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(svg_path_markers)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(svg_sibling_selectors)->RangeMultiplier(10)->Range(1000, 100000)->Unit(benchmark::kMillisecond);
BENCHMARK(svg_filter_huge_blur)
    ->ArgsProduct({{1000, 10000, 10000000}, {1, 2}})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK(fill_random_segments)->RangeMultiplier(10)->Range(10000, 1000000)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
