// Transform lists (every function, order of composition, errors) and the style attribute.
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>

#include "curvescan/svg/style_attribute.h"
#include "curvescan/svg/transform.h"

using namespace curvescan;
using namespace curvescan::svg;

namespace {

Affine transform_of(std::string_view text) {
  const auto transform = parse_transform(text);
  INFO(text);
  REQUIRE(transform.is_ok());
  return *transform;
}

// Trigonometry of degrees converted to radians: a few ulps from exact; 1e-12 is generous and far below
// any pixel.
void check_close(const Affine& x, const Affine& y) {
  for (auto [u, v] : {std::pair{x.a, y.a}, {x.b, y.b}, {x.c, y.c}, {x.d, y.d}, {x.e, y.e}, {x.f, y.f}}) {
    CHECK_THAT(u, Catch::Matchers::WithinAbs(v, 1e-12));
  }
}

}  // namespace

TEST_CASE("every transform function, with its default arguments") {
  CHECK(transform_of("") == Affine::identity());
  CHECK(transform_of("matrix(1 2 3 4 5 6)") == Affine{1, 2, 3, 4, 5, 6});
  CHECK(transform_of("translate(5)") == Affine::translate(5, 0));
  CHECK(transform_of("translate(5,-6)") == Affine::translate(5, -6));
  CHECK(transform_of("scale(2)") == Affine::scale(2, 2));
  CHECK(transform_of("scale(2 3)") == Affine::scale(2, 3));
  check_close(transform_of("rotate(90)"), Affine{0, 1, -1, 0, 0, 0});
  // rotate(90 10 0) maps (10, 0) to itself and (11, 0) to (10, 1).
  const Affine pivot = transform_of("rotate(90, 10, 0)");
  CHECK_THAT(pivot.apply(Point{10, 0}).x, Catch::Matchers::WithinAbs(10, 1e-12));
  CHECK_THAT(pivot.apply(Point{11, 0}).y, Catch::Matchers::WithinAbs(1, 1e-12));
  check_close(transform_of("skewX(45)"), Affine{1, 0, 1, 1, 0, 0});
  check_close(transform_of("skewY(45)"), Affine{1, 1, 0, 1, 0, 0});
}

TEST_CASE("a transform list composes left to right, the rightmost applied first") {
  const Affine list = transform_of("translate(10,0) scale(2)");
  CHECK(list.apply(Point{1, 1}) == Point{12, 2});
  const Affine commas = transform_of(" scale(2) ,translate(10 0)");
  CHECK(commas.apply(Point{1, 1}) == Point{22, 2});
  CHECK(transform_of("translate(1e2-1e1)") == Affine::translate(100, -10));
}

TEST_CASE("malformed transform lists are refused with the reason") {
  const auto unknown = parse_transform("spin(3)");
  REQUIRE_FALSE(unknown.is_ok());
  CHECK(unknown.error().message == "transform 'spin(3)': unknown function 'spin'");
  const auto count = parse_transform("rotate(1 2)");
  REQUIRE_FALSE(count.is_ok());
  CHECK(count.error().message == "transform 'rotate(1 2)': rotate() does not take 2 arguments");
  CHECK_FALSE(parse_transform("scale(2").is_ok());
  CHECK_FALSE(parse_transform("scale 2").is_ok());
  CHECK_FALSE(parse_transform("scale(a)").is_ok());
  CHECK_FALSE(parse_transform("matrix(1 2 3 4 5)").is_ok());
}

TEST_CASE("style attribute declarations: trimming, comments, case, !important and junk") {
  const auto declarations =
      parse_style_attribute(" FILL : red ;stroke-width:2px/* c; d */;; bogus; opacity: .5 ! important ;x:");
  REQUIRE(declarations.size() == 3);
  CHECK(declarations[0].name == "fill");
  CHECK(declarations[0].value == "red");
  CHECK(declarations[1].name == "stroke-width");
  CHECK(declarations[1].value == "2px");
  CHECK(declarations[2].name == "opacity");
  CHECK(declarations[2].value == ".5");
  CHECK(parse_style_attribute("").empty());
  CHECK(parse_style_attribute("/* unterminated fill: red").empty());
}
