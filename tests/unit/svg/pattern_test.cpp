// <pattern> (SVG 1.1 13.3). The scenes put every tile edge on whole device pixels, so the tile image
// maps onto the canvas pixel for pixel and bilinear sampling returns the tile's own pixels (a pixel
// centre maps onto a texel centre: weights 1, 0): exact values.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

const Rgba8 kGreen{0, 128, 0, 255};
const Rgba8 kBlue{0, 0, 255, 255};

// A 10 x 10 tile: green top-left quarter, blue bottom-right quarter, transparent elsewhere.
const std::string kQuarters =
    "<rect width=\"5\" height=\"5\" fill=\"green\"/><rect x=\"5\" y=\"5\" width=\"5\" height=\"5\" "
    "fill=\"blue\"/>";

}  // namespace

TEST_CASE("pattern: userSpaceOnUse tiles repeat with their period, as fill and as stroke", "[svg][pattern]") {
  const RenderedDocument doc =
      render_square(40, "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"10\" height=\"10\">" +
                            kQuarters + "</pattern><rect width=\"40\" height=\"40\" fill=\"url(#p)\"/>");
  CHECK(doc.image.at(2, 2) == kGreen);
  CHECK(doc.image.at(7, 7) == kBlue);
  CHECK(doc.image.at(7, 2) == Rgba8{});
  CHECK(doc.image.at(32, 22) == kGreen);  // the fourth column, third row of tiles
  CHECK(doc.image.at(37, 37) == kBlue);
  CHECK(doc.warnings.empty());
  const RenderedDocument stroked = render_square(
      40, "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"10\" height=\"10\">" + kQuarters +
              "</pattern><rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" fill=\"none\" "
              "stroke=\"url(#p)\" stroke-width=\"10\"/>");
  CHECK(stroked.image.at(7, 7) == kBlue);      // in the stroke, in pattern space (not shifted by the shape)
  CHECK(stroked.image.at(22, 22) == Rgba8{});  // inside the stroke's hole (15..25)
  CHECK(stroked.image.at(32, 32) == kGreen);   // in the stroke (its extent is 5..35)
  CHECK(stroked.image.at(37, 37) == Rgba8{});  // outside it
  CHECK(stroked.image.at(2, 2) == Rgba8{});
}

TEST_CASE("pattern: x and y shift the tiles — objectBoundingBox units — content units — viewBox",
          "[svg][pattern]") {
  const RenderedDocument shifted = render_square(
      40, "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" x=\"5\" width=\"10\" height=\"10\">" +
              kQuarters + "</pattern><rect width=\"40\" height=\"40\" fill=\"url(#p)\"/>");
  CHECK(shifted.image.at(7, 2) == kGreen);   // tiles start at x = 5
  CHECK(shifted.image.at(2, 2) == Rgba8{});  // x 0..5 is the right half of the tile at -5
  CHECK(shifted.image.at(2, 7) == kBlue);
  // Default units: a tile of 0.5 x 0.5 of the box 0..20 is 10 user units; content in user units.
  const RenderedDocument box = render_square(
      40, "<pattern id=\"p\" width=\"0.5\" height=\"50%\">" + kQuarters +
              "</pattern><rect x=\"20\" y=\"20\" width=\"20\" height=\"20\" fill=\"url(#p)\"/>");
  CHECK(box.image.at(22, 22) == kGreen);
  CHECK(box.image.at(37, 37) == kBlue);
  // patternContentUnits=objectBoundingBox: content in fractions of the box (0.25 of 20 = 5).
  const RenderedDocument content = render_square(
      40,
      "<pattern id=\"p\" width=\"0.5\" height=\"0.5\" patternContentUnits=\"objectBoundingBox\">"
      "<rect width=\"0.25\" height=\"0.25\" fill=\"green\"/></pattern>"
      "<rect x=\"20\" y=\"20\" width=\"20\" height=\"20\" fill=\"url(#p)\"/>");
  CHECK(content.image.at(22, 22) == kGreen);
  CHECK(content.image.at(27, 22) == Rgba8{});
  // viewBox 0 0 2 2 onto a 10 x 10 tile: a 1 x 1 rect fills a quarter.
  const RenderedDocument view_box = render_square(
      40,
      "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"10\" height=\"10\" viewBox=\"0 0 2 2\">"
      "<rect width=\"1\" height=\"1\" fill=\"green\"/></pattern><rect width=\"40\" height=\"40\" "
      "fill=\"url(#p)\"/>");
  CHECK(view_box.image.at(4, 4) == kGreen);
  CHECK(view_box.image.at(6, 4) == Rgba8{});
}

TEST_CASE("pattern: patternTransform, href inheritance, nested patterns, opacity", "[svg][pattern]") {
  const RenderedDocument moved =
      render_square(40,
                    "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"10\" height=\"10\" "
                    "patternTransform=\"translate(5 0)\">" +
                        kQuarters + "</pattern><rect width=\"40\" height=\"40\" fill=\"url(#p)\"/>");
  CHECK(moved.image.at(7, 2) == kGreen);
  CHECK(moved.image.at(2, 2) == Rgba8{});
  // Attributes and children both come from the referenced pattern.
  const RenderedDocument inherited = render_square(
      40, "<pattern id=\"base\" patternUnits=\"userSpaceOnUse\" width=\"10\" height=\"10\">" + kQuarters +
              "</pattern><pattern id=\"p\" xlink:href=\"#base\" x=\"5\"/><rect width=\"40\" height=\"40\" "
              "fill=\"url(#p)\"/>");
  CHECK(inherited.image.at(7, 2) == kGreen);
  // A pattern whose content is filled with another pattern.
  const RenderedDocument nested = render_square(
      40,
      "<pattern id=\"inner\" patternUnits=\"userSpaceOnUse\" width=\"2\" height=\"2\">"
      "<rect width=\"1\" height=\"2\" fill=\"green\"/></pattern>"
      "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"10\" height=\"10\">"
      "<rect width=\"5\" height=\"5\" fill=\"url(#inner)\"/></pattern><rect width=\"40\" height=\"40\" "
      "fill=\"url(#p)\"/>");
  CHECK(nested.image.at(0, 1) == kGreen);
  CHECK(nested.image.at(1, 1) == Rgba8{});
  CHECK(nested.image.at(2, 1) == kGreen);
  CHECK(nested.image.at(7, 1) == Rgba8{});
  // fill-opacity 0.5 multiplies the tile by alpha 128.
  const RenderedDocument faded = render_square(
      40, "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"10\" height=\"10\">" + kQuarters +
              "</pattern><rect width=\"40\" height=\"40\" fill=\"url(#p)\" "
              "fill-opacity=\"0.5\"/>");
  CHECK(faded.image.at(7, 7) == Rgba8{0, 0, 128, 128});
}

TEST_CASE("pattern: degenerate and recursive patterns paint nothing", "[svg][pattern]") {
  const std::string target = "<rect width=\"40\" height=\"40\" fill=\"url(#p)\"/>";
  CHECK(render_square(40, "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"0\" height=\"10\">" +
                              kQuarters + "</pattern>" + target)
            .image.at(2, 2) == Rgba8{});
  CHECK(render_square(
            40, "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"10\" height=\"10\"/>" + target)
            .image.at(2, 2) == Rgba8{});
  // A tile that paints itself: the inner reference is none, the outer tile still draws its stroke.
  const RenderedDocument self = render_square(
      40,
      "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"10\" height=\"10\">"
      "<rect width=\"5\" height=\"5\" fill=\"url(#p)\"/><rect x=\"5\" y=\"5\" width=\"5\" height=\"5\" "
      "fill=\"blue\"/>"
      "</pattern>" +
          target);
  CHECK(self.image.at(2, 2) == Rgba8{});
  CHECK(self.image.at(7, 7) == kBlue);
  CHECK(contains(self.warnings, "inside itself"));
  // objectBoundingBox units on a line (a box without height): the fallback colour paints the stroke.
  const RenderedDocument line =
      render_square(40, "<pattern id=\"p\" width=\"1\" height=\"1\">" + kQuarters +
                            "</pattern><line x1=\"0\" y1=\"20\" x2=\"40\" "
                            "y2=\"20\" stroke=\"url(#p) green\" stroke-width=\"4\"/>");
  CHECK(line.image.at(20, 20) == kGreen);
  // A singular patternTransform is ignored.
  CHECK(render_square(40,
                      "<pattern id=\"p\" patternUnits=\"userSpaceOnUse\" width=\"10\" height=\"10\" "
                      "patternTransform=\"scale(0)\">" +
                          kQuarters + "</pattern>" + target)
            .image.at(2, 2) == kGreen);
}
