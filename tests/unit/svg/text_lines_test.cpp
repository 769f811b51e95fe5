// Lines of SVG text made by white-space (raster/svg/text_chunk_layout.cpp, text_element.cpp): preserved
// tabs set at tab stops measured from the start of the line box (CSS Text 3 section 4.2), and the lines of
// forced line breaks placed by their line boxes (CSS 2.1 10.8.1, SVG 2 11.4). The expected images are the
// same glyph outlines laid out by the library's text API (text_layout.h) at the positions the
// specifications give, computed here from the font's own advances and metrics.
//
// Tolerance: max |Δ| <= 1/255 per channel, as in text_white_space_layout_test.cpp: the same curves through
// the same rasterizer, positions summed in another order (~1e-13 px) can flip one rounding level; a glyph at
// the wrong tab stop or on the wrong baseline moves whole edges (differences of ~100/255 and more).
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/svg/document.h"
#include "curvescan/text/text_layout.h"
#include "svg_test_support.h"
#include "text_test_support.h"

using namespace curvescan;
using curvescan::svg::testing::inked_pixels;
using curvescan::svg::testing::max_delta;

namespace {

constexpr int kWidth = 240;
constexpr int kHeight = 120;

const Font& dejavu() {
  return svg::testing::dejavu_sans();
}

// Font units -> px at `size`.
double px(double units, double size) {
  return units * size / dejavu().metrics().units_per_em;
}

double advance(char32_t c, double size) {
  return px(dejavu().advance(dejavu().glyph_for(c)), size);
}

struct Piece {
  std::string text;
  Point origin;
  double size = 20.0;
};

Image oracle(const std::vector<Piece>& pieces) {
  Result<Canvas> canvas = Canvas::create(kWidth, kHeight);
  REQUIRE(canvas.is_ok());
  for (const Piece& piece : pieces) {
    TextStyle style;
    style.size = piece.size;
    const Result<Path> path = text_path(dejavu(), piece.text, piece.origin, style);
    REQUIRE(path.is_ok());
    REQUIRE(canvas->fill(*path, Paint::solid({0, 0, 0, 1}), FillRule::kNonZero, Affine::identity()).is_ok());
  }
  return std::move(*canvas).take_image();
}

svg::RenderedDocument render(const std::string& attributes, const std::string& content) {
  return svg::testing::render_sized(
      kWidth, kHeight,
      "<text font-family=\"DejaVu Sans\" font-size=\"20\" " + attributes + ">" + content + "</text>");
}

// The text must draw something substantial, or "equal" would prove nothing.
void check_same(const Image& expected, const svg::RenderedDocument& actual) {
  CHECK(actual.warnings.empty());
  CHECK(inked_pixels(expected) > 100);
  CHECK(max_delta(expected, actual.image) <= 1);
}

}  // namespace

TEST_CASE("white-space pre: a tab after a font-size change goes to the line's tab stop, not its run's") {
  // Tab stops every 8 spaces of the <text>'s font from the line's start (CSS Text 3 4.2): at 20 px the
  // space of DejaVu Sans is 651/2048 em, 6.36 px, so the first stop is 50.9 px from x. "a" (20 px) and "b"
  // (30 px, a run of its own) end 31.3 px from x, so the tab ends at the first stop, where "c" starts —
  // not 50.9 px past the end of "b", as a tab measured from the start of its own run would put it.
  const double stop = 8.0 * advance(U' ', 20.0);
  const double after_b = advance(U'a', 20.0) + advance(U'b', 30.0);
  REQUIRE(stop - after_b > 0.5 * advance(U'0', 20.0));  // the stop is not skipped for being too near
  check_same(oracle({{"a", {10, 40}}, {"b", {10 + advance(U'a', 20.0), 40}, 30.0}, {"c", {10 + stop, 40}}}),
             render("x=\"10\" y=\"40\" style=\"white-space: pre\"", "a<tspan font-size=\"30\">b</tspan>\tc"));
}

TEST_CASE("white-space pre: a tab after an absolute x is measured along the laid-out line") {
  // SVG 2 lays the line out before x moves its chunks: the tab after "ab" in the second chunk still ends
  // at the line's first stop (50.9 px from the line's start), so "c" is that far minus the advance of "ab"
  // past the chunk's x.
  const double stop = 8.0 * advance(U' ', 20.0);
  const double ab = advance(U'a', 20.0) + advance(U'b', 20.0);
  check_same(oracle({{"ab", {10, 40}}, {"c", {120 + stop - ab, 40}}}),
             render("x=\"10\" y=\"40\" style=\"white-space: pre\"", "ab<tspan x=\"120\">\tc</tspan>"));
}

TEST_CASE("tab-size: a number of spaces or a length, the next stop skipped when nearer than 0.5ch") {
  const double space = advance(U' ', 20.0), ab = advance(U'a', 20.0) + advance(U'b', 20.0);
  const double half_ch = 0.5 * advance(U'0', 20.0);
  // 3 spaces: stops every 19.1 px; "ab" ends at 25.0, the next stop is 38.1.
  REQUIRE(6.0 * space - ab > half_ch);
  check_same(oracle({{"ab", {10, 40}}, {"c", {10 + 6.0 * space, 40}}}),
             render("x=\"10\" y=\"40\" style=\"white-space: pre; tab-size: 3\"", "ab\tc"));
  // A length: stops every 40 px.
  check_same(oracle({{"ab", {10, 40}}, {"c", {50, 40}}}),
             render("x=\"10\" y=\"40\" style=\"white-space: pre; tab-size: 40px\"", "ab\tc"));
  // 26 px: the stop at 26 is 1 px after "ab", nearer than 0.5ch (6.4 px), so the tab goes on to 52.
  REQUIRE(26.0 - ab < half_ch);
  check_same(oracle({{"ab", {10, 40}}, {"c", {62, 40}}}),
             render("x=\"10\" y=\"40\" style=\"white-space: pre; tab-size: 26px\"", "ab\tc"));
  // tab-size is the <text>'s (it applies to block containers): a tspan's own value changes nothing.
  check_same(oracle({{"ab", {10, 40}}, {"c", {50, 40}}}),
             render("x=\"10\" y=\"40\" style=\"white-space: pre; tab-size: 40px\"",
                    "ab<tspan style=\"tab-size: 2\">\tc</tspan>"));
  // No presentation attribute (SVG 2 6.6 lists none for tab-size): named and ignored, tabs stay 8 spaces.
  const svg::RenderedDocument attribute =
      render("x=\"10\" y=\"40\" tab-size=\"2\" style=\"white-space: pre\"", "ab\tc");
  CHECK(max_delta(oracle({{"ab", {10, 40}}, {"c", {10 + 8.0 * space, 40}}}), attribute.image) <= 1);
  CHECK(attribute.warnings.size() == 1);
  // A negative value is invalid: named, ignored.
  const svg::RenderedDocument negative =
      render("x=\"10\" y=\"40\" style=\"white-space: pre; tab-size: -1\"", "ab\tc");
  CHECK(max_delta(oracle({{"ab", {10, 40}}, {"c", {10 + 8.0 * space, 40}}}), negative.image) <= 1);
  CHECK(negative.warnings.size() == 1);
}

TEST_CASE("white-space pre: a taller font on a line moves that line's baseline down by its own ascent") {
  // DejaVu Sans has no line gap (hhea: ascender 1901, descender -483 of 2048; font.h line height 2384), so
  // each line box reaches ascender above and descender below the baseline of each font on it, the <text>'s
  // own font (20 px) always among them (the strut). Second line at 40 px: its baseline is the first's
  // depth (20 px font) plus its own height (40 px font) below the first.
  const FontMetrics m = dejavu().metrics();
  REQUIRE(m.line_height == Approx(m.ascender - m.descender));
  const double second = 40 + px(-m.descender, 20.0) + px(m.ascender, 40.0);
  check_same(
      oracle({{"ab", {10, 40}}, {"cd", {10, second}, 40.0}}),
      render("x=\"10\" y=\"40\" style=\"white-space: pre\"", "ab\n<tspan font-size=\"40\">cd</tspan>"));
  // A tall first line pushes the second down by its depth; the second (20 px) needs only the strut.
  const double third = 40 + px(-m.descender, 40.0) + px(m.ascender, 20.0);
  check_same(
      oracle({{"AB", {10, 40}, 40.0}, {"cd", {10, third}}}),
      render("x=\"10\" y=\"40\" style=\"white-space: pre\"", "<tspan font-size=\"40\">AB</tspan>\ncd"));
  // Smaller text on a line does not bring it up: the strut keeps the <text>'s line height.
  const double strut = px(m.line_height, 20.0);
  check_same(
      oracle({{"ab", {10, 40}}, {"cd", {10, 40 + strut}, 10.0}}),
      render("x=\"10\" y=\"40\" style=\"white-space: pre\"", "ab\n<tspan font-size=\"10\">cd</tspan>"));
}
