// <a> outside text (SVG 2 16.3.1, SVG 1.1 17.1): a container drawn as <g> is, wherever a <g> may stand —
// the document, a <switch>, a <pattern>, a <mask>, a <marker>, a <symbol> drawn by <use>, another <a> —
// with its own transform, opacity and inherited properties; its link is not followed. Whole-pixel
// rectangles on a transparent canvas, so every expected colour is exact.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

const Rgba8 kGreen{0, 128, 0, 255};

const std::string kSquare = "<rect width=\"10\" height=\"10\"/>";

}  // namespace

TEST_CASE("<a> is a group: inherited paint, transform, opacity, nesting — the link is not followed",
          "[svg][a]") {
  // fill inherits from the <a>, its transform moves the square to the lower right quadrant.
  const RenderedDocument moved =
      render_square(20, "<a href=\"https://example.org/\" fill=\"green\" transform=\"translate(10 10)\">" +
                            kSquare + "</a>");
  CHECK(moved.image.at(15, 15) == kGreen);
  CHECK(moved.image.at(5, 5) == Rgba8{});
  CHECK(moved.warnings.empty());
  // opacity applies to the <a> as a group: two overlapping opaque squares at 50 % show one layer, not two
  // (green 128 at alpha 0.5: premultiplied 64, alpha 128; a per-shape opacity would make the overlap darker).
  const RenderedDocument group = render_square(
      20, "<a opacity=\"0.5\" fill=\"green\">" + kSquare + "<rect x=\"5\" width=\"10\" height=\"10\"/></a>");
  CHECK(group.image.at(7, 5) == group.image.at(2, 5));
  CHECK(group.image.at(2, 5).a == 128);
  // Nested <a> elements (invalid in HTML, harmless in SVG) are groups too.
  CHECK(render_square(20, "<a fill=\"green\"><a transform=\"translate(10 0)\">" + kSquare + "</a></a>")
            .image.at(15, 5) == kGreen);
  // display="none" on the <a> hides its content.
  CHECK(render_square(20, "<a display=\"none\" fill=\"red\">" + kSquare + "</a>").image.at(5, 5) == Rgba8{});
}

TEST_CASE("<a> anywhere a group may be: switch, pattern, mask, marker, symbol", "[svg][a]") {
  // Chosen by a <switch> as its first child whose conditions hold.
  CHECK(render_square(20, "<switch><a fill=\"green\">" + kSquare +
                              "</a><rect width=\"20\" height=\"20\" fill=\"red\"/></switch>")
            .image.at(5, 5) == kGreen);
  // In a pattern's tile (10 x 10, the <a>'s square filling it): the whole area is green.
  CHECK(
      render_square(
          20,
          "<pattern id=\"p\" width=\"10\" height=\"10\" patternUnits=\"userSpaceOnUse\"><a fill=\"green\">" +
              kSquare + "</a></pattern><rect width=\"20\" height=\"20\" fill=\"url(#p)\"/>")
          .image.at(15, 15) == kGreen);
  // In a mask: a white <a> square lets the left half through.
  const RenderedDocument masked = render_square(
      20,
      "<mask id=\"m\" maskUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"20\" height=\"20\"><a "
      "fill=\"white\">"
      "<rect width=\"10\" height=\"20\"/></a></mask><rect width=\"20\" height=\"20\" fill=\"green\" "
      "mask=\"url(#m)\"/>");
  CHECK(masked.image.at(5, 5) == kGreen);
  CHECK(masked.image.at(15, 5) == Rgba8{});
  // In a marker, at the start of a line: a 10 x 10 green square with its corner at the vertex.
  CHECK(
      render_square(20,
                    "<marker id=\"k\" markerUnits=\"userSpaceOnUse\" markerWidth=\"10\" markerHeight=\"10\" "
                    "overflow=\"visible\"><a fill=\"green\">" +
                        kSquare +
                        "</a></marker>"
                        "<path d=\"M 10 10 H 20\" stroke=\"none\" marker-start=\"url(#k)\"/>")
          .image.at(15, 15) == kGreen);
  // In a symbol drawn by <use>.
  CHECK(render_square(
            20, "<symbol id=\"s\"><a fill=\"green\">" + kSquare + "</a></symbol><use href=\"#s\" x=\"10\"/>")
            .image.at(15, 5) == kGreen);
}
