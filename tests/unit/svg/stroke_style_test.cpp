// stroke_style_of (stroke_style.h): the computed stroke properties as the core's StrokeStyle, the one
// place the SVG reader makes it (for drawing, and for the ink box of --export-id).
#include "svg/stroke_style.h"

#include <catch2/catch.hpp>
#include <vector>

using namespace curvescan;
using namespace curvescan::svg::detail;

TEST_CASE("stroke style of the initial computed style is SVG's initial stroke") {
  const StrokeStyle stroke = stroke_style_of(ComputedStyle{});
  CHECK(stroke.width == 1.0);
  CHECK(stroke.join == LineJoin::kMiter);
  CHECK(stroke.cap == LineCap::kButt);
  CHECK(stroke.miter_limit == 4.0);
  CHECK(stroke.dash_array.empty());
  CHECK(stroke.dash_offset == 0.0);
}

TEST_CASE("stroke style maps every join and cap, arcs drawn as miter") {
  ComputedStyle style;
  const auto join_of = [&](LineJoinValue value) {
    style.stroke_linejoin = value;
    return stroke_style_of(style).join;
  };
  CHECK(join_of(LineJoinValue::kMiter) == LineJoin::kMiter);
  CHECK(join_of(LineJoinValue::kMiterClip) == LineJoin::kMiterClip);
  CHECK(join_of(LineJoinValue::kRound) == LineJoin::kRound);
  CHECK(join_of(LineJoinValue::kBevel) == LineJoin::kBevel);
  CHECK(join_of(LineJoinValue::kArcs) == LineJoin::kMiter);  // SVG 2's fallback for arcs
  const auto cap_of = [&](LineCapValue value) {
    style.stroke_linecap = value;
    return stroke_style_of(style).cap;
  };
  CHECK(cap_of(LineCapValue::kButt) == LineCap::kButt);
  CHECK(cap_of(LineCapValue::kRound) == LineCap::kRound);
  CHECK(cap_of(LineCapValue::kSquare) == LineCap::kSquare);
}

TEST_CASE("stroke style carries width, miter limit and dashes in user units") {
  ComputedStyle style;
  style.stroke_width = 2.5;
  style.stroke_miterlimit = 10.0;
  style.stroke_dasharray = {3.0, 1.0, 2.0};
  style.stroke_dashoffset = -1.5;
  const StrokeStyle stroke = stroke_style_of(style);
  CHECK(stroke.width == 2.5);
  CHECK(stroke.miter_limit == 10.0);
  CHECK(stroke.dash_array == std::vector<double>{3.0, 1.0, 2.0});
  CHECK(stroke.dash_offset == -1.5);
}
