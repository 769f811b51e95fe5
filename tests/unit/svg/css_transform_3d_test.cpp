// CSS transforms with relative lengths and 3D functions (css_transform.h): em of the element's font
// size, percentages of the reference box (transform-box: view-box, the nearest viewport), and 3D lists
// flattened onto z = 0 (CSS Transforms 2, 5 and 12) when the result is affine in x and y.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>

#include "svg/css_transform.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;
using detail::CssTransformContext;
using detail::parse_css_transform;

namespace {

// The products of sines and cosines of the 3D rotations leave a few ulps; 1e-12 is far below them.
bool near(const Affine& a, const Affine& b) {
  return std::abs(a.a - b.a) < 1e-12 && std::abs(a.b - b.b) < 1e-12 && std::abs(a.c - b.c) < 1e-12 &&
         std::abs(a.d - b.d) < 1e-12 && std::abs(a.e - b.e) < 1e-12 && std::abs(a.f - b.f) < 1e-12;
}

Affine parsed(std::string_view text, const CssTransformContext& context = {}) {
  const Result<Affine> transform = parse_css_transform(text, context);
  INFO(text);
  if (!transform) INFO(transform.error().message);
  REQUIRE(transform.is_ok());
  return *transform;
}

}  // namespace

TEST_CASE("css transform: em of the font size, ex as half of it, percentages of the reference box") {
  const CssTransformContext context{20.0, 200.0, 100.0};
  CHECK(near(parsed("translate(1.5em, 1ex)", context), Affine::translate(30, 10)));
  CHECK(near(parsed("translate(10%, 50%)", context), Affine::translate(20, 50)));
  CHECK(near(parsed("translateX(25%) translateY(-10%)", context), Affine::translate(50, -10)));
  CHECK(near(parsed("translate3d(10%, 1em, 0)", context), Affine::translate(20, 20)));
  // A percentage is no length for z (translateZ has no reference box) nor an angle.
  CHECK_FALSE(parse_css_transform("translateZ(10%)", context));
  CHECK_FALSE(parse_css_transform("rotate(10%)", context));
}

TEST_CASE("css transform: 3D functions that are 2D in the plane z = 0") {
  const double pi = std::numbers::pi;
  CHECK(near(parsed("translate3d(10px, 5px, 0)"), Affine::translate(10, 5)));
  CHECK(near(parsed("translate3d(10px, 5px, 7px)"), Affine::translate(10, 5)));  // z is dropped
  CHECK(near(parsed("translateZ(40px)"), Affine::identity()));
  CHECK(near(parsed("scale3d(2, 3, 1)"), Affine::scale(2, 3)));
  CHECK(near(parsed("scaleZ(5) scale3d(2, 3, 4)"), Affine::scale(2, 3)));
  CHECK(near(parsed("rotateZ(30deg)"), Affine::rotate(pi / 6)));
  CHECK(near(parsed("rotate3d(0, 0, 2, 30deg)"), Affine::rotate(pi / 6)));    // the axis is normalized
  CHECK(near(parsed("rotate3d(0, 0, -1, 30deg)"), Affine::rotate(-pi / 6)));  // the other way round
  // rotateX(a) seen from the front without perspective: y shrinks by cos(a) (Transforms 2, 12.1).
  CHECK(near(parsed("rotateX(60deg)"), Affine::scale(1, 0.5)));
  CHECK(near(parsed("rotateY(60deg)"), Affine::scale(0.5, 1)));
  // A translation along z between two rotations about y moves x: composed in 3D, then flattened.
  // rotateY(90deg) maps (0, 0, 10) to (10, 0, 0).
  CHECK(near(parsed("rotateY(90deg) translateZ(10px) rotateY(-90deg)"), Affine::translate(10, 0)));
  // matrix3d column by column; this one is matrix(2, 0.5, -1, 3, 7, 8) with z terms that do not reach
  // the plane.
  CHECK(near(parsed("matrix3d(2, 0.5, 0, 0,  -1, 3, 0, 0,  0, 0, 5, 0,  7, 8, 9, 1)"),
             Affine{2, 0.5, -1, 3, 7, 8}));
  // A homogeneous w other than 1 divides out.
  CHECK(
      near(parsed("matrix3d(2, 0, 0, 0,  0, 2, 0, 0,  0, 0, 1, 0,  4, 6, 0, 2)"), Affine{1, 0, 0, 1, 2, 3}));
  // Perspective alone leaves the plane z = 0 where it is; tilted under it, the map is projective.
  CHECK(near(parsed("perspective(100px)"), Affine::identity()));
  CHECK_FALSE(parse_css_transform("perspective(100px) rotateX(30deg)"));
  CHECK_FALSE(parse_css_transform("matrix3d(1, 0, 0, 0.01,  0, 1, 0, 0,  0, 0, 1, 0,  0, 0, 0, 1)"));
  CHECK_FALSE(parse_css_transform("rotate3d(0, 0, 0, 30deg)"));
}

TEST_CASE("css transform in a document: em of the element's font size, percentages of the viewport") {
  // A 100 x 20 viewport: translateX(40%) is 40 px; 2em at font-size 10px is 20 px; scale3d(1, 1, 9)
  // changes nothing in the plane.
  const RenderedDocument rendered = render(svg_document(
      "width=\"100\" height=\"20\"",
      "<style>#a { transform: translateX(40%) } #b { font-size: 10px; transform: translate3d(2em, 0, 5px) }"
      " #c { transform: scale3d(1, 1, 9) translateX(60px) }</style>"
      "<rect id=\"a\" width=\"10\" height=\"10\" fill=\"#ff0000\"/>"
      "<rect id=\"b\" width=\"10\" height=\"10\" fill=\"#00ff00\"/>"
      "<rect id=\"c\" width=\"10\" height=\"10\" fill=\"#0000ff\"/>"));
  CHECK(square_colour(rendered.image, 0) == "none");
  CHECK(square_colour(rendered.image, 2) == "#00ff00");
  CHECK(square_colour(rendered.image, 4) == "#ff0000");
  CHECK(square_colour(rendered.image, 6) == "#0000ff");
  CHECK(rendered.warnings.empty());
}
