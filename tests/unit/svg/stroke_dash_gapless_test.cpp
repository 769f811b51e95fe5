// stroke-dasharray with zero gaps ("40 0"): the dashes meet end to end, and the stroke is drawn as one
// with its joins, as Cairo (rsvg-convert 2.54) and browsers draw it; resvg's reference leaves the outer
// corner square of a join blank where a dash ends on it.
#include <catch2/catch.hpp>
#include <string>

#include "curvescan/svg/document.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;

namespace {

/// `body` in a 40 x 10 document, rendered (svg_test_support.h).
RenderedDocument render(const std::string& body) {
  return curvescan::svg::testing::render(curvescan::svg::testing::svg_document("width=\"40\" height=\"10\"", body));
}

bool inked(const Image& image, int x, int y) { return image.at(x, y).a == 255; }

}  // namespace

TEST_CASE("stroke-dasharray with zero gaps draws a solid stroke with its joins (the dasher joins gapless dashes)") {
  // A square's outline dashed "10 0": dash ends fall on the corners, where butt-ended dashes would
  // leave the outer corner square of the miter join blank. The same square stroked solid is the oracle.
  const std::string square = "<rect x=\"10\" y=\"2\" width=\"6\" height=\"6\" fill=\"none\" stroke=\"#000\""
                             " stroke-width=\"2\"";
  const RenderedDocument dashed = render(square + " stroke-dasharray=\"6 0\"/>");
  const RenderedDocument solid = render(square + "/>");
  CHECK(dashed.image.pixels() == solid.image.pixels());
  CHECK(inked(dashed.image, 9, 1));  // the outer corner of the top-left join
}
