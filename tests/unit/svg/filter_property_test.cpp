// The `filter` property's value (Filter Effects 1, sections 11 and 13): url() references and the CSS
// filter functions, with SVG 2's unitless lengths in presentation attributes and font-relative lengths
// resolved against the element's font size.
#include "svg/filter/filter_property.h"

#include <catch2/catch.hpp>

using namespace curvescan::svg::detail::filter;
using Kind = FilterFunction::Kind;

namespace {

// The single function `text` declares, with its lengths resolved for `font_size`.
FilterFunction only(const char* text, double font_size = 16.0) {
  const auto list = parse_filter_property(text);
  INFO(text);
  REQUIRE(list);
  REQUIRE(list->size() == 1);
  return list->front().resolved_for(font_size);
}

}  // namespace

TEST_CASE("filter property: unitless lengths are px", "[svg][filter]") {
  CHECK(only("blur(4)").amount == 4.0);
  CHECK(only("blur(4px)").amount == 4.0);
  const FilterFunction shadow = only("drop-shadow(blue 4 5 6)");
  CHECK(shadow.kind == Kind::kDropShadow);
  CHECK(shadow.dx == 4.0);
  CHECK(shadow.dy == 5.0);
  CHECK(shadow.amount == 6.0);
  REQUIRE(shadow.color);
  CHECK(shadow.color->b == 1.0);
}

TEST_CASE("filter property: em lengths follow the element's font size", "[svg][filter]") {
  // 0.2em, 0.3em, 0.1em at font-size 64: 12.8, 19.2, 6.4 px (exact in binary? no: compared within 1e-12).
  const FilterFunction shadow = only("drop-shadow(blue 0.2em 0.3em 0.1em)", 64.0);
  CHECK(shadow.dx == Approx(12.8).epsilon(1e-12));
  CHECK(shadow.dy == Approx(19.2).epsilon(1e-12));
  CHECK(shadow.amount == Approx(6.4).epsilon(1e-12));
  // A length with an absolute unit does not change with the font size: 1in is 96 px.
  CHECK(only("blur(1in)", 64.0).amount == 96.0);
  CHECK(only("blur(2em)", 10.0).amount == 20.0);
}

TEST_CASE("filter property: the drop-shadow colour goes before or after the lengths", "[svg][filter]") {
  CHECK(only("drop-shadow(red 1px 2px 3px)").color);
  CHECK(only("drop-shadow(1px 2px 3px red)").color);
  CHECK_FALSE(only("drop-shadow(1px 2px)").color);  // currentColor
  CHECK_FALSE(only("drop-shadow(currentColor 1px 2px)").color);
  CHECK_FALSE(parse_filter_property("drop-shadow(1px red 2px)"));  // between the lengths
  CHECK_FALSE(parse_filter_property("drop-shadow(red 1px 2px blue)"));
  CHECK_FALSE(parse_filter_property("drop-shadow(1px)"));
  CHECK_FALSE(parse_filter_property("drop-shadow(1px 2px 3px 4px)"));
  CHECK_FALSE(parse_filter_property("drop-shadow(1px 2px -3px)"));  // σ must not be negative
}

TEST_CASE("filter property: a comma between arguments makes the value invalid", "[svg][filter]") {
  CHECK_FALSE(parse_filter_property("drop-shadow(red, 10, 15)"));
  CHECK_FALSE(parse_filter_property("blur(1px, 2px)"));
  // Commas inside a colour function are the colour's own.
  const FilterFunction shadow = only("drop-shadow(rgb(255, 0, 0) 1px 2px)");
  REQUIRE(shadow.color);
  CHECK(shadow.color->r == 1.0);
}
