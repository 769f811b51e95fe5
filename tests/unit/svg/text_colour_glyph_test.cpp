// Colour glyphs in SVG text (color_glyph.h, text_element.cpp): a COLR version 0 glyph is drawn as its
// layers in their palette colours, the foreground layer in the text's fill; an SVG glyph as the element
// "glyphN" of its document; COLR version 1 glyphs as plain outlines with one warning per font. The font is
// tests/fonts/CurvescanColourTest.ttf (the test fontconfig configuration names it); the oracle is
// tests/support/colour_glyph_oracle.h, which states its tolerance.
#include <catch2/catch.hpp>
#include <cstdlib>
#include <string>

#include "colour_glyph_oracle.h"
#include "svg_test_support.h"

using namespace curvescan;
using curvescan::test::colour_glyph_max_delta;
using curvescan::test::ColourGlyphScene;

namespace {

svg::RenderedDocument render_glyphs(const std::string& text_attributes, const std::string& text) {
  return svg::testing::render(svg::testing::svg_document(
      "width=\"100\" height=\"100\"",
      "<rect width=\"100\" height=\"100\" fill=\"white\"/><text x=\"10\" y=\"80\" font-size=\"100\" "
      "font-family=\"Curvescan Colour Test\" " +
          text_attributes + ">" + text + "</text>"));
}

int count_containing(const std::vector<std::string>& messages, const std::string& part) {
  int count = 0;
  for (const std::string& message : messages) count += message.find(part) != std::string::npos ? 1 : 0;
  return count;
}

}  // namespace

TEST_CASE("colour glyphs: a COLR v0 glyph draws its layers in palette order, the foreground in the fill") {
  const svg::RenderedDocument rendered = render_glyphs("fill=\"#00ff00\"", "A");
  CHECK(rendered.warnings.empty());
  CHECK(colour_glyph_max_delta(rendered.image, ColourGlyphScene{10, 80, Color{0, 1, 0, 1}}) <= 1);
  // The red layer is really there (the oracle is not all white where the glyph is).
  CHECK(rendered.image.at(15, 25) == Rgba8{255, 0, 0, 255});
}

TEST_CASE("colour glyphs: a translucent fill fades the palette layers with the foreground") {
  const svg::RenderedDocument rendered = render_glyphs("fill=\"#00ff00\" fill-opacity=\"0.5\"", "A");
  // fill-opacity is the paint's alpha (SVG 1.1 11.3): the same as a fill colour of alpha 0.5.
  CHECK(colour_glyph_max_delta(rendered.image, ColourGlyphScene{10, 80, Color{0, 1, 0, 0.5}}) <= 1);
  const svg::RenderedDocument rgba = render_glyphs("fill=\"rgba(0,255,0,0.5)\"", "A");
  CHECK(colour_glyph_max_delta(rgba.image, ColourGlyphScene{10, 80, Color{0, 1, 0, 0.5}}) <= 1);
}

TEST_CASE("colour glyphs: fill none draws no layers, a stroke follows the glyph's own outline") {
  const svg::RenderedDocument none = render_glyphs("fill=\"none\"", "A");
  CHECK(svg::testing::max_delta(none.image, render_glyphs("fill=\"none\"", "").image) == 0);
  // The stroke of the base outline (0,0)-(600,600): a 2 px black line centred on x = 10 and x = 70.
  const svg::RenderedDocument stroked =
      render_glyphs("fill=\"none\" stroke=\"black\" stroke-width=\"2\"", "A");
  CHECK(stroked.image.at(10, 50) == Rgba8{0, 0, 0, 255});
  CHECK(stroked.image.at(69, 50) == Rgba8{0, 0, 0, 255});
  CHECK(stroked.image.at(40, 50) == Rgba8{255, 255, 255, 255});  // inside: no fill, no layer
}

TEST_CASE("colour glyphs: COLR v1 glyphs are plain outlines, named once per font, SVG glyphs are drawn") {
  const svg::RenderedDocument rendered = render_glyphs("fill=\"black\"", "BCBC");
  CHECK(count_containing(
            rendered.warnings,
            "COLR v1 colour glyphs in font 'Curvescan Colour Test' are drawn as plain outlines") == 1);
  CHECK(rendered.warnings.size() == 1);
  // B's outline, (0,0)-(600,600) at 10 units a pixel, in the fill at x 10..70; C's SVG document, a green
  // (#008000) square over the same box, at x 80..140.
  CHECK(rendered.image.at(40, 50) == Rgba8{0, 0, 0, 255});
  CHECK(rendered.image.at(85, 50) == Rgba8{0, 128, 0, 255});
  // A plain glyph of the same font warns of nothing.
  CHECK(render_glyphs("fill=\"black\"", "D").warnings.empty());
}

TEST_CASE("colour glyphs: an SVG glyph is its document's element, in font units with y down") {
  // C's document: <rect width="600" height="600" y="-600" fill="green"/> in element "glyph3", so the square
  // (0,0)-(600,600) of the y-up em: (10, 20)-(70, 80) at font-size 100 and x = 10, y = 80. Its edges fall
  // on pixel boundaries, so every pixel is green or white exactly.
  const svg::RenderedDocument rendered = render_glyphs("fill=\"black\"", "C");
  CHECK(rendered.warnings.empty());
  int wrong = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      const bool inside = x >= 10 && x < 70 && y >= 20 && y < 80;
      wrong +=
          rendered.image.at(x, y) == (inside ? Rgba8{0, 128, 0, 255} : Rgba8{255, 255, 255, 255}) ? 0 : 1;
    }
  }
  CHECK(wrong == 0);
  // Faded by fill-opacity as a group: green at alpha 0.5 over white.
  const svg::RenderedDocument faded = render_glyphs("fill=\"black\" fill-opacity=\"0.5\"", "C");
  const Rgba8 half = faded.image.at(40, 50);
  CHECK(std::abs(half.r - 128) <= 1);  // (255 + 0) / 2, rounded either way: one level
  CHECK(std::abs(half.g - 192) <= 1);  // (255 + 128) / 2
  // fill="none": nothing of the document.
  CHECK(render_glyphs("fill=\"none\"", "C").image.at(40, 50) == Rgba8{255, 255, 255, 255});
}

TEST_CASE(
    "colour glyphs: each occurrence of an SVG glyph is drawn in its place and opacity by the one parsed "
    "document") {
  // Seven Cs at font-size 20 on two lines: advance 700 units = 14 px, square 600 units = 12 px, so square i
  // of a line is (14 i, baseline - 12)-(14 i + 12, baseline) on whole pixels. The document is parsed at
  // the first C and its renderer drawn again for the rest (document.cpp, draw_svg_glyph), the second line
  // faded by fill-opacity: the kept renderer must carry nothing from one occurrence to the next.
  const svg::RenderedDocument rendered = svg::testing::render(svg::testing::svg_document(
      "width=\"100\" height=\"100\"",
      "<rect width=\"100\" height=\"100\" fill=\"white\"/>"
      "<text x=\"0\" y=\"40\" font-size=\"20\" font-family=\"Curvescan Colour Test\">CCCCCCC</text>"
      "<text x=\"0\" y=\"80\" font-size=\"20\" font-family=\"Curvescan Colour Test\" "
      "fill-opacity=\"0.5\">CCCCCCC</text>"));
  CHECK(rendered.warnings.empty());
  int wrong = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      const bool in_column = x < 7 * 14 && x % 14 < 12;
      const bool first = in_column && y >= 28 && y < 40, second = in_column && y >= 68 && y < 80;
      const Rgba8 pixel = rendered.image.at(x, y);
      if (first) {
        wrong += pixel == Rgba8{0, 128, 0, 255} ? 0 : 1;
      } else if (second) {
        // Green at alpha 0.5 over white: (128, 192, 128), one level either way for the rounding.
        wrong += std::abs(pixel.r - 128) <= 1 && std::abs(pixel.g - 192) <= 1 && std::abs(pixel.b - 128) <= 1
                     ? 0
                     : 1;
      } else {
        wrong += pixel == Rgba8{255, 255, 255, 255} ? 0 : 1;
      }
    }
  }
  CHECK(wrong == 0);
}

TEST_CASE("colour glyphs: an SVG glyph document that is not SVG draws the plain outline, with a warning") {
  // tests/fonts/CurvescanBrokenSvgTest.ttf: glyph C's document is an <html> element
  // (make_colour_test_font.py).
  const svg::RenderedDocument rendered = svg::testing::render(svg::testing::svg_document(
      "width=\"100\" height=\"100\"",
      "<rect width=\"100\" height=\"100\" fill=\"white\"/><text x=\"10\" y=\"80\" font-size=\"100\" "
      "font-family=\"Curvescan Broken Svg Test\" fill=\"black\">C</text>"));
  CHECK(count_containing(rendered.warnings, "is not a well-formed SVG document") == 1);
  CHECK(rendered.image.at(40, 50) == Rgba8{0, 0, 0, 255});  // the outline (0,0)-(600,600), filled
  CHECK(rendered.image.at(75, 50) == Rgba8{255, 255, 255, 255});
}
