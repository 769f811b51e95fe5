// context-fill and context-stroke (SVG 2 13.4.1): inside a marker, the paints of the element the marker
// is drawn for; inside a <use>'s content, the <use>'s paints; elsewhere none. Opaque shapes on whole
// pixels: exact colours.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

const Rgba8 kRed{255, 0, 0, 255};
const Rgba8 kBlue{0, 0, 255, 255};
const Rgba8 kNothing{0, 0, 0, 0};

}  // namespace

TEST_CASE("context-fill and context-stroke in a marker take the marked element's paints", "[svg][context-paint]") {
  // A 6 x 6 marker square centred on the path's start (10, 20), its left half the path's fill, its right
  // half the path's stroke.
  const RenderedDocument rendered = render_square(
      40,
      "<marker id=\"m\" markerUnits=\"userSpaceOnUse\" markerWidth=\"6\" markerHeight=\"6\" refX=\"3\" "
      "refY=\"3\">"
      "<rect width=\"3\" height=\"6\" fill=\"context-fill\"/><rect x=\"3\" width=\"3\" height=\"6\" "
      "fill=\"context-stroke\"/></marker>"
      "<path d=\"M10 20 H30\" fill=\"red\" stroke=\"blue\" stroke-width=\"1\" marker-start=\"url(#m)\"/>");
  CHECK(rendered.image.at(8, 18) == kRed);
  CHECK(rendered.image.at(11, 18) == kBlue);
}

TEST_CASE("context-fill in a <use>'s content takes the <use>'s fill — currentColor is the use's colour",
          "[svg][context-paint]") {
  const RenderedDocument rendered = render_square(
      40,
      "<defs><rect id=\"r\" width=\"10\" height=\"10\" fill=\"context-fill\" stroke=\"none\"/></defs>"
      "<use href=\"#r\" fill=\"red\"/><use href=\"#r\" x=\"20\" fill=\"currentColor\" color=\"blue\"/>");
  CHECK(rendered.image.at(5, 5) == kRed);
  CHECK(rendered.image.at(25, 5) == kBlue);
}

TEST_CASE("context paints outside a context element paint nothing — one is no fallback", "[svg][context-paint]") {
  const RenderedDocument outside =
      render_square(40, "<rect width=\"10\" height=\"10\" fill=\"context-fill\"/>");
  CHECK(outside.image.at(5, 5) == kNothing);
  // "url(#missing) context-fill" is not a valid <paint> (the fallback must be none or a colour): the
  // declaration is ignored, the initial black fill stays.
  const RenderedDocument fallback =
      render_square(40, "<rect width=\"10\" height=\"10\" fill=\"url(#missing) context-fill\"/>");
  CHECK(fallback.image.at(5, 5) == (Rgba8{0, 0, 0, 255}));
}
