// Dashes culled to a visible box (stroke_path with `visible`, dasher.cpp): none made or counted where the
// outline cannot reach the box, and inside it the same coverage as the stroke made without the box.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cstdlib>
#include <limits>
#include <string>
#include <vector>

#include "curvescan/raster/limits.h"
#include "curvescan/raster/path_builder.h"
#include "curvescan/raster/stroke.h"
#include "stroke_render.h"

namespace curvescan {
namespace {

using testing::add_polygon_path;
using testing::CoverageMask;
using testing::MaskSink;
using testing::polyline_path;

constexpr int kBoxSize = 60;
const Rect kVisible{0.0, 0.0, kBoxSize, kBoxSize};

// The outline filled nonzero over the visible box (the rasterizer clips what lies outside it).
CoverageMask visible_coverage(const Path& outline) {
  CoverageMask mask(kBoxSize, kBoxSize);
  Rasterizer rasterizer(IntRect{0, 0, kBoxSize, kBoxSize});
  add_polygon_path(rasterizer, outline);
  MaskSink sink(mask);
  rasterizer.rasterize(FillRule::kNonZero, Antialias::kExact, sink);
  CHECK(sink.violations == 0);
  return mask;
}

Path curved_path() {
  // Leaves and re-enters the box through lines and a cubic; closed through a chord that crosses it.
  PathBuilder builder;
  builder.move_to({-200, 20});
  builder.line_to({300, 25});
  builder.line_to({290, 50});
  builder.cubic_to({100, 200}, {-50, -100}, {-200, 70});
  builder.close();
  builder.move_to({30, 30});  // starts inside: its last dash joins its first through vertex 0
  builder.line_to({300, 40});
  builder.line_to({40, 300});
  builder.close();
  builder.move_to({-500, -400});  // open, a quadratic through the box
  builder.quad_to({30, 200}, {500, -300});
  Result<Path> path = std::move(builder).build();
  REQUIRE(path.is_ok());
  return *path;
}

TEST_CASE("inside the visible box, culled dashes cover what the full dash pattern covers", "[stroke][dash]") {
  struct Case {
    std::vector<double> dashes;
    double offset;
    LineCap cap;
    LineJoin join;
    double width;
  };
  const std::vector<Case> cases = {
      {{7, 3, 1, 3}, 2.0, LineCap::kSquare, LineJoin::kMiter, 6.0},
      {{5}, -1.5, LineCap::kButt, LineJoin::kBevel, 3.0},
      {{0, 4}, 0.0, LineCap::kRound, LineJoin::kRound, 2.5},  // dots: zero-length dashes
      {{40, 0.5}, 13.0, LineCap::kSquare, LineJoin::kMiterClip, 9.0},
  };
  const Path path = curved_path();
  for (const Case& c : cases) {
    StrokeStyle style;
    style.dash_array = c.dashes;
    style.dash_offset = c.offset;
    style.cap = c.cap;
    style.join = c.join;
    style.width = c.width;
    const Result<Path> full = stroke_path(path, style, 0.05);
    const Result<Path> culled = stroke_path(path, style, 0.05, kMaxStrokeOutlinePoints, kVisible);
    REQUIRE(full.is_ok());
    REQUIRE(culled.is_ok());
    // Culling did drop dashes: the culled outline is a fraction of the full one.
    CHECK(culled->points().size() * 2 < full->points().size());
    const CoverageMask a = visible_coverage(*full);
    const CoverageMask b = visible_coverage(*culled);
    // Past a culled piece the pattern moves by whole periods (fmod) where the full walk subtracts entry by
    // entry: the dash ends agree to rounding (~1e-13 units), which can tip a coverage byte's rounding by
    // one, never more.
    int worst = 0;
    for (std::size_t i = 0; i < a.values.size(); ++i)
      worst = std::max(worst, std::abs(a.values[i] - b.values[i]));
    INFO("dash pattern of " << c.dashes.size() << " entries, width " << c.width);
    CHECK(worst <= 1);
    CHECK(a.total() > 100.0);  // the box does hold dashes
  }
}

TEST_CASE("a square cap's corner and a miter's tip reach into the box from beyond half the width",
          "[stroke][dash]") {
  // Both the cap's end point and the miter's vertex lie 3.5 and 7 units outside the box, farther than half
  // the width (3): the cull box must grow by √2 and the miter limit times half the width (stroke_reach.h).
  PathBuilder builder;
  builder.move_to({-40, -6.5});  // ends at (-3.5, 30) heading (1, 1)/√2: a cap corner at (0.74, 30)
  builder.line_to({-3.5, 30});
  builder.move_to({0, -100});  // a spike at (30, -7) with a 36.9° angle: its miter tip reaches y = 2.5
  builder.line_to({30, -7});
  builder.line_to({60, -100});
  Result<Path> path = std::move(builder).build();
  REQUIRE(path.is_ok());
  StrokeStyle style;
  style.width = 6.0;
  style.cap = LineCap::kSquare;
  style.join = LineJoin::kMiter;
  style.dash_array = {200, 1};  // on along both subpaths
  const Result<Path> full = stroke_path(*path, style, 0.05);
  const Result<Path> culled = stroke_path(*path, style, 0.05, kMaxStrokeOutlinePoints, kVisible);
  REQUIRE(full.is_ok());
  REQUIRE(culled.is_ok());
  const CoverageMask a = visible_coverage(*full);
  const CoverageMask b = visible_coverage(*culled);
  CHECK(a.at(0, 30) > 0);  // the cap's corner
  CHECK(a.at(30, 1) > 0);  // the miter's tip
  CHECK(a.values == b.values);
}

TEST_CASE("dashes outside the visible box are neither made nor counted against the dash limit",
          "[stroke][dash][limits]") {
  // 10^10 dashes along the whole line, far past kMaxDashSegments; about 70 reach the box.
  const Path long_line = polyline_path({{-1e7, 30}, {1e7, 30}});
  StrokeStyle style;
  style.dash_array = {0.001, 0.001};
  style.width = 4.0;
  style.join = LineJoin::kRound;  // the reach is then half the width, not the miter limit's multiple of it
  REQUIRE_FALSE(stroke_path(long_line, style, 0.1).is_ok());
  const Result<Path> culled = stroke_path(long_line, style, 0.1, kMaxStrokeOutlinePoints, kVisible);
  REQUIRE(culled.is_ok());
  // Every outline point lies within the stroke's reach of the box: half the width + 2·tolerance = 2.2
  // (stroke_reach.h), butt caps adding nothing; 1e-9 absorbs the rounding of the cut points.
  const Rect bounds = culled->bounds();
  CHECK(bounds.x0 >= -2.2 - 1e-9);
  CHECK(bounds.x1 <= kBoxSize + 2.2 + 1e-9);
  // The box's 60 units of line hold 30 000 dashes of 0.001 each side of the pattern; a butt-capped dash
  // outline has at least 4 points.
  CHECK(culled->verbs().size() >= 4 * 30000);
  CHECK(visible_coverage(*culled).total() > 0.45 * kBoxSize * 4.0);  // half of the 60 x 4 band is inked
}

TEST_CASE("a box that is not finite culls nothing", "[stroke][dash]") {
  const Path line = polyline_path({{-100, 30}, {200, 30}});
  StrokeStyle style;
  style.dash_array = {3, 2};
  const double inf = std::numeric_limits<double>::infinity();
  const Result<Path> full = stroke_path(line, style, 0.05);
  const Result<Path> unbounded =
      stroke_path(line, style, 0.05, kMaxStrokeOutlinePoints, Rect{-inf, -inf, inf, inf});
  REQUIRE(full.is_ok());
  REQUIRE(unbounded.is_ok());
  CHECK(full->points().size() == unbounded->points().size());
  CHECK(full->bounds() == unbounded->bounds());
}

}  // namespace
}  // namespace curvescan
