// Bitmap colour glyphs in SVG text (color_glyph.h, text_element.cpp, document.cpp's paint_glyph_bitmap):
// the image of the nearest strike drawn over its rectangle as <image> draws a bitmap, against an oracle
// that draws FreeType's bitmap of the same strike directly through the core (Canvas::fill with
// image_pattern_paint, bilinear, edge pixels padded) at the place the fonts' tables state
// (tests/fonts/make_bitmap_test_fonts.py: the image is the box (0,0)-(600,600) of a 1000-unit em).
// Both paths sample the same image through the same code; the only difference allowed is the last bit of
// the composed transform (the renderer multiplies the glyph placement by the strike's scale, the oracle
// writes the product down), which moves a sample point by ~1e-15 pixel and a bilinear weight by at most
// one 8-bit step: tolerance 1.

#include <catch2/catch.hpp>
#include <string>

#include "curvescan/raster/canvas.h"
#include "curvescan/raster/image_pattern.h"
#include "curvescan/raster/path_builder.h"
#include "freetype_colour_bitmap.h"
#include "svg_test_support.h"

using namespace curvescan;

namespace {

// A white 100 x 100 canvas with `image` drawn over the square of side `side` whose bottom-left corner is
// (x, baseline), at `opacity`.
Image oracle(const Image& image, double x, double baseline, double side, double opacity = 1.0) {
  Result<Canvas> canvas = Canvas::create(100, 100);
  REQUIRE(canvas.is_ok());
  canvas->clear(Paint::solid(Color{1, 1, 1, 1}));
  const double scale = side / image.width();
  const Affine image_to_user{scale, 0.0, 0.0, scale, x, baseline - side};
  PathBuilder square;
  square.move_to({x, baseline - side});
  square.line_to({x + side, baseline - side});
  square.line_to({x + side, baseline});
  square.line_to({x, baseline});
  square.close();
  const Paint paint =
      image_pattern_paint(image, image_to_user, PatternExtend::kPad, PatternFilter::kBilinear, opacity);
  REQUIRE(canvas->fill(square.build().value(), paint, FillRule::kNonZero).is_ok());
  return std::move(*canvas).take_image();
}

svg::RenderedDocument render_text(const std::string& family, const std::string& attributes,
                                  const std::string& text) {
  return svg::testing::render(
      svg::testing::svg_document("width=\"100\" height=\"100\"",
                                 "<rect width=\"100\" height=\"100\" fill=\"white\"/><text x=\"10\" y=\"80\" "
                                 "font-family=\"" +
                                     family + "\" " + attributes + ">" + text + "</text>"));
}

}  // namespace

TEST_CASE("bitmap glyphs in SVG: an sbix glyph is its largest strike scaled to the font size") {
  // font-size 100: no strike is that large, so the 50-ppem one (30 x 30) is scaled by 2 onto the box
  // (0,0)-(600,600) font units = (10, 20)-(70, 80) in user space.
  const svg::RenderedDocument rendered = render_text("Curvescan Sbix Test", "font-size=\"100\"", "A");
  CHECK(rendered.warnings.empty());
  CHECK(svg::testing::max_delta(
            rendered.image, oracle(curvescan::test::freetype_colour_bitmap("CurvescanSbixTest.ttf", U'A', 1),
                                   10, 80, 60)) <= 1);
  CHECK(rendered.image.at(20, 30) == Rgba8{255, 0, 0, 255});  // the red quadrant, not an outline
}

TEST_CASE("bitmap glyphs in SVG: at a strike's own size the strike is drawn pixel for pixel") {
  const svg::RenderedDocument rendered = render_text("Curvescan Sbix Test", "font-size=\"20\"", "A");
  CHECK(svg::testing::max_delta(
            rendered.image, oracle(curvescan::test::freetype_colour_bitmap("CurvescanSbixTest.ttf", U'A', 0),
                                   10, 80, 12)) <= 1);
}

TEST_CASE("bitmap glyphs in SVG: the strike is chosen by the device pixels the em covers") {
  // font-size 20 drawn 2.5 times larger, by a transform or by the output's scale (viewBox 40 units on 100
  // pixels): the em covers 50 device pixels, so the 50-ppem strike (30 x 30) is drawn pixel for pixel over
  // (10, 50)-(40, 80), where a strike chosen by the 20-unit size (12 x 12) would be scaled up 2.5 times.
  const Image expected =
      oracle(curvescan::test::freetype_colour_bitmap("CurvescanSbixTest.ttf", U'A', 1), 10, 80, 30);
  const std::string text = R"(<text x="4" y="32" font-family="Curvescan Sbix Test" font-size="20">A</text>)";
  const std::string white = R"(<rect width="100" height="100" fill="white"/>)";
  for (const std::string& document :
       {svg::testing::svg_document(R"(width="100" height="100")",
                                   white + R"svg(<g transform="scale(2.5)">)svg" + text + "</g>"),
        svg::testing::svg_document(R"(width="100" height="100" viewBox="0 0 40 40")",
                                   R"(<rect width="40" height="40" fill="white"/>)" + text)}) {
    INFO(document);
    const svg::RenderedDocument rendered = svg::testing::render(document);
    CHECK(rendered.warnings.empty());
    CHECK(svg::testing::max_delta(rendered.image, expected) <= 1);
  }
}

TEST_CASE("bitmap glyphs in SVG: fill-opacity and a translucent fill colour fade the image") {
  const Image expected =
      oracle(curvescan::test::freetype_colour_bitmap("CurvescanSbixTest.ttf", U'A', 1), 10, 80, 60, 0.5);
  CHECK(svg::testing::max_delta(
            render_text("Curvescan Sbix Test", "font-size=\"100\" fill-opacity=\"0.5\"", "A").image,
            expected) <= 1);
  CHECK(svg::testing::max_delta(
            render_text("Curvescan Sbix Test", "font-size=\"100\" fill=\"rgba(0,0,0,0.5)\"", "A").image,
            expected) <= 1);
  // fill="none": no image (as no COLR layer is drawn without a fill).
  CHECK(svg::testing::max_delta(
            render_text("Curvescan Sbix Test", "font-size=\"100\" fill=\"none\"", "A").image,
            render_text("Curvescan Sbix Test", "font-size=\"100\"", "").image) == 0);
}

TEST_CASE("bitmap glyphs in SVG: a CBDT font without outlines is found by family and drawn") {
  const svg::RenderedDocument rendered = render_text("Curvescan Cbdt Test", "font-size=\"100\"", "A");
  CHECK(rendered.warnings.empty());
  CHECK(svg::testing::max_delta(
            rendered.image, oracle(curvescan::test::freetype_colour_bitmap("CurvescanCbdtTest.ttf", U'A', 0),
                                   10, 80, 60)) <= 1);
  // A stroke has no outline to follow: nothing more is drawn, and nothing fails.
  const svg::RenderedDocument stroked =
      render_text("Curvescan Cbdt Test", "font-size=\"100\" stroke=\"black\" stroke-width=\"4\"", "A");
  CHECK(svg::testing::max_delta(stroked.image, rendered.image) == 0);
}

TEST_CASE("bitmap glyphs in SVG: the stroke of an sbix glyph follows its outline") {
  // The outline (0,0)-(600,600) at font-size 100: a 4-unit black stroke centred on x = 10 and on y = 20.
  const svg::RenderedDocument stroked =
      render_text("Curvescan Sbix Test", "font-size=\"100\" stroke=\"black\" stroke-width=\"4\"", "A");
  CHECK(stroked.image.at(10, 50) == Rgba8{0, 0, 0, 255});
  CHECK(stroked.image.at(40, 20) == Rgba8{0, 0, 0, 255});
  CHECK(stroked.image.at(20, 30) == Rgba8{255, 0, 0, 255});
}

TEST_CASE("bitmap glyphs in SVG: the document's pixel limit refuses a larger image, with a warning") {
  svg::RenderOptions options;
  options.limits.max_pixels = 100 * 100;  // the canvas fits, the 30 x 30 strike does too...
  const svg::RenderedDocument fits = svg::testing::render(
      svg::testing::svg_document(
          "width=\"100\" height=\"100\"",
          "<text x=\"10\" y=\"80\" font-size=\"100\" font-family=\"Curvescan Sbix Test\">A</text>"),
      options);
  CHECK(fits.warnings.empty());
  options.limits.max_pixels = 20 * 20;  // ...but not under a limit of 400 pixels: the outline instead
  const svg::RenderedDocument refused = svg::testing::render(
      svg::testing::svg_document(
          "width=\"20\" height=\"20\"",
          "<text x=\"0\" y=\"20\" font-size=\"100\" font-family=\"Curvescan Sbix Test\">A</text>"),
      options);
  CHECK(svg::testing::contains(refused.warnings, "is not drawn"));
  CHECK(refused.image.at(5, 15) == Rgba8{0, 0, 0, 255});  // the black outline fill
}
