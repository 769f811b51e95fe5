// Dash trains (stroker_outline.cpp, continues_train / bridge_gap): consecutive dashes whose facing round or
// square caps overlap are traced as one polygon along the caps' envelope instead of one polygon per dash.
// The nonzero union must stay the same: checked in closed form on a straight line, and against the dashes
// stroked one by one (dash_path, then each dash stroked solid into the same rasterizer: the per-dash
// polygons the stroker emitted before trains) on seeded random polylines, corners and short chords
// included (a train must not form where a cap pokes past the other dash's straight part).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <numbers>
#include <random>
#include <vector>

#include "curvescan/raster/stroke.h"
#include "stroke_render.h"

namespace curvescan {
namespace {

using testing::polyline_path;
using testing::render_stroke;

constexpr double kTolerance = 0.05;

std::size_t contour_count(const Path& outline) {
  std::size_t count = 0;
  for (const PathElement& element : outline) count += element.verb == PathVerb::kMove ? 1 : 0;
  return count;
}

// Area of {|y| <= max(sqrt(h² - x²), sqrt(h² - (g - x)²))} over 0 <= x <= g: twice the circle segment
// ∫_0^{g/2} 2·sqrt(h² - x²) dx.
double bridge_area(double g, double h) {
  const double x = 0.5 * g;
  const double half_segment = 0.5 * (x * std::sqrt(h * h - x * x) + h * h * std::asin(x / h));
  return 4.0 * half_segment;
}

/// The two cap tests' stroke: width 20 (h = 10), dashes 12 and gaps 6, so facing caps overlap by 14.
StrokeStyle wide_short_dashes(LineCap cap) {
  StrokeStyle style;
  style.width = 20.0;
  style.cap = cap;
  style.dash_array = {12.0, 6.0};
  return style;
}

TEST_CASE("round-capped dashes on a line whose caps overlap are one polygon with the union's area",
          "[stroke][dash]") {
  // Dashes 12, gaps 6, half-width 10 from x = 20 to 200 on y = 50: 10 dashes (the last one 12 long, ending
  // at 200 - 0 = 20 + 10·18 - 6), caps overlapping by 14. Area: the dash rectangles, one disc for the two
  // outer caps, and per gap the envelope of the two facing caps. Tolerance as in stroke_area_test.cpp:
  // 0.05 px times the perimeter (< 2·180 + 2π·10 + 10·2π·10) plus 8-bit rounding.
  const Path line = polyline_path({{20, 50}, {194, 50}});
  const StrokeStyle style = wide_short_dashes(LineCap::kRound);
  const Result<Path> outline = stroke_path(line, style, kTolerance);
  REQUIRE(outline.is_ok());
  CHECK(contour_count(*outline) == 1);

  const testing::CoverageMask mask = render_stroke(line, style, 240, 100, kTolerance);
  const double h = 10.0;
  const int dashes = 10;
  const double area = dashes * 12.0 * 2 * h + std::numbers::pi * h * h + (dashes - 1) * bridge_area(6.0, h);
  const double perimeter = 2 * 180.0 + 11 * 2 * std::numbers::pi * h;
  CHECK(mask.total() ==
        Approx(area).margin(kTolerance * perimeter + 0.5 / 255.0 * static_cast<double>(mask.values.size())));
  CHECK(mask.at(20 + 12 + 3, 50) == 255);  // the middle of the first gap is covered
  // Its edge has the notch between the two caps: at mid-gap the envelope is sqrt(h² - 3²) = 9.54 high, so
  // the pixel row [40, 41] is covered about half there.
  CHECK(mask.at(20 + 12 + 3, 40) > 64);
  CHECK(mask.at(20 + 12 + 3, 40) < 192);
}

TEST_CASE("square-capped dashes on a line whose caps overlap are one rectangle", "[stroke][dash]") {
  const Path line = polyline_path({{20, 50}, {194, 50}});
  StrokeStyle style = wide_short_dashes(LineCap::kSquare);
  const Result<Path> outline = stroke_path(line, style, kTolerance);
  REQUIRE(outline.is_ok());
  CHECK(contour_count(*outline) == 1);
  const testing::CoverageMask mask = render_stroke(line, style, 240, 100, kTolerance);
  // From 20 - 10 to 194 + 10 (the last dash ends at 194), 20 high; integer corners: exact up to rounding.
  CHECK(mask.total() == Approx(194.0 * 20.0).margin(0.5 / 255.0 * static_cast<double>(mask.values.size())));
}

TEST_CASE("butt caps and gaps wider than the caps reach keep one polygon per dash", "[stroke][dash]") {
  const Path line = polyline_path({{20, 50}, {194, 50}});
  StrokeStyle style;
  style.width = 4.0;
  style.dash_array = {12.0, 6.0};
  for (const LineCap cap : {LineCap::kButt, LineCap::kRound, LineCap::kSquare}) {
    style.cap = cap;
    const Result<Path> outline = stroke_path(line, style, kTolerance);
    REQUIRE(outline.is_ok());
    CHECK(contour_count(*outline) == 10);  // gap 6 > 2h = 4: the caps do not meet
  }
}

// The union of the dashes stroked one by one: every subpath of dash_path() stroked solid, all outlines
// filled nonzero together.
testing::CoverageMask render_dashes_one_by_one(const Path& path, const StrokeStyle& style, int size) {
  const Result<Path> dashes = dash_path(path, style.dash_array, style.dash_offset, 0.5 * kTolerance);
  REQUIRE(dashes.is_ok());
  StrokeStyle solid = style;
  solid.dash_array.clear();
  Rasterizer rasterizer(IntRect{0, 0, size, size});
  PathBuilder builder;
  bool open = false;
  const auto flush = [&] {
    if (!open) return;
    const Result<Path> dash = builder.build();
    REQUIRE(dash.is_ok());
    const Result<Path> outline = stroke_path(*dash, solid, kTolerance);
    REQUIRE(outline.is_ok());
    testing::add_polygon_path(rasterizer, *outline);
    builder = PathBuilder();
    open = false;
  };
  for (const PathElement& element : *dashes) {
    switch (element.verb) {
      case PathVerb::kMove:
        flush();
        builder.move_to(element.start);
        open = true;
        break;
      case PathVerb::kClose:
        builder.close();
        break;
      default:
        builder.line_to(element.end);
        break;
    }
  }
  flush();
  testing::CoverageMask mask(size, size);
  testing::MaskSink sink(mask);
  rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
  return mask;
}

TEST_CASE("dash trains on seeded random polylines cover what the dashes stroked one by one cover",
          "[stroke][dash]") {
  // Both sides are within the stroke tolerance of the same exact union; they differ only where a bridge's
  // arc polygon replaces the two caps' (vertices at other angles: up to the arc tolerance, 0.0125 px here,
  // 3.2/255 of a pixel) plus 8-bit rounding on each side: max 5/255.
  std::mt19937 rng(4077);
  std::uniform_real_distribution<double> coordinate(20.0, 140.0);
  std::uniform_real_distribution<double> offset(-20.0, 20.0);
  // No zero-length dashes: dash_path() gives a dot no direction, so its square would follow the x axis
  // (SVG 2 for a lone zero-length subpath) where the stroker squares it along the path.
  const std::vector<std::vector<double>> arrays = {{12, 6}, {9, 4, 2}, {3, 1}, {0.5, 5}, {20, 2}};
  std::size_t merged_somewhere = 0;
  for (int i = 0; i < 20; ++i) {
    PathBuilder builder;
    builder.move_to({coordinate(rng), coordinate(rng)});
    for (int k = 0; k < 4; ++k) builder.line_to({coordinate(rng), coordinate(rng)});
    if (i % 3 == 0) builder.close();
    const Result<Path> path = builder.build();
    REQUIRE(path.is_ok());
    StrokeStyle style;
    style.width = i % 2 == 0 ? 20.0 : 9.0;
    style.cap = i % 4 < 2 ? LineCap::kRound : LineCap::kSquare;
    style.join = i % 5 == 0 ? LineJoin::kRound : LineJoin::kMiter;
    style.dash_array = arrays[static_cast<std::size_t>(i) % arrays.size()];
    style.dash_offset = offset(rng);
    const testing::CoverageMask trains = render_stroke(*path, style, 160, 160, kTolerance);
    const testing::CoverageMask one_by_one = render_dashes_one_by_one(*path, style, 160);
    int worst = 0;
    for (std::size_t p = 0; p < trains.values.size(); ++p) {
      worst = std::max(worst, std::abs(int{trains.values[p]} - int{one_by_one.values[p]}));
    }
    INFO("polyline " << i << " width " << style.width << " cap " << static_cast<int>(style.cap));
    CHECK(worst <= 5);
    const Result<Path> outline = stroke_path(*path, style, kTolerance);
    const Result<Path> dashes = dash_path(*path, style.dash_array, style.dash_offset, 0.5 * kTolerance);
    REQUIRE((outline.is_ok() && dashes.is_ok()));
    if (contour_count(*outline) < contour_count(*dashes)) ++merged_somewhere;
  }
  CHECK(merged_somewhere >= 10);  // the trains do form on most of these
}

}  // namespace
}  // namespace curvescan
