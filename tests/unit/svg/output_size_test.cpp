// The output size rules of rsvg-convert 2.54 (raster/svg/output_size.h). Every expected size below is what
// rsvg-convert 2.54.7 (Debian 12's librsvg2-bin) wrote for a 100 x 50 px document with the same flags,
// rounded up to whole pixels as both programs round; tests/svg_corpus/render_rsvg_convert_test.cpp runs
// the two programs side by side where rsvg-convert is installed.
#include <catch2/catch.hpp>
#include <cmath>
#include <optional>

#include "svg/output_size.h"

using curvescan::svg::detail::output_size;
using curvescan::svg::detail::OutputSizeRequest;

namespace {

struct Case {
  std::optional<double> width, height;
  double zoom_x, zoom_y;
  bool keep_aspect_ratio;
  int expected_width, expected_height;
};

}  // namespace

TEST_CASE("output_size follows rsvg-convert 2.54 for -w, -h, -z, -x, -y and -a") {
  const std::optional<double> none;
  const Case cases[] = {
      // no zoom
      {none, none, 1, 1, false, 100, 50},
      {200.0, none, 1, 1, false, 200, 100},
      {none, 200.0, 1, 1, false, 400, 200},
      {200.0, 200.0, 1, 1, false, 200, 200},
      {200.0, 200.0, 1, 1, true, 200, 100},
      {120.0, 300.0, 1, 1, true, 120, 60},
      {300.0, 60.0, 1, 1, true, 120, 60},
      {40.0, 30.0, 1, 1, false, 40, 30},
      {40.0, 30.0, 1, 1, true, 40, 20},
      // -z 3: the zoomed size 300 x 150 capped by -w / -h
      {none, none, 3, 3, false, 300, 150},
      {200.0, none, 3, 3, false, 200, 150},
      {200.0, none, 3, 3, true, 200, 100},
      {none, 200.0, 3, 3, false, 300, 150},
      {200.0, 200.0, 3, 3, false, 200, 200},
      {200.0, 200.0, 3, 3, true, 200, 100},
      {300.0, 60.0, 3, 3, false, 300, 60},
      {40.0, none, 3, 3, false, 40, 150},
      {none, 20.0, 3, 3, true, 40, 20},
      // -z 0.5: 50 x 25, which -w 200 -h 200 do not cap
      {200.0, 200.0, 0.5, 0.5, false, 50, 25},
      {40.0, none, 0.5, 0.5, false, 40, 25},
      {40.0, 30.0, 0.5, 0.5, true, 40, 20},
      // -x 3 -y 0.5: 300 x 25
      {none, none, 3, 0.5, true, 300, 25},
      {200.0, none, 3, 0.5, false, 200, 25},
      {200.0, none, 3, 0.5, true, 200, 17},
      {200.0, 200.0, 3, 0.5, false, 200, 200},
      {120.0, 300.0, 3, 0.5, true, 120, 10},
      {300.0, 60.0, 3, 0.5, true, 300, 25},
      {none, 20.0, 3, 0.5, true, 240, 20},
      // -x 0.5: 50 x 50
      {40.0, none, 0.5, 1, true, 40, 40},
      {none, 20.0, 0.5, 1, true, 20, 20},
      {40.0, 30.0, 0.5, 1, true, 30, 30},
  };
  for (const Case& c : cases) {
    const auto size = output_size({100.0, 50.0, c.width, c.height, c.zoom_x, c.zoom_y, c.keep_aspect_ratio});
    REQUIRE(size.has_value());
    INFO("w " << c.width.value_or(-1) << " h " << c.height.value_or(-1) << " zoom " << c.zoom_x << " x "
              << c.zoom_y << (c.keep_aspect_ratio ? " -a" : ""));
    // Whole pixels as the renderer rounds (document.cpp): up, after absorbing 1e-9 of rounding error.
    CHECK(std::ceil(size->width - 1e-9) == c.expected_width);
    CHECK(std::ceil(size->height - 1e-9) == c.expected_height);
  }
}

TEST_CASE("output_size: a document without area has no output size") {
  CHECK_FALSE(output_size({0.0, 50.0, std::nullopt, std::nullopt, 1, 1, false}).has_value());
  CHECK_FALSE(output_size({100.0, 0.0, 200.0, 200.0, 1, 1, true}).has_value());
}

TEST_CASE("output_size: a product that overflows on the way does not spoil a size that fits") {
  // A 1e300 px document zoomed 1e9 times (1e309: infinite in double), then capped by -w 100 -h 100 -a:
  // the factor 100 / inf is 0 and inf * 0 NaN in plain arithmetic, but the size is 100 x 50.
  const auto capped = output_size({1e300, 5e299, 100.0, 100.0, 1e9, 1e9, true});
  REQUIRE(capped.has_value());
  CHECK(capped->width == Approx(100.0));
  CHECK(capped->height == Approx(50.0));
  // -w 1e308 on a document twice as tall as wide: the height is beyond a double, infinite (not NaN).
  const auto tall = output_size({100.0, 200.0, 1e308, std::nullopt, 1, 1, false});
  REQUIRE(tall.has_value());
  CHECK(tall->width == 1e308);
  CHECK(std::isinf(tall->height));
}

TEST_CASE("output_size_scaled: the size times 2^exponent, finite where the sides are beyond a double") {
  const auto scaled =
      curvescan::svg::detail::output_size_scaled({100.0, 200.0, 1e308, std::nullopt, 1, 1, false});
  REQUIRE(scaled.has_value());
  CHECK(std::log10(scaled->size.width) + scaled->exponent * std::log10(2.0) == Approx(308.0));
  CHECK(std::log10(scaled->size.height) + scaled->exponent * std::log10(2.0) ==
        Approx(308.0 + std::log10(2.0)));
}
