// The object bounding box of a nested <svg>, and of a <symbol> instanced by <use>, is its content's box
// in the user space the element itself is in: the content measured in the viewport the element
// establishes and mapped out of it by x, y and the viewBox (SVG 1.1 7.9, SVG 2 8.10). Each case puts a
// filter region or mask in objectBoundingBox units on such an element and reads pixels inside and outside
// where that box lands.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

// feFlood over exactly the bounding box (region 0 0 1 1 in objectBoundingBox units): opaque blue.
const std::string kFloodBox =
    "<filter id=\"f\" x=\"0\" y=\"0\" width=\"1\" height=\"1\"><feFlood flood-color=\"#0000ff\"/></filter>";

bool blue(const Image& image, int x, int y) {
  const auto pixel = image.at(x, y);
  return pixel.r == 0 && pixel.g == 0 && pixel.b == 255 && pixel.a == 255;
}

}  // namespace

TEST_CASE("nested svg: an objectBoundingBox filter region is its content's box mapped by its viewBox") {
  // viewBox 0 0 10 10 onto 80 x 80: the rect (5, 5, 5, 5) covers 40..80 of the document.
  const Image image = render(svg_document("width=\"100\" height=\"100\"",
                                          kFloodBox + "<svg viewBox=\"0 0 10 10\" width=\"80\" height=\"80\" "
                                                      "filter=\"url(#f)\"><rect x=\"5\" y=\"5\" width=\"5\" "
                                                      "height=\"5\" fill=\"#00ff00\"/></svg>"))
                          .image;
  CHECK(blue(image, 41, 41));
  CHECK(blue(image, 78, 78));
  CHECK(image.at(38, 60).a == 0);  // left of the box: measured without the viewBox it would be x 5..10
  CHECK(image.at(60, 38).a == 0);
  CHECK(image.at(82, 60).a == 0);  // beyond the box (and the viewport)
}

TEST_CASE("nested svg: its x and y move its content's box") {
  const Image image = render(svg_document("width=\"100\" height=\"100\"",
                                          kFloodBox + "<svg x=\"30\" y=\"20\" width=\"50\" height=\"50\" "
                                                      "filter=\"url(#f)\"><rect width=\"10\" height=\"10\" "
                                                      "fill=\"#00ff00\"/></svg>"))
                          .image;
  CHECK(blue(image, 31, 21));
  CHECK(blue(image, 39, 29));
  CHECK(image.at(5, 5).a == 0);    // where the rect would be without x and y
  CHECK(image.at(41, 25).a == 0);  // right of the 10 x 10 box
}

TEST_CASE("symbol under use: an objectBoundingBox filter region follows the use's size and the viewBox") {
  // The use's width and height (60 x 60) override the symbol's; viewBox 0 0 10 10 scales by 6, and the
  // use's x and y place it at (20, 20): the rect (0, 5, 5, 5) covers x 20..50, y 50..80.
  const Image image =
      render(svg_document("width=\"100\" height=\"100\"",
                          kFloodBox + "<symbol id=\"s\" viewBox=\"0 0 10 10\" filter=\"url(#f)\">"
                                      "<rect y=\"5\" width=\"5\" height=\"5\" fill=\"#00ff00\"/>"
                                      "</symbol><use href=\"#s\" x=\"20\" y=\"20\" width=\"60\" "
                                      "height=\"60\"/>"))
          .image;
  CHECK(blue(image, 21, 51));
  CHECK(blue(image, 48, 78));
  CHECK(image.at(52, 60).a == 0);
  CHECK(image.at(30, 48).a == 0);
}

TEST_CASE("use of a symbol: a mask in objectBoundingBox units on the use measures the mapped content") {
  // The mask's white rect covers the left half of the use's box; the box is the symbol's content mapped
  // by its viewBox (x 20..80), so the mask shows x 20..50 and hides 50..80.
  const Image image = render(svg_document("width=\"100\" height=\"100\"",
                                          "<mask id=\"m\" maskContentUnits=\"objectBoundingBox\"><rect "
                                          "width=\"0.5\" height=\"1\" fill=\"white\"/></mask>"
                                          "<symbol id=\"s\" viewBox=\"0 0 10 10\"><rect width=\"10\" "
                                          "height=\"10\" fill=\"#00ff00\"/></symbol>"
                                          "<use href=\"#s\" x=\"20\" y=\"20\" width=\"60\" height=\"60\" "
                                          "mask=\"url(#m)\"/>"))
                          .image;
  CHECK(image.at(30, 50).a == 255);
  CHECK(image.at(70, 50).a == 0);
}
