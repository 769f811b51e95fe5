// The canvas of an output size, or its refusal (raster/svg/output_size_refusal.h): the message states the
// size, what made it, the limit it passes and the option that changes it, with finite numbers only.
#include "svg/output_size_refusal.h"

#include <catch2/catch.hpp>

using curvescan::svg::detail::output_pixels;
using curvescan::svg::detail::output_size;
using curvescan::svg::detail::OutputSizeAsked;

namespace {

constexpr std::int64_t kDefaultMaxPixels = std::int64_t{1} << 24;

OutputSizeAsked asked_for(double natural_width, double natural_height, std::optional<double> width,
                          std::optional<double> height, double zoom = 1.0) {
  OutputSizeAsked asked;
  asked.request = {natural_width, natural_height, width, height, zoom, zoom, false};
  asked.zoom = zoom;
  asked.max_pixels = kDefaultMaxPixels;
  return asked;
}

std::string refusal(const OutputSizeAsked& asked) {
  const auto drawn = output_size(asked.request);
  REQUIRE(drawn.has_value());
  const auto pixels = output_pixels(asked, *drawn);
  REQUIRE_FALSE(pixels.is_ok());
  CHECK(pixels.error().kind == curvescan::ErrorKind::kLimitExceeded);
  return pixels.error().message;
}

}  // namespace

TEST_CASE("output_pixels: a size within the limits is its canvas, rounded up") {
  const OutputSizeAsked asked = asked_for(100.0, 50.0, 200.5, std::nullopt);
  const auto pixels = output_pixels(asked, *output_size(asked.request));
  REQUIRE(pixels.is_ok());
  CHECK(pixels->width == 201);
  CHECK(pixels->height == 101);  // 100.25, rounded up
}

TEST_CASE(
    "output_pixels: -w 1e308 on a document twice as tall names -w, the sizes and the side limit, finite") {
  const std::string message = refusal(asked_for(100.0, 200.0, 1e308, std::nullopt));
  CHECK(message ==
        "the output would be 1e+308 x 2e+308 pixels (the document's size 100 x 200 px, -w 1e+308 px), beyond "
        "the limit of 32767 pixels per side: give a smaller -w, -h or -z");
  CHECK(message.find("inf") == std::string::npos);
}

TEST_CASE("output_pixels: a side beyond 32767 is not helped by --max-pixels") {
  const std::string message = refusal(asked_for(100.0, 50.0, 40000.0, std::nullopt));
  CHECK(message ==
        "the output would be 40000 x 20000 pixels (the document's size 100 x 50 px, -w 40000 px), beyond the "
        "limit of 32767 pixels per side: give a smaller -w, -h or -z");
}

TEST_CASE("output_pixels: too many pixels in all says whether --max-pixels can reach them") {
  // 8000 x 4000 = 3.2e7: above the default 2^24, below the largest --max-pixels (2^26).
  CHECK(refusal(asked_for(100.0, 50.0, std::nullopt, std::nullopt, 80.0)) ==
        "the output would be 8000 x 4000 pixels (the document's size 100 x 50 px, -z 80), 32000000 in all, "
        "beyond the limit of 16777216 pixels (raise it with --max-pixels, up to 67108864, or give a smaller "
        "-w, -h or -z)");
  // 20000 x 10000 = 2e8: beyond what --max-pixels allows.
  CHECK(
      refusal(asked_for(100.0, 50.0, std::nullopt, std::nullopt, 200.0)) ==
      "the output would be 20000 x 10000 pixels (the document's size 100 x 50 px, -z 200), 200000000 in all, "
      "beyond the limit of 16777216 pixels (--max-pixels goes up to 67108864; give a smaller -w, -h or -z)");
}

TEST_CASE("output_pixels: the resolution and the page are named where they make the size") {
  OutputSizeAsked asked = asked_for(1e8, 2e8, std::nullopt, std::nullopt);
  asked.dpi_x = asked.dpi_y = 1e6;
  CHECK(refusal(asked) ==
        "the output would be 100000000 x 200000000 pixels (the document's size 1e+08 x 2e+08 px at --dpi "
        "1e+06), "
        "beyond the limit of 32767 pixels per side: give a smaller -w, -h or -z");
  OutputSizeAsked page = asked_for(100.0, 50.0, std::nullopt, std::nullopt);
  page.page_width = 1e308;
  page.page_height = 1.0;
  CHECK(refusal(page) ==
        "the output would be 1e+308 x 1 pixels (the document's size 100 x 50 px, --page-width 1e+308 px, "
        "--page-height 1 px), beyond the limit of 32767 pixels per side: give a smaller --page-width and "
        "--page-height");
}

TEST_CASE("output_pixels: an output under one pixel asks for a larger size, not a smaller one") {
  CHECK(refusal(asked_for(100.0, 50.0, 1e-10, std::nullopt)) ==
        "the output would be 0 x 0 pixels (the document's size 100 x 50 px, -w 1e-10 px): an image is at "
        "least 1 "
        "pixel wide and tall; give a larger -w, -h or -z");
}
