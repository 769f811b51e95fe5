// The root <svg>'s background-color paints the canvas (CSS Backgrounds 3, 2.11.2; canvas_background.h).
// Expected pixels follow from source-over on premultiplied RGBA8 (paint.h): a colour of alpha 128/255
// leaves (r·128/255, ..., 128) where nothing covers it; an opaque shape on top replaces it. Every checked
// pixel is a whole pixel inside or outside every shape, so the values are exact.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

bool same(const Rgba8& pixel, int r, int g, int b, int a) {
  return pixel.r == r && pixel.g == g && pixel.b == b && pixel.a == a;
}

}  // namespace

TEST_CASE("canvas background: the root's background-color lies under the whole drawing",
          "[svg][background]") {
  // #0000ff80: blue at alpha 128, premultiplied (0, 0, 128, 128).
  const RenderedDocument out = render(svg_document(
      "width=\"20\" height=\"20\" viewBox=\"-10 -10 20 20\" style=\"background-color: #0000ff80\"",
      "<rect x=\"-5\" y=\"-5\" width=\"10\" height=\"10\" fill=\"#008000\"/>"));
  CHECK(same(out.image.at(0, 0), 0, 0, 128, 128));  // outside the viewBox's user-space origin too
  CHECK(same(out.image.at(19, 19), 0, 0, 128, 128));
  CHECK(same(out.image.at(10, 10), 0, 128, 0, 255));  // the opaque rectangle over it
}

TEST_CASE("canvas background: from a style sheet, with currentColor", "[svg][background]") {
  const RenderedDocument out = render(svg_document("width=\"10\" height=\"10\" color=\"#ff0000\"",
                                                   "<style>svg { background-color: currentColor }</style>"));
  CHECK(same(out.image.at(5, 5), 255, 0, 0, 255));
}

TEST_CASE("canvas background: not a presentation attribute, and no background on other elements",
          "[svg][background]") {
  // SVG 2 6.6 gives background-color no presentation attribute; an SVG element other than the root has
  // no CSS box to paint it on.
  const RenderedDocument attribute =
      render(svg_document("width=\"10\" height=\"10\" background-color=\"red\"", ""));
  CHECK(inked_pixels(attribute.image) == 0);
  const RenderedDocument group = render(svg_document("width=\"10\" height=\"10\"",
                                                     "<g style=\"background-color: red\"><rect width=\"1\" "
                                                     "height=\"1\"/></g>"));
  CHECK(inked_pixels(group.image) == 1);
}

TEST_CASE("canvas background: an invalid value falls back to the declaration below it", "[svg][background]") {
  // CSS Syntax 3 5.4.6: the invalid declaration is dropped, so the sheet's valid one wins.
  const RenderedDocument out =
      render(svg_document("width=\"10\" height=\"10\" style=\"background-color: nonsense\"",
                          "<style>svg { background-color: #00ff00 }</style>"));
  CHECK(same(out.image.at(5, 5), 0, 255, 0, 255));
  const RenderedDocument initial =
      render(svg_document("width=\"10\" height=\"10\" style=\"background-color: inherit\"", ""));
  CHECK(inked_pixels(initial.image) == 0);
}
