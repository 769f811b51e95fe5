// overflow on a nested <svg> and on a <symbol> instanced by <use> (SVG 2 14.3.3, "overflow"): hidden (the
// default for elements that establish a viewport) clips the content to the viewport; visible and auto
// (which SVG 2 treats as visible) do not.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

// A 40 x 40 viewport at (10, 10) whose content, a 60 x 60 square from its origin, overflows it to 70.
std::string nested(const std::string& overflow) {
  return svg_document("width=\"80\" height=\"80\"",
                      "<svg x=\"10\" y=\"10\" width=\"40\" height=\"40\"" + overflow +
                          "><rect width=\"60\" height=\"60\" fill=\"#00ff00\"/></svg>");
}

std::string symbol(const std::string& overflow) {
  return svg_document("width=\"80\" height=\"80\"",
                      "<symbol id=\"s\"" + overflow +
                          "><rect width=\"60\" height=\"60\" fill=\"#00ff00\"/></symbol>"
                          "<use href=\"#s\" x=\"10\" y=\"10\" width=\"40\" height=\"40\"/>");
}

}  // namespace

TEST_CASE("nested svg and symbol: overflow hidden clips to the viewport, visible and auto do not") {
  for (const auto& make : {nested, symbol}) {
    // Pixel (60, 60) lies inside the square and outside the viewport; (30, 30) inside both.
    const Image hidden = render(make("")).image;
    CHECK(hidden.at(30, 30).a == 255);
    CHECK(hidden.at(60, 60).a == 0);
    CHECK(render(make(" overflow=\"hidden\"")).image.at(60, 60).a == 0);
    CHECK(render(make(" style=\"overflow: scroll\"")).image.at(60, 60).a == 0);
    for (const std::string visible :
         {" overflow=\"visible\"", " overflow=\"auto\"", " style=\"overflow:visible\""}) {
      INFO(visible);
      const Image image = render(make(visible)).image;
      CHECK(image.at(60, 60).a == 255);
      CHECK(image.at(75, 75).a == 0);  // the square ends at 70
    }
  }
}
