// A mask's content is drawn offscreen only over the part of the output its region covers (mask.h
// device_box), placed at a whole-pixel offset; the coverage is then put back at that offset in a mask of the
// output's size. These tests check the pieces, and that a masked element draws the same pixels as the
// same masking done over the whole output (exactly: the offset is whole pixels, so nothing may move).
#include <catch2/catch.hpp>
#include <string>

#include "svg/mask.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;
using curvescan::svg::detail::device_box;
using curvescan::svg::detail::PixelBox;

TEST_CASE("mask offscreen: the device box is the region's pixels within the output", "[svg][mask]") {
  // Grown to whole pixels: 2.5..7.25 covers columns 2..7, 1..3 rows 1..2.
  const std::optional<PixelBox> box = device_box(Rect{2.5, 1.0, 7.25, 3.0}, Affine::identity(), 100, 100);
  REQUIRE(box);
  CHECK((box->x0 == 2 && box->y0 == 1 && box->x1 == 8 && box->y1 == 3));
  // Mapped by the transform (scaled by 2, moved by 10): the box of the corners.
  const std::optional<PixelBox> mapped =
      device_box(Rect{0.0, 0.0, 5.0, 5.0}, Affine::translate(10.0, 10.0) * Affine::scale(2.0, 2.0), 100, 100);
  REQUIRE(mapped);
  CHECK((mapped->x0 == 10 && mapped->y0 == 10 && mapped->x1 == 20 && mapped->y1 == 20));
  // Rotated by 45 degrees about the origin: the corners map to (0, 0), (3.54, 3.54), (-3.54, 3.54) and
  // (0, 7.07); within the output, columns 0..3 and rows 0..7.
  const std::optional<PixelBox> turned =
      device_box(Rect{0.0, 0.0, 5.0, 5.0}, Affine::rotate(0.7853981633974483), 100, 100);
  REQUIRE(turned);
  CHECK((turned->x0 == 0 && turned->y0 == 0 && turned->x1 == 4 && turned->y1 == 8));
  // Clipped to the output, and nothing when it lies outside it or is not finite.
  const std::optional<PixelBox> clipped =
      device_box(Rect{-50.0, 90.0, 10.0, 300.0}, Affine::identity(), 100, 100);
  REQUIRE(clipped);
  CHECK((clipped->x0 == 0 && clipped->y0 == 90 && clipped->x1 == 10 && clipped->y1 == 100));
  CHECK_FALSE(device_box(Rect{120.0, 0.0, 130.0, 10.0}, Affine::identity(), 100, 100));
  CHECK_FALSE(device_box(Rect{0.0, 0.0, 1e308, 10.0}, Affine::scale(10.0, 1.0), 100, 100));
}

TEST_CASE("mask offscreen: the coverage of the part lands at its offset, zero elsewhere", "[svg][mask]") {
  Image part(2, 1);
  part.pixels()[0] = Rgba8{0, 0, 0, 255};
  part.pixels()[1] = Rgba8{0, 0, 0, 100};
  const ClipMask mask = svg::detail::mask_coverage(part, svg::detail::MaskType::kAlpha, 4, 3, 1, 2);
  REQUIRE((mask.width() == 4 && mask.height() == 3));
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      const int expected = (y == 2 && x == 1) ? 255 : (y == 2 && x == 2) ? 100 : 0;
      INFO("x " << x << " y " << y);
      CHECK(int{mask.at(x, y)} == expected);
    }
  }
}

TEST_CASE("mask offscreen: a small mask region draws what the same mask over the whole output draws",
          "[svg][mask]") {
  // The same clip of the content, once as the mask region (drawn on an offscreen of the region's pixels,
  // at an offset) and once as a clip-path inside a mask whose region is the whole output (drawn on an
  // output-sized offscreen): the gradient, the rotated ellipse and the fractional rectangle edges must
  // land on the same pixels with the same values. No tolerance: a whole-pixel offset changes nothing.
  const std::string content =
      "<linearGradient id='g' x1='0' x2='1'><stop offset='0' stop-color='white'/>"
      "<stop offset='1' stop-color='#204080'/></linearGradient>";
  const std::string shapes =
      "<rect x='10' y='10' width='60' height='50' fill='url(#g)'/>"
      "<ellipse cx='40' cy='35' rx='25' ry='9' fill='white' fill-opacity='0.6' transform='rotate(30 40 "
      "35)'/>";
  const std::string target =
      "<g transform='translate(3.3 4.6) scale(1.7)'><rect x='5' y='5' width='70' height='60' fill='#c03010' "
      "mask='url(#m)'/></g>";
  const RenderedDocument small = render_square(
      200, content +
               "<mask id='m' maskUnits='userSpaceOnUse' x='12.35' y='13.8' width='47.3' height='38.45'>" +
               shapes + "</mask>" + target);
  const RenderedDocument whole = render_square(
      200, content +
               "<clipPath id='c'><rect x='12.35' y='13.8' width='47.3' height='38.45'/></clipPath>"
               "<mask id='m' maskUnits='userSpaceOnUse' x='-1000' y='-1000' width='3000' height='3000'>"
               "<g clip-path='url(#c)'>" +
               shapes + "</g></mask>" + target);
  REQUIRE(inked_pixels(small.image) > 1000);  // the test draws something
  CHECK(max_delta(small.image, whole.image) == 0);
}
