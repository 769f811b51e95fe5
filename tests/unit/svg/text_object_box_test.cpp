// The object bounding box of <text> (SVG 2 8.10, "Bounding boxes": for text content elements "all
// glyphs occupy the full glyph cell" — each glyph's advance along the line by the font's ascent and
// descent across it), which objectBoundingBox units of paint servers, clip paths, masks and filters refer
// to, a <tspan>'s as its <text>'s (paint servers tested here). Oracle: the same document with the units made explicit in user space,
// the box computed from the formula with the library's shaped advances and FreeType's metrics of the font.
//
// Tolerance: max |Δ| <= 1/255 per channel (same curves and rasterizer; the gradient's end points differ only
// by the rounding of the box's arithmetic, ~1e-13 px).
#include <catch2/catch.hpp>
#include <string>

#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"
#include "svg_test_support.h"

using namespace curvescan;
using curvescan::svg::testing::inked_pixels;
using curvescan::svg::testing::max_delta;

namespace {

constexpr double kSize = 40.0;

svg::RenderedDocument render(const std::string& body) {
  return svg::testing::render(svg::testing::svg_document("width=\"240\" height=\"100\"", body));
}

// The cell box of `text` in DejaVu Sans at kSize from (x, y): [x, x + advances] x [y - ascent, y - descent].
Rect cell_box(std::u32string_view text, double x, double y) {
  Result<Font> font = load_font(FontQuery{"DejaVu Sans", 400, false}, false);
  REQUIRE(font.is_ok());
  TextStyle style;
  style.size = kSize;
  const Result<TextLayout> layout = layout_text(*font, text, {0.0, 0.0}, style);
  REQUIRE(layout.is_ok());
  double advance = 0.0;
  for (const PositionedGlyph& glyph : layout->glyphs) advance += glyph.advance;
  const FontMetrics m = font->metrics();
  const double s = kSize / m.units_per_em;
  return {x, y - m.ascender * s, x + advance, y - m.descender * s};
}

std::string number(double value) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

// A hard-stopped gradient: red on the first half, blue on the second, along (x1,y1)-(x2,y2).
std::string gradient(const std::string& units, double x1, double y1, double x2, double y2) {
  return "<linearGradient id=\"g\" gradientUnits=\"" + units + "\" x1=\"" + number(x1) + "\" y1=\"" +
         number(y1) + "\" x2=\"" + number(x2) + "\" y2=\"" + number(y2) +
         "\"><stop offset=\"0.5\" stop-color=\"red\"/><stop offset=\"0.5\" stop-color=\"blue\"/>"
         "</linearGradient>";
}

void check_same(const svg::RenderedDocument& expected, const svg::RenderedDocument& actual) {
  CHECK(actual.warnings.empty());
  CHECK(inked_pixels(expected.image) > 500);  // the text must draw something, or "equal" proves nothing
  CHECK(max_delta(expected.image, actual.image) <= 1);
}

const std::string kText = R"(font-family="DejaVu Sans" font-size="40")";

}  // namespace

TEST_CASE("text object box: objectBoundingBox paint spans the glyph cells, not the ink") {
  const Rect box = cell_box(U"Type", 20.0, 70.0);
  // The cells run from the pen to the last advance and from the ascender to the descender: wider and
  // taller than the ink of "Type" (its T starts at the pen but the 'e' ends before the advance).
  const std::string text = "<text x=\"20\" y=\"70\" fill=\"url(#g)\" " + kText + ">Type</text>";
  check_same(render(gradient("userSpaceOnUse", box.x0, 0.0, box.x1, 0.0) + text),
             render(gradient("objectBoundingBox", 0.0, 0.0, 1.0, 0.0) + text));
  check_same(render(gradient("userSpaceOnUse", 0.0, box.y0, 0.0, box.y1) + text),
             render(gradient("objectBoundingBox", 0.0, 0.0, 0.0, 1.0) + text));
}

TEST_CASE("text object box: a tspan's paint uses its text's box") {
  const Rect box = cell_box(U"Type", 20.0, 70.0);
  const auto text = [](const std::string& fill) {
    return "<text x=\"20\" y=\"70\" " + kText + ">Ty<tspan fill=\"" + fill + "\">pe</tspan></text>";
  };
  check_same(render(gradient("userSpaceOnUse", box.x0, 0.0, box.x1, 0.0) + text("url(#g)")),
             render(gradient("objectBoundingBox", 0.0, 0.0, 1.0, 0.0) + text("url(#g)")));
}
