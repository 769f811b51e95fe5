// Gradients and the shape's bounding box (svg/paint_server.h): objectBoundingBox units on a shape whose
// box has no width or no height (a horizontal or vertical line) cannot be used (SVG 1.1 7.11, SVG 2
// 8.11: the effect is ignored), so the paint falls back to the fallback colour of the fill or stroke
// value, or to none without one -- as rsvg-convert 2.54 and resvg draw it. And the SVG 1.1 focal-point
// rule: a focal point outside the end circle is moved onto it along the same ray (13.2.3).
//
// Colours are read at pixel centres inside 10 px wide strokes of whole-pixel lines, where coverage is
// exactly 1: no tolerance is needed.
#include <catch2/catch.hpp>
#include <string>

#include "curvescan/svg/document.h"

using namespace curvescan;
using namespace curvescan::svg;

namespace {

RenderedDocument render(const std::string& body, int width = 40) {
  const std::string text = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + std::to_string(width) +
                           "\" height=\"10\">" + body + "</svg>";
  Result<RenderedDocument> rendered = render_svg_document(text, {});
  INFO(text);
  REQUIRE(rendered.is_ok());
  return std::move(rendered).value();
}

std::string colour(const Image& image, int x, int y) {
  const Rgba8 pixel = image.at(x, y);
  if (pixel.a == 0) return "none";
  char text[16];
  std::snprintf(text, sizeof text, "#%02x%02x%02x/%d", pixel.r, pixel.g, pixel.b, pixel.a);
  return text;
}

}  // namespace

TEST_CASE("gradient on a box without area: the fallback colour, else nothing") {
  const RenderedDocument rendered = render(
      "<linearGradient id=\"g\"><stop stop-color=\"#ff0000\"/><stop offset=\"1\" stop-color=\"#ff1100\"/>"
      "</linearGradient>"
      "<radialGradient id=\"r\"><stop stop-color=\"#ff0000\"/></radialGradient>"
      "<linearGradient id=\"u\" gradientUnits=\"userSpaceOnUse\" x2=\"40\"><stop stop-color=\"#0000ff\"/>"
      "<stop offset=\"1\" stop-color=\"#0000ff\"/></linearGradient>"
      "<line x1=\"0\" y1=\"5\" x2=\"10\" y2=\"5\" stroke=\"url(#g)\" stroke-width=\"10\"/>"
      "<line x1=\"10\" y1=\"5\" x2=\"20\" y2=\"5\" stroke=\"url(#g) #008000\" stroke-width=\"10\"/>"
      "<line x1=\"25\" y1=\"0\" x2=\"25\" y2=\"10\" stroke=\"url(#r) currentColor\" color=\"#008000\""
      " stroke-width=\"10\"/>"
      "<line x1=\"30\" y1=\"5\" x2=\"40\" y2=\"5\" stroke=\"url(#u) #ff0000\" stroke-width=\"10\"/>");
  CHECK(colour(rendered.image, 5, 5) == "none");
  CHECK(colour(rendered.image, 15, 5) == "#008000/255");
  CHECK(colour(rendered.image, 25, 5) == "#008000/255");
  CHECK(colour(rendered.image, 35, 5) == "#0000ff/255");  // user space: the box does not matter
  CHECK(rendered.warnings.empty());
}

TEST_CASE("radial gradient: a focal point outside the circle draws as the point on the circle") {
  // r 0.5 about the centre of the box; fx 3 is far outside to the right, fx 1 is on the circle: both
  // are moved to the same point (kFocalClampRatio inside the circle), so the images are identical.
  const std::string shape = "<rect width=\"40\" height=\"10\" fill=\"url(#g)\"/>";
  const auto gradient = [](const std::string& fx) {
    return "<radialGradient id=\"g\" fx=\"" + fx +
           "\" fy=\"0.5\"><stop stop-color=\"#ffff00\"/>"
           "<stop offset=\"1\" stop-color=\"#003366\"/></radialGradient>";
  };
  const RenderedDocument outside = render(gradient("3") + shape);
  const RenderedDocument on_circle = render(gradient("1") + shape);
  const RenderedDocument inside = render(gradient("0.6") + shape);
  CHECK(outside.image.pixels() == on_circle.image.pixels());
  CHECK(outside.image.pixels() != inside.image.pixels());  // the comparison can fail
}

TEST_CASE("gradient stops: currentColor and inherit resolve along the stop's own ancestors (regression)") {
  // SVG 1.1 13.2.4: stops inherit from the gradient and its ancestors, never from the painted shape.
  // One-colour gradients (two equal stops) paint a solid colour, exact at any pixel.
  const RenderedDocument rendered = render(
      "<linearGradient id=\"a\" color=\"#008000\"><stop stop-color=\"currentColor\"/>"
      "<stop offset=\"1\" stop-color=\"currentColor\"/></linearGradient>"
      "<g color=\"#0000ff\"><defs><linearGradient id=\"b\"><stop stop-color=\"currentColor\"/>"
      "<stop offset=\"1\" style=\"stop-color: currentColor\"/></linearGradient></defs></g>"
      "<linearGradient id=\"c\" stop-color=\"#008000\" stop-opacity=\"0.5\"><stop stop-color=\"inherit\""
      " stop-opacity=\"inherit\"/><stop offset=\"1\" stop-color=\"inherit\" stop-opacity=\"inherit\"/>"
      "</linearGradient>"
      "<linearGradient id=\"d\"><stop stop-color=\"inherit\"/><stop offset=\"1\" stop-color=\"inherit\"/>"
      "</linearGradient>"
      "<g color=\"#ff0000\"><rect width=\"10\" height=\"10\" fill=\"url(#a)\"/>"
      "<rect x=\"10\" width=\"10\" height=\"10\" fill=\"url(#b)\"/>"
      "<rect x=\"20\" width=\"10\" height=\"10\" fill=\"url(#c)\"/>"
      "<rect x=\"30\" width=\"10\" height=\"10\" fill=\"url(#d)\" stop-color=\"#ff0000\"/></g>");
  CHECK(colour(rendered.image, 5, 5) == "#008000/255");
  CHECK(colour(rendered.image, 15, 5) == "#0000ff/255");
  // 0.5 alpha: 127.5 rounds to 128; Image holds premultiplied colour, 128 x 0.5 = 64 (0x40).
  CHECK(colour(rendered.image, 25, 5) == "#004000/128");
  CHECK(colour(rendered.image, 35, 5) == "#000000/255");  // the gradient's own stop-color: initial black
}

TEST_CASE("radial gradient: a negative r or fr is read as 0, with a warning") {
  const RenderedDocument rendered = render(
      "<radialGradient id=\"r\" r=\"-1\"><stop stop-color=\"#000000\"/><stop offset=\"1\" "
      "stop-color=\"#008000\"/>"
      "</radialGradient>"
      "<radialGradient id=\"f\" fr=\"-1\" r=\"0\"><stop stop-color=\"#000000\"/>"
      "<stop offset=\"1\" stop-color=\"#0000ff\"/></radialGradient>"
      "<rect width=\"10\" height=\"10\" fill=\"url(#r)\"/><rect x=\"10\" width=\"10\" height=\"10\" "
      "fill=\"url(#f)\"/>");
  CHECK(colour(rendered.image, 5, 5) == "#008000/255");   // r 0: the last stop's colour
  CHECK(colour(rendered.image, 15, 5) == "#0000ff/255");  // fr 0 (and r 0): the same rule
  CHECK(!rendered.warnings.empty());
}

TEST_CASE("gradients: geometry attributes inherit only from the same kind, a singular transform is ignored") {
  // A radialGradient naming a linearGradient takes its spreadMethod and stops' absence, not its cx
  // (a linearGradient has none): cx stays 50 %, so the gradient is symmetric about the box's centre.
  const RenderedDocument rendered = render(
      "<linearGradient id=\"l\" cx=\"1\" spreadMethod=\"reflect\"/>"
      "<radialGradient id=\"r\" href=\"#l\"><stop stop-color=\"#ffffff\"/><stop offset=\"1\" "
      "stop-color=\"#000000\"/>"
      "</radialGradient>"
      "<linearGradient id=\"s\" gradientTransform=\"matrix(0 0 0 0 0 0)\"><stop stop-color=\"#ffffff\"/>"
      "<stop offset=\"1\" stop-color=\"#000000\"/></linearGradient>"
      "<rect width=\"20\" height=\"10\" fill=\"url(#r)\"/><rect x=\"20\" width=\"20\" height=\"10\" "
      "fill=\"url(#s)\"/>",
      40);
  // Mirror pixels about x = 10 are equal (the centre is at 50 %); with cx = 1 they would not be.
  for (int x = 0; x < 10; ++x) CHECK(colour(rendered.image, x, 5) == colour(rendered.image, 19 - x, 5));
  CHECK(colour(rendered.image, 0, 5) != colour(rendered.image, 10, 5));
  // The singular transform is ignored: the identity's gradient runs white to black left to right.
  const Rgba8 left = rendered.image.at(20, 5), right = rendered.image.at(39, 5);
  CHECK(left.r > right.r);
  CHECK(left.a == 255);
}
