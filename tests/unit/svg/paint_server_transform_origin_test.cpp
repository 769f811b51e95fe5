// transform-origin on gradients and patterns: SVG 2 makes gradientTransform and patternTransform
// presentation attributes of the transform property (13.2.2, 13.3), so transform-origin (CSS Transforms
// 1, 6.1, transform-box view-box: percentages and keywords of the viewport) moves the point they act
// about. The oracle is the definition itself: T about origin o is translate(o) T translate(-o), written
// out in the attribute of an otherwise identical document, which must render to the same pixels.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

std::string gradient(const std::string& attributes) {
  return svg_document(
      "width=\"100\" height=\"80\"",
      "<linearGradient id=\"g\" gradientUnits=\"userSpaceOnUse\" x1=\"0\" x2=\"50\" " + attributes +
          "><stop offset=\"0\" stop-color=\"#ff0000\"/><stop offset=\"1\" stop-color=\"#0000ff\"/>"
          "</linearGradient><rect width=\"100\" height=\"80\" fill=\"url(#g)\"/>");
}

std::string pattern(const std::string& attributes) {
  return svg_document("width=\"100\" height=\"80\"",
                      "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"20\" height=\"20\" " +
                          attributes +
                          "><rect width=\"10\" height=\"10\" fill=\"#008000\"/></pattern>"
                          "<rect width=\"100\" height=\"80\" fill=\"url(#p)\"/>");
}

}  // namespace

TEST_CASE("transform-origin moves the point gradientTransform and patternTransform act about") {
  // center of the 100 x 80 viewport: (50, 40); "25% 10px": (25, 10).
  const Image about_center =
      render(gradient("gradientTransform=\"scale(2) rotate(30)\" transform-origin=\"center\"")).image;
  const Image written_out =
      render(gradient("gradientTransform=\"translate(50 40) scale(2) rotate(30) translate(-50 -40)\"")).image;
  CHECK(max_delta(about_center, written_out) == 0);
  const Image unmoved = render(gradient("gradientTransform=\"scale(2) rotate(30)\"")).image;
  CHECK(max_delta(about_center, unmoved) > 0);  // the origin matters here

  const RenderedDocument styled =
      render(pattern("patternTransform=\"rotate(45)\" style=\"transform-origin: 25% 10px\""));
  const Image pattern_written =
      render(pattern("patternTransform=\"translate(25 10) rotate(45) translate(-25 -10)\"")).image;
  CHECK(max_delta(styled.image, pattern_written) == 0);
  CHECK(styled.warnings.empty());

  // An invalid origin is ignored with a warning: the transform acts about (0, 0).
  const RenderedDocument invalid =
      render(gradient("gradientTransform=\"scale(2)\" transform-origin=\"sideways\""));
  CHECK(max_delta(invalid.image, render(gradient("gradientTransform=\"scale(2)\"")).image) == 0);
  CHECK(contains(invalid.warnings, "transform-origin"));
}
