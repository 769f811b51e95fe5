// x, y, width and height of <svg>, <symbol> and <use> set by style sheets: SVG 2 9.1.1 makes them
// geometry properties of these elements, so a declaration beats the attribute, and an invalid one falls
// back to the attribute (CSS Cascade 4 4.1: invalid declarations are not part of the cascade).
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

TEST_CASE("nested svg: x, y, width and height from a style sheet beat the attributes") {
  // The attributes would put a 10 x 10 viewport at (0, 0); the sheet moves it to (40, 20) and makes it
  // 30 x 30, with a viewBox of 10 x 10 that the green square fills.
  const std::string body =
      "<style>#v { x: 40px; y: 20px; width: 30px; height: 30px }</style>"
      "<svg id=\"v\" x=\"0\" y=\"0\" width=\"10\" height=\"10\" viewBox=\"0 0 10 10\">"
      "<rect width=\"10\" height=\"10\" fill=\"#00ff00\"/></svg>";
  const Image image = render(svg_document("width=\"80\" height=\"60\"", body)).image;
  CHECK(image.at(5, 5).a == 0);      // the attributes' place stays empty
  CHECK(image.at(41, 21).g == 255);  // the viewport's corners, scaled 3x
  CHECK(image.at(68, 48).g == 255);
  CHECK(image.at(72, 52).a == 0);
}

TEST_CASE("use: x, y, width and height from a style sheet, an invalid declaration falls back") {
  const std::string defs =
      "<symbol id=\"s\" viewBox=\"0 0 10 10\"><rect width=\"10\" height=\"10\" fill=\"#00ff00\"/></symbol>";
  // The sheet places the symbol at (30, 10) at 20 x 20; the attributes would give (0, 0) at 10 x 10.
  const Image placed =
      render(svg_document("width=\"60\" height=\"40\"",
                          defs + "<style>use { x: 30px; y: 10px; width: 20px; height: 20px }</style>"
                                 "<use href=\"#s\" x=\"0\" y=\"0\" width=\"10\" height=\"10\"/>"))
          .image;
  CHECK(placed.at(5, 5).a == 0);
  CHECK(placed.at(31, 11).g == 255);
  CHECK(placed.at(48, 28).g == 255);
  CHECK(placed.at(52, 32).a == 0);
  // width: -5px is invalid (negative): the attribute's 10 stays; x: 30px still applies.
  const RenderedDocument fallback = render(
      svg_document("width=\"60\" height=\"40\"", defs + "<style>use { x: 30px; width: -5px }</style>"
                                                        "<use href=\"#s\" width=\"10\" height=\"10\"/>"));
  CHECK(fallback.image.at(35, 5).g == 255);
  CHECK(fallback.image.at(45, 5).a == 0);
  CHECK(contains(fallback.warnings, "width"));
}
