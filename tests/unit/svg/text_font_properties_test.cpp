// The font properties of the cascade (raster/svg/text_font_properties.h): keywords, numbers, the
// relative weights table of CSS Fonts 4 2.2.1, size keywords, family lists and the font shorthand.
#include "svg/text_font_properties.h"

#include <catch2/catch.hpp>

using namespace curvescan;
using namespace curvescan::svg::detail;

TEST_CASE("font-weight: keywords, numbers in [1, 1000], invalid values refused") {
  CHECK(parse_font_weight("normal", 700) == 400);
  CHECK(parse_font_weight(" bold ", 400) == 700);
  CHECK(parse_font_weight("100", 400) == 100);
  CHECK(parse_font_weight("650", 400) == 650);
  CHECK(parse_font_weight("1000", 400) == 1000);
  CHECK_FALSE(parse_font_weight("0", 400));
  CHECK_FALSE(parse_font_weight("1001", 400));
  CHECK_FALSE(parse_font_weight("heavy", 400));
  CHECK_FALSE(parse_font_weight("700px", 400));
  CHECK_FALSE(parse_font_weight("", 400));
}

TEST_CASE("font-weight: bolder and lighter follow the CSS Fonts 4 table") {
  // parent -> {bolder, lighter}, one row per band of the table.
  struct Row {
    int parent, bolder, lighter;
  };
  for (const Row row :
       {Row{50, 400, 50}, Row{100, 400, 100}, Row{300, 400, 100}, Row{400, 700, 100}, Row{500, 700, 100},
        Row{600, 900, 400}, Row{700, 900, 400}, Row{800, 900, 700}, Row{900, 900, 700}, Row{950, 950, 700}}) {
    INFO("parent weight " << row.parent);
    CHECK(parse_font_weight("bolder", row.parent) == row.bolder);
    CHECK(parse_font_weight("lighter", row.parent) == row.lighter);
  }
}

TEST_CASE("font-style and text-anchor keywords") {
  CHECK(parse_font_style_italic("normal") == false);
  CHECK(parse_font_style_italic("italic") == true);
  CHECK(parse_font_style_italic("oblique") == true);
  CHECK_FALSE(parse_font_style_italic("slanted"));
  CHECK(parse_text_anchor("start") == TextAnchor::kStart);
  CHECK(parse_text_anchor(" middle") == TextAnchor::kMiddle);
  CHECK(parse_text_anchor("end") == TextAnchor::kEnd);
  CHECK_FALSE(parse_text_anchor("center"));
  CHECK_FALSE(parse_text_anchor("left"));
}

TEST_CASE("font-size keywords: the CSS Fonts 3 scale on a 16px medium, larger and smaller by 1.2") {
  CHECK(font_size_keyword("medium", 30.0) == Approx(16.0));
  CHECK(font_size_keyword("xx-small", 30.0) == Approx(16.0 * 3.0 / 5.0));
  CHECK(font_size_keyword("x-small", 30.0) == Approx(12.0));
  CHECK(font_size_keyword("small", 30.0) == Approx(16.0 * 8.0 / 9.0));
  CHECK(font_size_keyword("large", 30.0) == Approx(19.2));
  CHECK(font_size_keyword("x-large", 30.0) == Approx(24.0));
  CHECK(font_size_keyword("xx-large", 30.0) == Approx(32.0));
  CHECK(font_size_keyword("larger", 10.0) == Approx(12.0));
  CHECK(font_size_keyword("smaller", 12.0) == Approx(10.0));
  CHECK_FALSE(font_size_keyword("12px", 10.0));
  CHECK_FALSE(font_size_keyword("huge", 10.0));
}

TEST_CASE("font-family lists: trimmed, empty names refused") {
  CHECK(parse_font_family("  'DejaVu Sans', serif ") == "'DejaVu Sans', serif");
  CHECK(parse_font_family("Cantarell") == "Cantarell");
  CHECK_FALSE(parse_font_family(""));
  CHECK_FALSE(parse_font_family("   "));
  CHECK_FALSE(parse_font_family("A,,B"));
  CHECK_FALSE(parse_font_family("A,"));
}

TEST_CASE("font shorthand: optional style/variant/weight, a size, an optional line height, a family") {
  const auto full = parse_font_shorthand("italic bold 12px/1.5 'DejaVu Sans', sans-serif", 400);
  REQUIRE(full);
  CHECK(full->italic);
  CHECK(full->weight == 700);
  CHECK(full->size == "12px");
  CHECK(full->family == "'DejaVu Sans', sans-serif");

  const auto minimal = parse_font_shorthand("20px serif", 700);
  REQUIRE(minimal);
  CHECK_FALSE(minimal->italic);
  CHECK(minimal->weight == 400);  // omitted parts reset to their initial values
  CHECK(minimal->size == "20px");

  const auto numeric = parse_font_shorthand("300 small-caps large Cantarell", 400);
  REQUIRE(numeric);
  CHECK(numeric->weight == 300);
  CHECK(numeric->size == "large");

  CHECK_FALSE(parse_font_shorthand("bold", 400));             // no size, no family
  CHECK_FALSE(parse_font_shorthand("12px", 400));             // no family
  CHECK_FALSE(parse_font_shorthand("caption", 400));          // system fonts are not supported
  CHECK_FALSE(parse_font_shorthand("wide 12px serif", 400));  // not a style, variant or weight
  // CSS Fonts 4 2.8: style, small-caps, weight and a font-stretch keyword, in any order.
  const auto four = parse_font_shorthand("condensed italic small-caps bold 12px serif", 400);
  REQUIRE(four);
  CHECK(four->italic);
  CHECK(four->small_caps);
  CHECK(four->weight == 700);
  CHECK(four->stretch == 75.0);
  CHECK(parse_font_shorthand("normal normal normal bold 12px serif", 400));
  CHECK_FALSE(parse_font_shorthand("normal normal normal normal bold 12px serif", 400));  // > 4 prefixes
}
