// The rotate attribute (SVG 1.1 10.5, SVG 2 11.8.3): each typographic character turns about its current
// text position; a base and its combining marks are one typographic character, so the marks turn with
// the base about the base's pen (the value of the cluster's first character applies to all its glyphs).
//
// Oracle: the library's own layout of the same string (text_layout.h: HarfBuzz places the marks, as SVG
// text does) at the origin, its outline filled through Canvas under translate(x, y) * rotate(angle) — the
// whole cluster turned about its pen. Tolerance: max |Δ| <= 1/255 per channel — same curves, same
// rasterizer; only the composition of the transforms differs (~1e-13 px), which can flip the rounding of
// 255·coverage by one level. A mark turned about its own pen instead (its pen is the base's advance further
// on, 12 px here) lands several pixels away: differences of ~255.
#include <catch2/catch.hpp>
#include <numbers>
#include <string>

#include "curvescan/raster/canvas.h"
#include "curvescan/svg/document.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"
#include "svg_test_support.h"

using namespace curvescan;
using curvescan::svg::testing::inked_pixels;
using curvescan::svg::testing::max_delta;

namespace {

constexpr int kWidth = 120;
constexpr int kHeight = 100;

// The text element in a kWidth x kHeight document (svg_test_support.h renders it, requiring success).
svg::RenderedDocument render(const std::string& text_element) {
  return svg::testing::render(svg::testing::svg_document(
      "width=\"" + std::to_string(kWidth) + "\" height=\"" + std::to_string(kHeight) + "\"", text_element));
}

// `utf8` in DejaVu Sans at 40 px, laid out from the origin, filled black under `transform`.
Image oracle(const std::string& utf8, const Affine& transform) {
  Result<Font> font = load_font(FontQuery{"DejaVu Sans", 400, false}, false);
  REQUIRE(font.is_ok());
  TextStyle style;
  style.size = 40.0;
  const Result<Path> path = text_path(*font, utf8, {0.0, 0.0}, style);
  REQUIRE(path.is_ok());
  Result<Canvas> canvas = Canvas::create(kWidth, kHeight);
  REQUIRE(canvas.is_ok());
  REQUIRE(canvas->fill(*path, Paint::solid({0, 0, 0, 1}), FillRule::kNonZero, transform).is_ok());
  return std::move(*canvas).take_image();
}

Affine turned(double x, double y, double degrees) {
  return Affine::translate(x, y) * Affine::rotate(degrees * std::numbers::pi / 180.0);
}

}  // namespace

TEST_CASE("svg text rotate: combining marks turn with their base about the cluster's pen") {
  // o + COMBINING DIAERESIS + COMBINING LOW LINE, a + COMBINING CANDRABINDU: one cluster each.
  for (const std::string& cluster : {std::string("o\xCC\x88\xCC\xB2"), std::string("a\xCC\x90")}) {
    INFO(cluster);
    const svg::RenderedDocument rendered =
        render(R"(<text x="40.5" y="60.25" font-family="DejaVu Sans" font-size="40" rotate="30">)" + cluster +
               "</text>");
    CHECK(rendered.warnings.empty());
    const Image expected = oracle(cluster, turned(40.5, 60.25, 30.0));
    CHECK(inked_pixels(expected) > 100);  // the text draws something, or "equal" proves nothing
    CHECK(max_delta(expected, rendered.image) <= 1);
  }
}

TEST_CASE("svg text rotate: the value of a cluster's first character turns the whole cluster") {
  // The mark's own value (the second in the list) does not apply: the mark is not the first character of
  // its typographic character (SVG 2, the rotate attribute).
  const std::string cluster = "o\xCC\x88";
  const svg::RenderedDocument rendered =
      render(R"(<text x="40.5" y="60.25" font-family="DejaVu Sans" font-size="40" rotate="-20 70">)" +
             cluster + "</text>");
  CHECK(rendered.warnings.empty());
  CHECK(max_delta(oracle(cluster, turned(40.5, 60.25, -20.0)), rendered.image) <= 1);
}
