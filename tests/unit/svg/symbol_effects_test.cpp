// A <symbol> instanced by <use> is drawn as a nested <svg> (SVG 2 5.6, "The use element": the symbol's
// instance in the shadow tree becomes an <svg>), so its own clip-path, mask, filter and opacity apply to
// its content as a group, as they do to an <svg> drawn in place. Each case sets one effect on the symbol
// and reads pixels its content covers with and without it.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

// An 80 x 80 document: the symbol, with `effect` among its attributes, holds a green 80 x 80 square; the
// <use> draws it over the whole canvas. `defs` holds what the effect refers to.
Image symbol_with(const std::string& effect, const std::string& defs = "") {
  return render(svg_document("width=\"80\" height=\"80\"",
                             defs + "<symbol id=\"s\" " + effect +
                                 "><rect width=\"80\" height=\"80\" fill=\"#00ff00\"/></symbol>"
                                 "<use href=\"#s\"/>"))
      .image;
}

}  // namespace

TEST_CASE("symbol under use: its clip-path clips its content") {
  const Image image = symbol_with("clip-path=\"url(#c)\"",
                                  "<clipPath id=\"c\"><rect width=\"40\" height=\"80\"/></clipPath>");
  CHECK(image.at(20, 40).a == 255);
  CHECK(image.at(60, 40).a == 0);  // outside the clip path's rectangle
}

TEST_CASE("symbol under use: its mask masks its content") {
  const Image image = symbol_with(
      "mask=\"url(#m)\"",
      "<mask id=\"m\" maskUnits=\"userSpaceOnUse\"><rect width=\"80\" height=\"40\" fill=\"white\"/></mask>");
  CHECK(image.at(40, 20).a == 255);
  CHECK(image.at(40, 60).a == 0);  // under the mask's black (nothing)
}

TEST_CASE("symbol under use: its filter filters its content") {
  // feFlood replaces the content with opaque blue over the filter region.
  const Image image =
      symbol_with("filter=\"url(#f)\"", "<filter id=\"f\"><feFlood flood-color=\"#0000ff\"/></filter>");
  CHECK(image.at(40, 40).r == 0);
  CHECK(image.at(40, 40).g == 0);
  CHECK(image.at(40, 40).b == 255);
}

TEST_CASE("symbol under use: its opacity applies to its content as one group") {
  // Two overlapping opaque squares at opacity 0.5: as a group, the overlap is as translucent as the rest
  // (alpha 128 everywhere); folded into each square, the overlap would be 0.75 (191).
  const Image image =
      render(svg_document("width=\"80\" height=\"80\"",
                          "<symbol id=\"s\" opacity=\"0.5\">"
                          "<rect width=\"60\" height=\"60\" fill=\"#00ff00\"/>"
                          "<rect x=\"20\" y=\"20\" width=\"60\" height=\"60\" fill=\"#00ff00\"/>"
                          "</symbol><use href=\"#s\"/>"))
          .image;
  // 0.5 of 255 rounds to 127 or 128 (the layer's alpha is quantized once).
  CHECK(image.at(10, 10).a >= 127);
  CHECK(image.at(10, 10).a <= 128);
  CHECK(image.at(40, 40).a == image.at(10, 10).a);  // the overlap
}
