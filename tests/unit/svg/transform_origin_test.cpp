// transform-origin (CSS Transforms 1, 6.1) on SVG elements: the transform applies about the origin point;
// lengths are user units, percentages and keywords refer to the viewport (transform-box: view-box, the
// initial value for SVG elements). A 10 x 10 red square at the top-left of a 40 x 40 canvas, turned by
// 180 degrees: whole pixels, exact colours.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

const Rgba8 kRed{255, 0, 0, 255};

// Where the square lands: the centre pixel of each 10 x 10 quadrant cell that is red.
bool red_at(const RenderedDocument& r, int x, int y) { return r.image.at(x, y) == kRed; }

RenderedDocument square(const std::string& attributes) {
  return render(svg_document("width=\"40\" height=\"40\"",
                             "<rect width=\"10\" height=\"10\" fill=\"red\" transform=\"rotate(180)\" " + attributes +
                                 "/>"));
}

}  // namespace

TEST_CASE("transform-origin moves the point a transform turns about", "[svg][transform-origin]") {
  // About (10, 10): the square turns onto (10..20, 10..20).
  CHECK(red_at(square("transform-origin=\"10 10\""), 15, 15));
  CHECK(red_at(square("transform-origin=\"10px 10px\""), 15, 15));
  // About the viewport's centre (20, 20): onto (30..40, 30..40).
  CHECK(red_at(square("transform-origin=\"center\""), 35, 35));
  CHECK(red_at(square("transform-origin=\"50% 50%\""), 35, 35));
  CHECK(red_at(square("style=\"transform-origin: 50% 50%\""), 35, 35));
  // Keywords in either order; one keyword leaves the other axis at its centre: "left" is (0, 20).
  CHECK(red_at(square("transform-origin=\"50% 25%\""), 35, 15));  // about (20, 10): onto (30..40, 10..20)
  // Without a transform the origin changes nothing; an invalid origin is ignored with a warning.
  const RenderedDocument invalid = square("transform-origin=\"10 10 5\"");
  CHECK(contains(invalid.warnings, "transform-origin"));
  CHECK_FALSE(red_at(invalid, 15, 15));  // turned about (0, 0): off the canvas
  const RenderedDocument plain = render(svg_document(
      "width=\"40\" height=\"40\"", "<rect width=\"10\" height=\"10\" fill=\"red\" transform-origin=\"20 20\"/>"));
  CHECK(red_at(plain, 5, 5));
}

TEST_CASE("transform-origin keywords, in either order", "[svg][transform-origin]") {
  // scale(0.5) about o maps the square (0..10) onto (o/2 .. o/2 + 5).
  const auto halved = [](const std::string& origin) {
    return render(svg_document("width=\"40\" height=\"40\"",
                               "<rect width=\"10\" height=\"10\" fill=\"red\" transform=\"scale(0.5)\" "
                               "transform-origin=\"" + origin + "\"/>"));
  };
  CHECK(red_at(halved("top right"), 22, 2));     // (40, 0)
  CHECK(red_at(halved("right top"), 22, 2));
  CHECK(red_at(halved("bottom left"), 2, 22));   // (0, 40)
  CHECK(red_at(halved("left"), 2, 12));          // (0, 20): the other axis at its centre
  CHECK(red_at(halved("bottom"), 12, 22));       // (20, 40)
  CHECK(red_at(halved("right 0"), 22, 2));       // a keyword and a length
  const RenderedDocument wrong_axis = halved("top top");
  CHECK(contains(wrong_axis.warnings, "transform-origin"));
  CHECK(red_at(wrong_axis, 2, 2));               // ignored: scaled about (0, 0)
}

TEST_CASE("transform-origin with a scale: the origin stays in place", "[svg][transform-origin]") {
  // scale(2) about (10, 10) maps the square (0..10) onto (-10..10): pixel (5, 5) red, (15, 15) not.
  const RenderedDocument scaled = render(svg_document(
      "width=\"40\" height=\"40\"",
      "<rect width=\"10\" height=\"10\" fill=\"red\" transform=\"scale(2)\" transform-origin=\"10 10\"/>"));
  CHECK(red_at(scaled, 5, 5));
  CHECK_FALSE(red_at(scaled, 15, 15));
}
