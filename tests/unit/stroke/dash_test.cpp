// The dasher: dash positions by arc length, odd arrays, offsets, zero-length dashes, joins through
// vertices, closed contours, and SVG's all-zero rule. Positions are exact here (lines, lengths and
// offsets that are exact binary fractions), so comparisons use a 1e-9 margin for the lerp rounding.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "curvescan/raster/stroke.h"
#include "stroke_render.h"

namespace curvescan {
namespace {

using testing::polyline_path;
using testing::render_stroke;

struct Dash {
  Point start, end;
  std::size_t vertex_count;
};

std::vector<Dash> dashes_of(const Path& path) {
  std::vector<Dash> out;
  for (const PathElement& e : path) {
    if (e.verb == PathVerb::kMove) {
      out.push_back({e.start, e.start, 1});
    } else if (e.verb != PathVerb::kClose) {
      out.back().end = e.end;
      ++out.back().vertex_count;
    }
  }
  return out;
}

TEST_CASE("dashes of a line follow the array, odd arrays repeat", "[dash]") {
  const Path line = polyline_path({{0, 0}, {100, 0}});
  const double even[] = {10, 5};
  std::vector<Dash> d = dashes_of(*dash_path(line, even, 0.0, 0.1));
  REQUIRE(d.size() == 7);
  for (std::size_t i = 0; i < d.size(); ++i) {
    CHECK(d[i].start.x == Approx(15.0 * static_cast<double>(i)).margin(1e-9));
    CHECK(d[i].end.x == Approx(std::min(100.0, 15.0 * static_cast<double>(i) + 10)).margin(1e-9));
  }
  const double odd[] = {10};  // [10] = [10, 10]
  d = dashes_of(*dash_path(line, odd, 0.0, 0.1));
  REQUIRE(d.size() == 5);  // the gap [90, 100] ends on the end point: no empty dash there
  CHECK(d[4].start.x == Approx(80.0).margin(1e-9));
  const double triple[] = {10, 5, 20};  // [10, 5, 20, 10, 5, 20]: period 70
  d = dashes_of(*dash_path(line, triple, 0.0, 0.1));
  // on [0,10] [15,35] [45,50], then the repeat: [70,80] [85,100 (cut by the end)].
  REQUIRE(d.size() == 5);
  const double starts[] = {0, 15, 45, 70, 85}, ends[] = {10, 35, 50, 80, 100};
  for (std::size_t i = 0; i < d.size(); ++i) {
    CHECK(d[i].start.x == Approx(starts[i]).margin(1e-9));
    CHECK(d[i].end.x == Approx(ends[i]).margin(1e-9));
  }
}

TEST_CASE("negative offsets are taken modulo the pattern", "[dash]") {
  const Path line = polyline_path({{0, 0}, {100, 0}});
  const double pattern[] = {10, 10};
  // -5 ≡ 15 (mod 20): the walk starts 5 into the gap, so the first dash is [5, 15].
  std::vector<Dash> minus = dashes_of(*dash_path(line, pattern, -5.0, 0.1));
  std::vector<Dash> plus = dashes_of(*dash_path(line, pattern, 15.0, 0.1));
  std::vector<Dash> far = dashes_of(*dash_path(line, pattern, -2005.0, 0.1));
  REQUIRE(minus.size() == 5);
  REQUIRE(plus.size() == minus.size());
  REQUIRE(far.size() == minus.size());
  for (std::size_t i = 0; i < minus.size(); ++i) {
    CHECK(minus[i].start.x == Approx(5.0 + 20.0 * static_cast<double>(i)).margin(1e-9));
    CHECK(plus[i].start.x == Approx(minus[i].start.x).margin(1e-9));
    CHECK(far[i].start.x == Approx(minus[i].start.x).margin(1e-9));
  }
}

TEST_CASE("an all-zero dash array strokes solid (SVG 2)", "[dash]") {
  const Path line = polyline_path({{10, 20}, {90, 20}});
  StrokeStyle solid;
  solid.width = 6;
  StrokeStyle zeros = solid;
  zeros.dash_array = {0, 0, 0};
  CHECK_FALSE(dash_is_active(zeros.dash_array));
  CHECK(testing::max_abs_diff(render_stroke(line, solid, 100, 40), render_stroke(line, zeros, 100, 40)) == 0);
}

TEST_CASE("zero-length dashes draw dots with round caps, squares with square caps, nothing with butt",
          "[dash]") {
  const Path line = polyline_path({{10, 20}, {110, 20}});
  StrokeStyle style;
  style.width = 6;
  style.dash_array = {0, 20};  // dots at 10, 30, ..., 110: six of them
  style.cap = LineCap::kRound;
  const double h = 3.0, margin = 6 * 2 * std::numbers::pi * h * 0.05 + 0.5 / 255 * 130 * 40;
  CHECK(render_stroke(line, style, 130, 40).total() == Approx(6 * std::numbers::pi * h * h).margin(margin));
  style.cap = LineCap::kSquare;
  CHECK(render_stroke(line, style, 130, 40).total() == Approx(6 * 36.0).margin(0.5 / 255 * 130 * 40));
  style.cap = LineCap::kButt;
  CHECK(render_stroke(line, style, 130, 40).total() == 0.0);
}

TEST_CASE("square dots of a zero-length dash follow the path direction", "[dash]") {
  // A diagonal line: each square is rotated 45°; its corners reach h·√2 along the axes.
  const Path diagonal = polyline_path({{20, 20}, {80, 80}});
  StrokeStyle style;
  style.width = 10;
  style.cap = LineCap::kSquare;
  style.dash_array = {0, 1000};
  const testing::CoverageMask mask = render_stroke(diagonal, style, 100, 100);
  CHECK(mask.at(26, 19) > 0);   // the corner at (20 + 7.07, 20) reaches x = 27
  CHECK(mask.at(24, 15) == 0);  // an axis-aligned square would cover (24, 15)
}

TEST_CASE("a dash running through a vertex gets the join, not two caps", "[dash]") {
  const Path corner = polyline_path({{20, 80}, {50, 20}, {80, 80}});
  StrokeStyle solid;
  solid.width = 10;
  solid.miter_limit = 10;
  StrokeStyle dashed = solid;
  dashed.dash_array = {1000, 10};  // one dash covering the whole path
  CHECK(testing::max_abs_diff(render_stroke(corner, solid, 100, 100), render_stroke(corner, dashed, 100, 100)) ==
        0);
  dashed.dash_array = {60, 200};  // ends 60 - 67.08 = before the vertex... no: 60 < 67.08
  dashed.dash_offset = -30;        // starts 30 before: the dash covers [30, 90] and the vertex at 67.08
  const testing::CoverageMask mask = render_stroke(corner, dashed, 100, 100);
  CHECK(mask.at(50, 10) > 100);  // the miter tip is there
}

TEST_CASE("a dash ending exactly on a vertex takes the incoming tangent for its cap", "[dash]") {
  // First dash [0, 40] ends on the vertex (60, 20); its square cap must extend along +x to x = 65 (the
  // incoming tangent), not down the next segment.
  const Path corner = polyline_path({{20, 20}, {60, 20}, {60, 90}});
  StrokeStyle style;
  style.width = 10;
  style.cap = LineCap::kSquare;
  style.dash_array = {40, 20};
  const testing::CoverageMask mask = render_stroke(corner, style, 100, 100);
  CHECK(mask.at(63, 17) == 255);  // inside the cap beyond the vertex
  CHECK(mask.at(60, 30) == 0);    // the gap [40, 60] runs down from the vertex; caps take 5 px of it
  CHECK(mask.at(60, 36) == 255);  // the next dash starts at y = 40, its square cap at 35
}

TEST_CASE("on a closed contour the dash over the start joins the last one", "[dash]") {
  const Path square = polyline_path({{10, 10}, {70, 10}, {70, 70}, {10, 70}}, true);  // perimeter 240
  const double pattern[] = {30, 10};
  // Offset 5: on at the start (25 left) and on at the end (240 + 5 ≡ 5): the last and first dashes merge.
  std::vector<Dash> d = dashes_of(*dash_path(square, pattern, 5.0, 0.1));
  CHECK(d.size() == 6);
  // Offset 0: the pattern divides the perimeter, the last dash ends 10 before the start: six dashes too.
  d = dashes_of(*dash_path(square, pattern, 0.0, 0.1));
  CHECK(d.size() == 6);
  // The merged dash runs through the corner (10, 10), which gets its miter: pixel (7, 7) is covered.
  StrokeStyle style;
  style.width = 8;
  style.dash_array = {30, 10};
  style.dash_offset = 5;
  CHECK(render_stroke(square, style, 80, 80).at(7, 7) == 255);
}

}  // namespace
}  // namespace curvescan
