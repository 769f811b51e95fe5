// viewBox and preserveAspectRatio parsing and the viewBox-to-viewport transform (SVG 1.1 7.7-7.8).
#include "curvescan/svg/viewport.h"

#include <catch2/catch.hpp>

using namespace curvescan;
using namespace curvescan::svg;

TEST_CASE("parse_view_box: four numbers, negative sizes refused") {
  const auto box = parse_view_box(" 1,2 30 40 ");
  REQUIRE(box.is_ok());
  CHECK(box->x == 1);
  CHECK(box->height == 40);
  CHECK_FALSE(parse_view_box("0 0 10").is_ok());
  CHECK_FALSE(parse_view_box("0 0 -1 10").is_ok());
  CHECK(parse_view_box("0 0 0 10").is_ok());  // valid; the caller then renders nothing
}

TEST_CASE("parse_preserve_aspect_ratio: all alignments, meet/slice, none, defer, junk") {
  const auto aspect = parse_preserve_aspect_ratio("defer xMaxYMin slice");
  REQUIRE(aspect.is_ok());
  CHECK(aspect->align_x == 1.0);
  CHECK(aspect->align_y == 0.0);
  CHECK(aspect->slice);
  CHECK(parse_preserve_aspect_ratio("none")->none);
  CHECK(parse_preserve_aspect_ratio("xMidYMax meet")->align_y == 1.0);
  CHECK_FALSE(parse_preserve_aspect_ratio("xMidYMax cover").is_ok());
  CHECK_FALSE(parse_preserve_aspect_ratio("xCenterYMid").is_ok());
  CHECK_FALSE(parse_preserve_aspect_ratio("").is_ok());
}

TEST_CASE("view_box_transform maps the box onto the viewport as meet, slice and none require") {
  const ViewBox box{10, 20, 20, 10};  // 2:1
  // meet into 64x64: scale 3.2 (the smaller ratio), centred vertically (64 - 32) / 2 = 16.
  const Affine meet = view_box_transform(box, {}, 0, 0, 64, 64);
  CHECK(meet.apply(Point{10, 20}) == Point{0, 16});
  CHECK(meet.apply(Point{30, 30}) == Point{64, 48});
  PreserveAspectRatio slice;
  slice.slice = true;
  slice.align_x = 0.0;
  // slice: scale 6.4 (the larger), xMin: the box's left edge at x = 0.
  const Affine sliced = view_box_transform(box, slice, 0, 0, 64, 64);
  CHECK(sliced.apply(Point{10, 20}) == Point{0, 0});
  CHECK(sliced.apply(Point{20, 30}) == Point{64, 64});
  PreserveAspectRatio none;
  none.none = true;
  const Affine stretched = view_box_transform(box, none, 5, 5, 40, 40);
  CHECK(stretched.apply(Point{30, 30}) == Point{45, 45});
}
