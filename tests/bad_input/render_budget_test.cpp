// The per-render budgets of Canvas (RenderLimits, limits.h) at the library level: what is counted, that a
// refused fill draws nothing, and that memory is refused before it is allocated.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/path_builder.h"

namespace curvescan {
namespace {

Path polygon(int vertices, double radius, Point centre) {
  PathBuilder builder;
  for (int i = 0; i < vertices; ++i) {
    const double angle = 2.0 * 3.141592653589793 * i / vertices;
    const Point p{centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)};
    if (i == 0) {
      builder.move_to(p);
    } else {
      builder.line_to(p);
    }
  }
  builder.close();
  Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  return std::move(path).value();
}

bool all_transparent(const Image& image) {
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (image.at(x, y).a != 0) return false;
  return true;
}

TEST_CASE("Canvas counts one segment per polygon edge, over every fill of the render", "[bad_input][limits]") {
  Result<Canvas> canvas = Canvas::create(32, 32, RenderLimits{});
  REQUIRE(canvas.is_ok());
  REQUIRE(canvas->fill(polygon(7, 10, {16, 16}), Paint::solid({0, 0, 0, 1}), FillRule::kNonZero).is_ok());
  CHECK(canvas->segments_used() == 7);
  REQUIRE(canvas->fill(polygon(5, 10, {16, 16}), Paint::solid({0, 0, 0, 1}), FillRule::kNonZero).is_ok());
  CHECK(canvas->segments_used() == 12);
}

TEST_CASE("a fill past the segment budget fails with kLimitExceeded and draws nothing", "[bad_input][limits]") {
  RenderLimits limits;
  limits.max_segments = 10;
  Result<Canvas> canvas = Canvas::create(32, 32, limits);
  REQUIRE(canvas.is_ok());
  REQUIRE(canvas->fill(polygon(10, 10, {16, 16}), Paint::solid({0, 0, 0, 1}), FillRule::kNonZero).is_ok());
  Result<Canvas> fresh = Canvas::create(32, 32, limits);
  REQUIRE(fresh.is_ok());
  const Status refused =
      fresh->fill(polygon(11, 10, {16, 16}), Paint::solid({0, 0, 0, 1}), FillRule::kNonZero);
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  CHECK(refused.error().message.find("--max-segments") != std::string::npos);
  CHECK(all_transparent(fresh->image()));
  // The budget is per render: after 10 segments, a triangle more is refused too.
  const Status second = canvas->fill(polygon(3, 5, {8, 8}), Paint::solid({0, 0, 0, 1}), FillRule::kNonZero);
  CHECK_FALSE(second.is_ok());
}

TEST_CASE("memory is refused before the canvas, a layer or a clip mask is allocated", "[bad_input][limits]") {
  RenderLimits limits;
  limits.max_memory_bytes = 100 * 100 * 4 - 1;  // one byte short of a 100 x 100 RGBA8 canvas
  Result<Canvas> too_big = Canvas::create(100, 100, limits);
  REQUIRE_FALSE(too_big.is_ok());
  CHECK(too_big.error().kind == ErrorKind::kLimitExceeded);
  CHECK(too_big.error().message.find("--max-memory") != std::string::npos);

  limits.max_memory_bytes = 100 * 100 * 4 + 100 * 100;  // the canvas and one clip mask, no layer
  Result<Canvas> canvas = Canvas::create(100, 100, limits);
  REQUIRE(canvas.is_ok());
  CHECK(canvas->memory_bytes() == 100 * 100 * 4);
  CHECK_FALSE(canvas->reserve_layer().is_ok());
  const Path square = polygon(4, 30, {50, 50});
  REQUIRE(canvas->reserve_clip(square).is_ok());
  REQUIRE(canvas->push_clip(square, FillRule::kNonZero).is_ok());
  CHECK(canvas->memory_bytes() == 100 * 100 * 5);
  CHECK_FALSE(canvas->reserve_clip(square).is_ok());
  REQUIRE(canvas->pop_clip().is_ok());
  CHECK(canvas->reserve_clip(square).is_ok());
}

TEST_CASE("the dash budget counts dashes as the dasher does", "[bad_input][limits]") {
  // A 100-unit line with a 1-unit period ({0.5, 0.5}) makes 100 dashes, plus one for the contour's start
  // (dasher.cpp's estimate): 101 fits a budget of 101 and not of 100.
  PathBuilder builder;
  builder.move_to({0, 5});
  builder.line_to({100, 5});
  Result<Path> line = builder.build();
  REQUIRE(line.is_ok());
  StrokeStyle style;
  style.dash_array = {0.5, 0.5};
  RenderLimits limits;
  limits.max_dashes = 101;
  Result<Canvas> canvas = Canvas::create(120, 10, limits);
  REQUIRE(canvas.is_ok());
  CHECK(canvas->stroke(*line, Paint::solid({0, 0, 0, 1}), style).is_ok());
  limits.max_dashes = 100;
  canvas->set_limits(limits);
  const Status refused = canvas->stroke(*line, Paint::solid({0, 0, 0, 1}), style);
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().message.find("--max-dashes") != std::string::npos);
  // An odd array repeats: {1} is {1, 1}, a 2-unit period with one dash: 50 + 1.
  style.dash_array = {1.0};
  limits.max_dashes = 51;
  canvas->set_limits(limits);
  CHECK(canvas->stroke(*line, Paint::solid({0, 0, 0, 1}), style).is_ok());
  limits.max_dashes = 50;
  canvas->set_limits(limits);
  CHECK_FALSE(canvas->stroke(*line, Paint::solid({0, 0, 0, 1}), style).is_ok());
}

TEST_CASE("the dash budget counts only dashes that can reach the canvas", "[bad_input][limits]") {
  // A line two million units long across a 120 x 10 canvas with a 1-unit period: two million dashes in
  // all, about 130 of them within the stroke's reach of the canvas (120 units + 2 × 4.2: half the width
  // times the default miter limit, plus twice the tolerance; stroke_reach.h). A budget of 200 holds them;
  // the line's pixels are drawn.
  PathBuilder builder;
  builder.move_to({-1e6, 5});
  builder.line_to({1e6, 5});
  Result<Path> line = builder.build();
  REQUIRE(line.is_ok());
  StrokeStyle style;
  style.dash_array = {0.5, 0.5};
  style.width = 2.0;  // rows 4 and 5 covered whole
  RenderLimits limits;
  limits.max_dashes = 200;
  Result<Canvas> canvas = Canvas::create(120, 10, limits);
  REQUIRE(canvas.is_ok());
  REQUIRE(canvas->stroke(*line, Paint::solid({0, 0, 0, 1}), style).is_ok());
  // Pixel 10 holds the dash [10, 10.5] of the pattern that starts at -10^6 (a multiple of the period):
  // half covered, 127.5 rounded either way.
  CHECK(canvas->image().at(10, 5).a >= 127);
  CHECK(canvas->image().at(10, 5).a <= 128);
  // Scaled by 10^-4 along x, the line runs from x = -100 to 100 px: the 10^6 dashes of its right half
  // reach the canvas, and the budget refuses them.
  const Status refused = canvas->stroke(*line, Paint::solid({0, 0, 0, 1}), style, Affine::scale(1e-4, 1.0));
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().message.find("--max-dashes") != std::string::npos);
}

}  // namespace
}  // namespace curvescan
