// context-fill and context-stroke with a gradient or pattern: SVG 2 13.4.1 draws the paint server in
// the context element's coordinate space and with its bounding box, so the shapes that take it show one
// continuous paint, not one paint per shape. The oracle: the same area filled directly by the context
// element's paint in one piece must render to the same pixels.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

const std::string kServers =
    "<linearGradient id=\"g\"><stop offset=\"0\" stop-color=\"#ff0000\"/><stop offset=\"1\" "
    "stop-color=\"#0000ff\"/></linearGradient>"
    "<pattern id=\"p\" width=\"0.125\" height=\"0.5\"><rect width=\"6\" height=\"5\" "
    "fill=\"#008000\"/></pattern>";

// Two halves of the 100 x 20 box at (0, 10) taking the <use>'s paint: the right one placed by its own
// transform, so that its user space differs from the <use>'s. They meet on a pixel boundary, where
// exact-area coverage leaves no seam.
std::string halves(const std::string& paint, const std::string& use_transform) {
  return svg_document(
      "width=\"120\" height=\"40\"",
      kServers +
          "<defs><g id=\"halves\"><rect x=\"0\" y=\"10\" width=\"50\" height=\"20\" fill=\"context-fill\"/>"
          "<rect transform=\"translate(50 10)\" width=\"50\" height=\"20\" fill=\"context-fill\"/></g></defs>"
          "<use href=\"#halves\" fill=\"" +
          paint + "\" transform=\"" + use_transform + "\"/>");
}

std::string whole(const std::string& paint, const std::string& use_transform) {
  return svg_document("width=\"120\" height=\"40\"",
                      kServers + "<rect x=\"0\" y=\"10\" width=\"100\" height=\"20\" fill=\"" + paint +
                          "\" transform=\"" + use_transform + "\"/>");
}

}  // namespace

TEST_CASE("context-fill: a gradient or pattern of a use spans its box, whatever each shape's transform") {
  for (const std::string paint : {"url(#g)", "url(#p)"}) {
    for (const std::string transform : {"translate(10 0)", "translate(10 0) scale(1.1 1)"}) {
      INFO(paint << " " << transform);
      const Image split = render(halves(paint, transform)).image;
      const Image one = render(whole(paint, transform)).image;
      // The scaled case puts the seam at x = 65 exactly, a pixel boundary again.
      CHECK(max_delta(split, one) == 0);
    }
  }
}

TEST_CASE("context-stroke on a marker: the marked path's gradient, in its space and box") {
  // The marker draws a 10 x 10 square centred on the path's end (90, 30) with context-stroke; the
  // path's gradient runs over the path's box (x 10 to 90; a box with height, or objectBoundingBox would
  // refuse it), not over the square's.
  const RenderedDocument rendered = render(svg_document(
      "width=\"100\" height=\"40\"",
      kServers +
          "<marker id=\"m\" markerUnits=\"userSpaceOnUse\" markerWidth=\"20\" markerHeight=\"20\" "
          "refX=\"10\" "
          "refY=\"10\" overflow=\"visible\"><rect x=\"5\" y=\"5\" width=\"10\" height=\"10\" "
          "fill=\"context-stroke\"/></marker>"
          "<path d=\"M 10 10 L 90 30\" stroke=\"url(#g)\" stroke-width=\"2\" marker-end=\"url(#m)\"/>"));
  const Rgba8 pixel = rendered.image.at(85, 33);  // in the marker's square, below the stroke
  CHECK(pixel.a == 255);
  // x = 85.5 (the pixel's centre) is 75.5/80 of the way along the path's box; the square's own box
  // would put it at 0.05.
  // Straight interpolation of 8-bit stops in sRGB; 1 level of rounding either way.
  CHECK(std::abs(pixel.b - static_cast<int>(255.0 * 75.5 / 80.0 + 0.5)) <= 1);
  CHECK(std::abs(pixel.r - static_cast<int>(255.0 * 4.5 / 80.0 + 0.5)) <= 1);
}
