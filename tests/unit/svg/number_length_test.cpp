// SVG numbers and lengths: the compact forms of the path-data grammar, overflow, units and conversions.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>

#include "curvescan/svg/length.h"
#include "curvescan/svg/number.h"

using namespace curvescan::svg;

TEST_CASE("consume_number reads the SVG number grammar and stops where a number cannot continue") {
  std::string_view text = "1.5.5-2e1e+2 3em";
  CHECK(consume_number(text) == 1.5);
  CHECK(consume_number(text) == 0.5);
  CHECK(consume_number(text) == -20.0);
  // "e+2" alone is not a number: the exponent belongs to the previous number only with digits after it.
  CHECK_FALSE(consume_number(text).has_value());
  CHECK(text == "e+2 3em");
  text = "+.25e-1x";
  CHECK(consume_number(text) == 0.025);  // 2.5e-2 is the correctly rounded double of the literal
  CHECK(text == "x");
  text = "3em";
  CHECK(consume_number(text) == 3.0);
  CHECK(text == "em");
  text = "7.";
  CHECK(consume_number(text) == 7.0);
  CHECK(text.empty());
}

TEST_CASE("consume_number refuses what is not a finite number and leaves the text alone") {
  for (std::string_view bad : {"", ".", "-", "+.", "e5", "nan", "inf", "1e999", "-1e400"}) {
    std::string_view text = bad;
    CHECK_FALSE(consume_number(text).has_value());
    CHECK(text == bad);
  }
}

TEST_CASE("consume_number agrees with strtod on seeded random decimal literals") {
  std::mt19937 random(20261121);
  std::uniform_real_distribution<double> mantissa(-1000.0, 1000.0);
  std::uniform_int_distribution<int> exponent(-30, 30);
  for (int i = 0; i < 2000; ++i) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17ge%d", mantissa(random), exponent(random));
    std::string_view text = buffer;
    const std::optional<double> value = consume_number(text);
    REQUIRE(value.has_value());
    CHECK(*value == std::strtod(buffer, nullptr));  // both round correctly: exact equality
    CHECK(text.empty());
  }
}

TEST_CASE("parse_number_list splits on comma-wsp and reports a trailing or broken item") {
  const NumberList good = parse_number_list(" 1,2 3\t,\n4-5.5.5 ");
  CHECK(good.complete);
  CHECK(good.values == std::vector<double>{1, 2, 3, 4, -5.5, 0.5});
  const NumberList trailing = parse_number_list("1,2,");
  CHECK_FALSE(trailing.complete);
  CHECK(trailing.values == std::vector<double>{1, 2});
  const NumberList broken = parse_number_list("1 2 x 3");
  CHECK_FALSE(broken.complete);
  CHECK(broken.values == std::vector<double>{1, 2});
  CHECK(parse_number_list("").values.empty());
}

TEST_CASE("parse_length knows the CSS units and names an unknown one") {
  const auto check = [](std::string_view text, double value, LengthUnit unit) {
    const auto length = parse_length(text);
    REQUIRE(length.is_ok());
    CHECK(length->value == value);
    CHECK(length->unit == unit);
  };
  check("12", 12, LengthUnit::kNone);
  check(" 12px ", 12, LengthUnit::kPx);
  check("3pt", 3, LengthUnit::kPt);
  check("2pc", 2, LengthUnit::kPc);
  check("-4.5mm", -4.5, LengthUnit::kMm);
  check("1cm", 1, LengthUnit::kCm);
  check("1in", 1, LengthUnit::kIn);
  check("2em", 2, LengthUnit::kEm);
  check("2ex", 2, LengthUnit::kEx);
  check("50%", 50, LengthUnit::kPercent);
  const auto unknown = parse_length("3km");
  REQUIRE_FALSE(unknown.is_ok());
  CHECK(unknown.error().message == "unknown unit 'km' in length '3km'");
  CHECK_FALSE(parse_length("px").is_ok());
  CHECK_FALSE(parse_length("3 px").is_ok());  // CSS: no space between a number and its unit
}

TEST_CASE("length_to_pixels uses the CSS ratios at the document resolution") {
  LengthContext context;  // 96 dpi, 16px font
  context.percent_reference = 200;
  // Products of exactly representable ratios; WithinRel 1e-15 allows the one rounding of each division.
  CHECK_THAT(length_to_pixels({1, LengthUnit::kIn}, context), Catch::Matchers::WithinRel(96.0, 1e-15));
  CHECK_THAT(length_to_pixels({72, LengthUnit::kPt}, context), Catch::Matchers::WithinRel(96.0, 1e-15));
  CHECK_THAT(length_to_pixels({6, LengthUnit::kPc}, context), Catch::Matchers::WithinRel(96.0, 1e-15));
  CHECK_THAT(length_to_pixels({25.4, LengthUnit::kMm}, context), Catch::Matchers::WithinRel(96.0, 1e-15));
  CHECK_THAT(length_to_pixels({2.54, LengthUnit::kCm}, context), Catch::Matchers::WithinRel(96.0, 1e-15));
  CHECK(length_to_pixels({2, LengthUnit::kEm}, context) == 32.0);
  CHECK(length_to_pixels({2, LengthUnit::kEx}, context) == 16.0);
  CHECK(length_to_pixels({25, LengthUnit::kPercent}, context) == 50.0);
  context.dpi = 300;
  CHECK_THAT(length_to_pixels({1, LengthUnit::kIn}, context), Catch::Matchers::WithinRel(300.0, 1e-15));
  CHECK(std::isnan(length_to_pixels({std::nan(""), LengthUnit::kMm}, context)));
}
