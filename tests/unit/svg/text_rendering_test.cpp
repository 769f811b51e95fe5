// text-rendering (SVG 1.1 10.8): optimizeSpeed on a <text> draws its glyphs and decorations without
// anti-aliasing (a pixel in when its centre is), as shape-rendering crispEdges draws shapes; auto,
// optimizeLegibility and geometricPrecision keep exact coverage. The <text>'s computed value decides, so a
// <tspan>'s own value does not split the element.
//
// Oracle: the same glyph outlines, laid out by the library's own text API (text_layout.h) at the same
// origin, filled through Canvas with Antialias::kNone or kExact. Tolerance: max |Δ| <= 1/255 — same curves,
// same rasterizer; only the summing of glyph offsets differs (~1e-13 px), which can flip the rounding of
// 255·coverage by one level in exact mode (and in aliased mode a pixel centre lying within 1e-13 px of an
// edge, which this text does not have: the check below holds it to 0 there).
#include <catch2/catch.hpp>
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

constexpr int kWidth = 200;
constexpr int kHeight = 60;

// The text element in a kWidth x kHeight document (svg_test_support.h renders it, requiring success).
svg::RenderedDocument render(const std::string& text_element) {
  return svg::testing::render(svg::testing::svg_document(
      "width=\"" + std::to_string(kWidth) + "\" height=\"" + std::to_string(kHeight) + "\"", text_element));
}

// "Text" in DejaVu Sans at 30 px from (10.3, 40.2), filled black, aliased or with exact coverage.
Image oracle(Antialias antialias) {
  Result<Font> font = load_font(FontQuery{"DejaVu Sans", 400, false}, false);
  REQUIRE(font.is_ok());
  TextStyle style;
  style.size = 30.0;
  const Result<Path> path = text_path(*font, "Text", {10.3, 40.2}, style);
  REQUIRE(path.is_ok());
  Result<Canvas> canvas = Canvas::create(kWidth, kHeight);
  REQUIRE(canvas.is_ok());
  REQUIRE(canvas
              ->fill(*path, Paint::solid({0, 0, 0, 1}), FillRule::kNonZero, Affine::identity(),
                     FillOptions{kDefaultFlattenTolerance, antialias})
              .is_ok());
  return std::move(*canvas).take_image();
}

// Pixels whose alpha is neither 0 nor 255.
int partial_pixels(const Image& image) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) count += image.at(x, y).a != 0 && image.at(x, y).a != 255;
  return count;
}

constexpr const char* kOpen = R"(<text x="10.3" y="40.2" font-family="DejaVu Sans" font-size="30" )";

}  // namespace

TEST_CASE("text-rendering: optimizeSpeed draws the text without anti-aliasing") {
  const Image aliased = oracle(Antialias::kNone);
  REQUIRE(inked_pixels(aliased) > 100);  // the text draws something, or "equal" proves nothing
  REQUIRE(partial_pixels(aliased) == 0);
  for (const std::string& attributes :
       {std::string(R"(text-rendering="optimizeSpeed">Text</text>)"),
        std::string(R"(style="text-rendering: optimizeSpeed">Text</text>)"),
        // Inherited from a group, and a tspan's own value does not split the <text>.
        std::string(R"(>Text</text>)"),
        std::string(R"(text-rendering="optimizeSpeed"><tspan text-rendering="auto">Text</tspan></text>)")}) {
    const bool from_group = attributes == ">Text</text>";
    const svg::RenderedDocument rendered =
        render(from_group ? std::string(R"(<g text-rendering="optimizeSpeed">)") + kOpen + attributes + "</g>"
                          : kOpen + attributes);
    INFO(attributes);
    CHECK(rendered.warnings.empty());
    CHECK(max_delta(aliased, rendered.image) == 0);
  }
}

TEST_CASE("text-rendering: auto, optimizeLegibility and geometricPrecision keep exact coverage") {
  const Image exact = oracle(Antialias::kExact);
  REQUIRE(partial_pixels(exact) > 50);  // anti-aliased edges exist, so aliasing would show
  for (const std::string value : {"auto", "optimizeLegibility", "geometricPrecision"}) {
    INFO(value);
    const svg::RenderedDocument rendered =
        render(kOpen + std::string("text-rendering=\"") + value + "\">Text</text>");
    CHECK(rendered.warnings.empty());
    CHECK(max_delta(exact, rendered.image) <= 1);
  }
  // A tspan's optimizeSpeed does not alias a <text> that is not.
  CHECK(max_delta(exact,
                  render(kOpen + std::string(R"(><tspan text-rendering="optimizeSpeed">Text</tspan></text>)"))
                      .image) <= 1);
}

TEST_CASE("text-rendering: an invalid value is ignored with a warning") {
  const svg::RenderedDocument rendered = render(std::string(R"(<g text-rendering="optimizeSpeed">)") + kOpen +
                                                R"(text-rendering="jagged">Text</text></g>)");
  CHECK(max_delta(oracle(Antialias::kNone), rendered.image) == 0);  // the inherited value stays
  CHECK(svg::testing::contains(rendered.warnings,
                               "ignoring invalid value 'jagged' of property 'text-rendering'"));
}
