// The geometry properties of SVG 2 (svg/geometry_properties.h): x, y, width, height, cx, cy, r, rx, ry and
// d set by style sheets and the style attribute, their precedence over the attributes, invalid values
// falling back, and the auto values of rx and ry on rect and ellipse (SVG 2 10.2, 10.4).
//
// Shapes are placed on whole pixels and checked at pixel centres well inside or well outside them,
// where coverage is exactly 1 or 0: no tolerance is needed. Round shapes are checked at centres at least
// one pixel from their outline.
#include "svg/geometry_properties.h"

#include <catch2/catch.hpp>
#include <string>

#include "curvescan/svg/document.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;

using curvescan::svg::testing::contains;

namespace {

/// `body` in a 40 x 10 document, rendered (svg_test_support.h).
RenderedDocument render(const std::string& body) {
  return curvescan::svg::testing::render(curvescan::svg::testing::svg_document("width=\"40\" height=\"10\"", body));
}

bool inked(const Image& image, int x, int y) {
  return image.at(x, y).a == 255;
}
bool blank(const Image& image, int x, int y) {
  return image.at(x, y).a == 0;
}


}  // namespace

TEST_CASE("geometry properties: rect x, y, width and height from a sheet win over the attributes") {
  const RenderedDocument rendered = render(
      "<style>rect { x: 10px; width: 10px } .tall { height: 10px }</style>"
      "<rect class=\"tall\" x=\"30\" width=\"2\" height=\"1\"/>");
  CHECK(inked(rendered.image, 15, 5));
  CHECK(blank(rendered.image, 31, 0));  // the attributes lost
  CHECK(blank(rendered.image, 5, 5));
  CHECK(rendered.warnings.empty());
}

TEST_CASE("geometry properties: the style attribute wins over a sheet, an invalid value falls back") {
  const RenderedDocument rendered = render(
      "<style>#a { width: 10px; height: 10px } #b { width: -5px; x: 20 }</style>"
      "<rect id=\"a\" style=\"x: 30px; width: 5; height: auto\" height=\"3\" y=\"0\"/>"
      "<rect id=\"b\" width=\"10\" height=\"10\" style=\"width: 12km\"/>");
  // #a: x 30 and width 5 from the style attribute; height auto is 0 for a rect: nothing drawn.
  CHECK(blank(rendered.image, 32, 1));
  // #b: the style attribute's width is invalid, so is the sheet's -5px: the attribute's 10 applies.
  CHECK(inked(rendered.image, 25, 5));
  CHECK(blank(rendered.image, 19, 5));
  CHECK(contains(rendered.warnings, "<rect> ignoring invalid value '-5px' of property 'width': negative"));
  CHECK(contains(rendered.warnings, "ignoring invalid value '12km' of property 'width'"));
}

TEST_CASE("geometry properties: circle and ellipse centres and radii, initial and inherit") {
  const RenderedDocument rendered = render(
      "<style>circle { cx: 5px; cy: 5px; r: 4px } .e { cx: 25px; rx: 4px; ry: 4px }"
      " .z { r: initial } g { x: 30px } .i { x: inherit }</style>"
      "<circle r=\"1\"/><g transform=\"translate(0 0)\"><ellipse class=\"e\" cy=\"5\"/></g>"
      "<circle class=\"z\" cx=\"15\" cy=\"5\" r=\"4\"/>"
      "<g><rect class=\"i\" width=\"10\" height=\"10\"/></g>");
  CHECK(inked(rendered.image, 5, 5));
  CHECK(inked(rendered.image, 7, 5));  // r 4 from the sheet, not the attribute's 1
  CHECK(inked(rendered.image, 25, 5));
  CHECK(inked(rendered.image, 27, 5));
  CHECK(blank(rendered.image, 15, 5));  // r: initial is 0: not rendered
  CHECK(inked(rendered.image, 35, 5));  // x inherited from the <g>'s declared 30px
  // In an attribute a CSS-wide keyword is invalid: x="inherit" is the initial 0, with a warning.
  const RenderedDocument attribute =
      render("<g x=\"20\"><rect x=\"inherit\" width=\"10\" height=\"10\"/></g>");
  CHECK(inked(attribute.image, 5, 5));
  CHECK(blank(attribute.image, 25, 5));
  CHECK(contains(attribute.warnings, "ignoring invalid value 'inherit' of property 'x'"));
}

TEST_CASE("geometry properties: d from path() in a sheet, none, and the attribute's path data") {
  const RenderedDocument rendered = render(
      "<style>#p { d: path(\"M0 0 H10 V10 H0 Z\") } #q { d: none } #r { d: path('M20,0h10v10h-10z') }"
      " #s { d: M30 0 }</style>"
      "<path id=\"p\" d=\"M10 0 h1 v1 z\"/><path id=\"q\" d=\"M10 0 H20 V10 H10 Z\"/><path id=\"r\"/>"
      "<path id=\"s\" d=\"M30 0 H40 V10 H30 Z\"/>");
  CHECK(inked(rendered.image, 5, 5));
  CHECK(blank(rendered.image, 10, 0));  // the attribute's path lost to the sheet's
  CHECK(blank(rendered.image, 15, 5));  // d: none
  CHECK(inked(rendered.image, 25, 5));  // single quotes
  CHECK(inked(rendered.image, 35, 5));  // not a path(): invalid in CSS, the attribute applies
  CHECK(contains(rendered.warnings, "ignoring invalid value 'M30 0' of property 'd'"));
}

TEST_CASE("geometry properties: the path() function's string, escapes and fill rule") {
  using detail::css_path_function;
  CHECK(css_path_function("path(\"M0 0\")") == std::optional<std::string>("M0 0"));
  CHECK(css_path_function("PATH( 'M0 0' )") == std::optional<std::string>("M0 0"));
  CHECK(css_path_function("path(evenodd, \"M0 0\")") == std::optional<std::string>("M0 0"));
  CHECK(css_path_function("path(\"M0 \\\"0\")") == std::optional<std::string>("M0 \"0"));
  CHECK_FALSE(css_path_function("path(M0 0)"));
  CHECK_FALSE(css_path_function("path(\"M0 0\" \"L1 1\")"));
  CHECK_FALSE(css_path_function("url(\"M0 0\")"));
  CHECK_FALSE(css_path_function("path(\"M0 0\""));
}

TEST_CASE("ellipse: rx or ry auto, missing, empty or negative takes the other's value (SVG 2 10.4)") {
  // Each ellipse is a circle of radius 4 about the centre of its square when the rule holds; the
  // checks sit at the pixels 2 px right of and below the centre (inside: their far corners are 3.2 px from
  // it) and at the square's corner (outside).
  const RenderedDocument rendered = render(
      "<ellipse cx=\"5\" cy=\"5\" rx=\"auto\" ry=\"4\"/><ellipse cx=\"15\" cy=\"5\" rx=\"4\"/>"
      "<ellipse cx=\"25\" cy=\"5\" rx=\"4\" ry=\"\"/><ellipse cx=\"35\" cy=\"5\" rx=\"-2\" ry=\"4\"/>");
  for (int i = 0; i < 4; ++i) {
    INFO("ellipse " << i);
    CHECK(inked(rendered.image, 10 * i + 5, 5));
    CHECK(inked(rendered.image, 10 * i + 7, 5));
    CHECK(inked(rendered.image, 10 * i + 5, 7));
    CHECK(blank(rendered.image, 10 * i, 0));
  }
  CHECK(contains(rendered.warnings, "ignoring invalid value '-2' of property 'rx': negative"));
  // Both auto: 0, nothing drawn.
  const RenderedDocument none =
      render("<ellipse cx=\"5\" cy=\"5\" rx=\"auto\"/><ellipse cx=\"15\" cy=\"5\"/>");
  CHECK(blank(none.image, 5, 5));
  CHECK(blank(none.image, 15, 5));
}

TEST_CASE("rect: rx and ry auto, negative or from a sheet (SVG 2 10.2)") {
  // A 10 x 10 square with corner radius 5 is a circle: its corner pixel (0, 0) is blank, (1, 1) covers
  // part of the arc, the centre is inked. Radius 0 leaves the corner inked.
  const RenderedDocument rendered = render(
      "<style>.s { rx: 5px }</style>"
      "<rect width=\"10\" height=\"10\" rx=\"auto\" ry=\"5\"/>"
      "<rect x=\"10\" width=\"10\" height=\"10\" rx=\"-1\" ry=\"5\"/>"
      "<rect x=\"20\" width=\"10\" height=\"10\" class=\"s\" rx=\"0\"/>"
      "<rect x=\"30\" width=\"10\" height=\"10\" rx=\"auto\" ry=\"auto\"/>");
  for (int i = 0; i < 3; ++i) {
    INFO("rect " << i);
    CHECK(blank(rendered.image, 10 * i, 0));
    CHECK(inked(rendered.image, 10 * i + 5, 5));
  }
  CHECK(inked(rendered.image, 30, 0));  // both auto: square corners
}

TEST_CASE("geometry properties: an image's x, y, width and height from a sheet") {
  // A 10 x 10 green SVG image, percent-encoded; the sheet places it at x 10 with size 10 x 10, over the
  // attributes' 0 and 40 x 40.
  const std::string image =
      "data:image/svg+xml,%3Csvg xmlns='http://www.w3.org/2000/svg' width='10' height='10'%3E"
      "%3Crect width='10' height='10' fill='%23008000'/%3E%3C/svg%3E";
  const RenderedDocument rendered = render("<style>image { x: 10px; width: 10px; height: 10px }</style>"
                                           "<image width=\"40\" height=\"40\" href=\"" +
                                           image + "\"/>");
  CHECK(inked(rendered.image, 15, 5));
  CHECK(blank(rendered.image, 5, 5));
  CHECK(blank(rendered.image, 25, 5));
}
