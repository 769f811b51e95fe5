// CSS colours: every syntax SVG documents use, clamping, case-insensitivity and refusals.
#include "curvescan/svg/color.h"

#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using curvescan::Color;
using curvescan::Rgba8;
using curvescan::svg::RenderedDocument;
using curvescan::svg::testing::render;
using namespace curvescan::svg;

namespace {

Color color_of(std::string_view text) {
  const auto color = parse_color(text);
  INFO(text);
  REQUIRE(color.is_ok());
  return *color;
}

// Channels from bytes: the parser divides by 255 exactly as this does, so equality is exact.
Color bytes(int r, int g, int b, int a = 255) {
  return {r / 255.0, g / 255.0, b / 255.0, a / 255.0};
}

}  // namespace

TEST_CASE("named colours, case-insensitive, including the grey spellings and rebeccapurple") {
  CHECK(color_of("red") == bytes(255, 0, 0));
  CHECK(color_of("ReD") == bytes(255, 0, 0));
  CHECK(color_of("green") == bytes(0, 128, 0));  // CSS green is 0x008000, not X11's 0x00FF00
  CHECK(color_of("grey") == color_of("gray"));
  CHECK(color_of("lightgoldenrodyellow") == bytes(0xFA, 0xFA, 0xD2));
  CHECK(color_of("rebeccapurple") == bytes(0x66, 0x33, 0x99));
  CHECK(color_of("aliceblue") == bytes(0xF0, 0xF8, 0xFF));
  CHECK(color_of("yellowgreen") == bytes(0x9A, 0xCD, 0x32));
  CHECK(color_of(" transparent ") == Color{0, 0, 0, 0});
}

TEST_CASE("hex colours in all four lengths") {
  CHECK(color_of("#f80") == bytes(255, 136, 0));
  CHECK(color_of("#F808") == bytes(255, 136, 0, 136));
  CHECK(color_of("#12ab9F") == bytes(0x12, 0xAB, 0x9F));
  CHECK(color_of("#12ab9f80") == bytes(0x12, 0xAB, 0x9F, 0x80));
  for (std::string_view bad : {"#", "#12", "#12345", "#1234567", "#ggg", "# 123"}) {
    CHECK_FALSE(parse_color(bad).is_ok());
  }
}

TEST_CASE("rgb() and rgba() with integers, percentages, clamping and an alpha") {
  CHECK(color_of("rgb(255, 0, 128)") == bytes(255, 0, 128));
  CHECK(color_of("RGB( 10 20 30 )") == bytes(10, 20, 30));
  CHECK(color_of("rgb(100%, 0%, 50%)") == Color{1.0, 0.0, 0.5, 1.0});
  CHECK(color_of("rgb(300, -5, 0)") == bytes(255, 0, 0));
  CHECK(color_of("rgba(0, 0, 255, 0.25)") == Color{0, 0, 1, 0.25});
  CHECK(color_of("rgba(0, 0, 255, 50%)") == Color{0, 0, 1, 0.5});
  CHECK(color_of("rgba(0, 0, 255, 7)") == Color{0, 0, 1, 1});
  CHECK_FALSE(parse_color("rgb(1, 2)").is_ok());
  CHECK_FALSE(parse_color("rgb(1, 2, 3").is_ok());
  CHECK_FALSE(parse_color("rgb(1%, 2, 3)").is_ok());  // CSS: all integers or all percentages
  CHECK_FALSE(parse_color("rgb(1, 2, 3,)").is_ok());
}

TEST_CASE("hsl() follows CSS Color 3's conversion") {
  // The primaries and greys come out exactly; tolerance 1e-12 covers the arithmetic of other hues.
  CHECK(color_of("hsl(0, 100%, 50%)") == Color{1, 0, 0, 1});
  CHECK(color_of("hsl(120, 100%, 50%)") == Color{0, 1, 0, 1});
  CHECK(color_of("hsl(240deg, 100%, 50%)") == Color{0, 0, 1, 1});
  CHECK(color_of("hsl(-120, 100%, 50%)") == Color{0, 0, 1, 1});  // hues wrap around the circle
  CHECK(color_of("hsl(77, 0%, 25%)") == Color{0.25, 0.25, 0.25, 1});
  const Color teal = color_of("hsla(180, 50%, 25%, 0.5)");
  CHECK_THAT(teal.r, Catch::Matchers::WithinAbs(0.125, 1e-12));
  CHECK_THAT(teal.g, Catch::Matchers::WithinAbs(0.375, 1e-12));
  CHECK_THAT(teal.b, Catch::Matchers::WithinAbs(0.375, 1e-12));
  CHECK(teal.a == 0.5);
  CHECK_FALSE(parse_color("hsl(0, 100, 50%)").is_ok());
}

TEST_CASE("unknown names and junk are refused with the text in the message") {
  const auto bad = parse_color("reddish");
  REQUIRE_FALSE(bad.is_ok());
  CHECK(bad.error().message == "'reddish' is not a CSS colour");
  CHECK_FALSE(parse_color("").is_ok());
  CHECK_FALSE(parse_color("currentColor").is_ok());  // a reference, resolved by the caller
  CHECK_FALSE(parse_color("cmyk(1,2,3)").is_ok());
}
TEST_CASE("a colour followed by an SVG 1.1 icc-color() is invalid, as in SVG 2 and browsers") {
  // SVG 2 and CSS Color 4 dropped "<color> icc-color(...)"; browsers and resvg treat the value as invalid
  // (a fill falls back to its inherited or initial value, black), so curvescan does the same and warns.
  CHECK_FALSE(parse_color("red icc-color(acmecmyk, 0.11, 0.48, 0.83, 0.00)").is_ok());
  const RenderedDocument rendered = render(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"2\" height=\"2\">"
      "<rect width=\"2\" height=\"2\" fill=\"#ff0000 icc-color(cmyk, 0, 1, 1, 0)\"/></svg>");
  CHECK(rendered.image.at(1, 1) == Rgba8{0, 0, 0, 255});
  REQUIRE(rendered.warnings.size() == 1);
  CHECK(rendered.warnings[0].find("invalid value '#ff0000 icc-color(cmyk, 0, 1, 1, 0)' of property 'fill'") !=
        std::string::npos);
}
