// A shape's object bounding box (SVG 1.1 7.11) is measured only for what may refer to it: a clip path, a
// mask, a filter, or a gradient or pattern fill or stroke. These pin each use that still needs it, the
// less obvious ones first: the clipPath's own clip-path in objectBoundingBox units under a clip path in
// user space (CSS Masking 1 6.1), and a stroke's paint server on a shape filled with a plain colour.
// Every region is a whole-pixel rectangle and every gradient has a hard stop, so each checked pixel is
// one colour: exact values.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

const Rgba8 kGreen{0, 128, 0, 255};
const Rgba8 kRed{255, 0, 0, 255};
const Rgba8 kBlue{0, 0, 255, 255};

// Red on the left half of the box it is placed on, blue on the right (objectBoundingBox units).
const std::string kHalves =
    "<linearGradient id=\"halves\"><stop offset=\"0.5\" stop-color=\"red\"/>"
    "<stop offset=\"0.5\" stop-color=\"blue\"/></linearGradient>";

}  // namespace

TEST_CASE("shape box: a clipPath's own clip-path in objectBoundingBox units uses the shape's box",
          "[svg][clip][box]") {
  // The outer clip is in user space and shows everything; its own clip-path keeps the left half of the
  // shape's box, x 10..20.
  const RenderedDocument doc = render_square(
      40,
      "<clipPath id=\"half\" clipPathUnits=\"objectBoundingBox\"><rect width=\"0.5\" "
      "height=\"1\"/></clipPath>"
      "<clipPath id=\"c\" clip-path=\"url(#half)\"><rect width=\"40\" height=\"40\"/></clipPath>"
      "<rect x=\"10\" width=\"20\" height=\"40\" fill=\"green\" clip-path=\"url(#c)\"/>");
  CHECK(doc.image.at(15, 20) == kGreen);
  CHECK(doc.image.at(25, 20) == Rgba8{});
}

TEST_CASE("shape box: a gradient fill in objectBoundingBox units spans the shape's box",
          "[svg][paint][box]") {
  const RenderedDocument doc = render_square(
      40, kHalves + "<rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" fill=\"url(#halves)\"/>");
  CHECK(doc.image.at(12, 20) == kRed);
  CHECK(doc.image.at(27, 20) == kBlue);
}

TEST_CASE("shape box: a stroke's gradient spans the shape's box when the fill is a plain colour",
          "[svg][paint][box]") {
  // The box is the geometry's (strokes excluded): the stroke outside it takes the gradient's ends.
  const RenderedDocument doc = render_square(
      40, kHalves +
              "<rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" fill=\"green\" stroke=\"url(#halves)\" "
              "stroke-width=\"4\"/>");
  CHECK(doc.image.at(9, 20) == kRed);
  CHECK(doc.image.at(30, 20) == kBlue);
  CHECK(doc.image.at(20, 20) == kGreen);
}

TEST_CASE("shape box: a mask in objectBoundingBox units covers the shape's box", "[svg][mask][box]") {
  // maskContentUnits in the box: the white rect shows the left half of the shape, x 10..20.
  const RenderedDocument doc =
      render_square(40,
                    "<mask id=\"m\" maskContentUnits=\"objectBoundingBox\"><rect width=\"0.5\" height=\"1\" "
                    "fill=\"white\"/></mask>"
                    "<rect x=\"10\" width=\"20\" height=\"40\" fill=\"green\" mask=\"url(#m)\"/>");
  CHECK(doc.image.at(15, 20) == kGreen);
  CHECK(doc.image.at(25, 20) == Rgba8{});
}
