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

// Regression: `overflow="inherit"` on a <marker> whose parent is the root <svg> clipped the marker, as if
// the user agent's `hidden` were the root's value. The root is `svg:root`, which the user agent's sheet
// (SVG 2 appendix A, `svg:not(:root), marker, ... { overflow: hidden }`) leaves at the initial `visible`,
// so the marker inherits `visible`; under a nested <svg> it inherits that viewport's `hidden`.
TEST_CASE(
    "overflow inherit reads the parent's computed value: visible under the root, hidden under a nested svg") {
  // A 2 x 2 marker viewport at the start of a path from (20, 20); its content, a circle of radius 8 about
  // the reference point, shows beyond 1 px of the vertex only when the marker does not clip.
  const std::string marker =
      "<marker id=\"m\" markerWidth=\"2\" markerHeight=\"2\" refX=\"1\" refY=\"1\" "
      "markerUnits=\"userSpaceOnUse\" overflow=\"inherit\">"
      "<circle cx=\"1\" cy=\"1\" r=\"8\" fill=\"#00ff00\"/></marker>";
  const std::string path = "<path d=\"M20 20 L60 20\" stroke=\"none\" marker-start=\"url(#m)\"/>";
  const Image under_root = render(svg_document("width=\"80\" height=\"80\"", marker + path)).image;
  CHECK(under_root.at(20, 25).a == 255);  // 5 px below the vertex, inside the circle
  // The same marker inside a nested <svg> (overflow hidden by the user agent's sheet) inherits hidden.
  const Image under_nested =
      render(svg_document("width=\"80\" height=\"80\"",
                          "<svg width=\"80\" height=\"80\">" + marker + path + "</svg>"))
          .image;
  CHECK(under_nested.at(20, 20).a > 0);   // the 2 x 2 viewport about the vertex still draws
  CHECK(under_nested.at(20, 25).a == 0);  // clipped
  // `initial` is the property's initial value, visible, not the user agent's hidden (CSS Cascade 4 7.3.1).
  std::string initial = marker;
  initial.replace(initial.find("inherit"), 7, "initial");
  CHECK(render(svg_document("width=\"80\" height=\"80\"",
                            "<svg width=\"80\" height=\"80\">" + initial + path + "</svg>"))
            .image.at(20, 25)
            .a == 255);
}
