// SVG text layout features (raster/svg/text_element.cpp) in whole documents against an independent
// composition: every glyph's outline placed by hand where SVG 1.1 chapter 10 / SVG 2 chapter 11 put it —
// pen positions from the library's own shaping (text_layout.h, checked against FreeType in
// tests/unit/font), plus the spacing, shifts, lengths and path placement computed here from the
// specification's formulas and the font's metrics — filled through Canvas with the same paint.
//
// Tolerance: max |Δ| <= 1/255 per channel, as in text_document_test.cpp: both sides fill the same curves
// with the same rasterizer; only the order in which offsets are summed differs (~1e-13 px), which can flip
// the rounding of 255·coverage by one level. A wrong offset of even 0.05 px moves an edge and gives
// differences of ~10/255 and more.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "curvescan/raster/canvas.h"
#include "curvescan/svg/document.h"
#include "curvescan/text/font_lookup.h"
#include "curvescan/text/text_layout.h"
#include "svg_test_support.h"
#include "text_test_support.h"

using namespace curvescan;
using curvescan::svg::testing::inked_pixels;
using curvescan::svg::testing::max_delta;

namespace {

constexpr int kWidth = 260;
constexpr int kHeight = 120;
constexpr double kSize = 24.0;

svg::RenderedDocument render(const std::string& body) {
  return svg::testing::render_sized(kWidth, kHeight, body);
}

const Font& dejavu() {
  return svg::testing::dejavu_sans();
}

// The library's shaping of `text` (kerning on, as SVG's default), glyphs left to right.
TextLayout shaped(std::u32string_view text, TextDirection direction = TextDirection::kLeftToRight,
                  bool override_direction = false, bool ligatures = true) {
  TextStyle style;
  style.size = kSize;
  style.direction = direction;
  style.bidi_override = override_direction;
  style.ligatures = ligatures;
  Result<TextLayout> layout = layout_text(dejavu(), text, {0.0, 0.0}, style);
  REQUIRE(layout.is_ok());
  return std::move(layout).value();
}

// One glyph of the oracle: font units -> user space.
struct HandGlyph {
  GlyphId glyph;
  Affine font_to_user;
};

Affine at(Point origin, double angle_degrees = 0.0, double scale_x = 1.0) {
  const double s = kSize / dejavu().metrics().units_per_em;
  return Affine::translate(origin.x, origin.y) * Affine::rotate(angle_degrees * std::numbers::pi / 180.0) *
         Affine::scale(scale_x, 1.0) * Affine{s, 0.0, 0.0, -s, 0.0, 0.0};
}

// The layout's glyphs with each origin mapped by `place(index, origin)`.
template <typename Place>
std::vector<HandGlyph> glyphs_of(const TextLayout& layout, Place place) {
  std::vector<HandGlyph> out;
  for (std::size_t i = 0; i < layout.glyphs.size(); ++i) {
    out.push_back({layout.glyphs[i].glyph, place(i, layout.glyphs[i])});
  }
  return out;
}

Image compose(const std::vector<HandGlyph>& glyphs, const std::vector<Path>& extra = {}) {
  Result<Canvas> canvas = Canvas::create(kWidth, kHeight);
  REQUIRE(canvas.is_ok());
  PathBuilder builder;
  for (const HandGlyph& glyph : glyphs)
    REQUIRE(dejavu().append_glyph(glyph.glyph, glyph.font_to_user, builder).is_ok());
  Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  const Paint black = Paint::solid({0, 0, 0, 1});
  for (const Path& p : extra) REQUIRE(canvas->fill(p, black, FillRule::kNonZero, Affine::identity()).is_ok());
  REQUIRE(canvas->fill(*path, black, FillRule::kNonZero, Affine::identity()).is_ok());
  return std::move(*canvas).take_image();
}


void check_same(const Image& expected, const svg::RenderedDocument& actual) {
  CHECK(actual.warnings.empty());
  CHECK(inked_pixels(expected) > 100);  // the text must draw something, or "equal" proves nothing
  CHECK(max_delta(expected, actual.image) <= 1);
}

Path rectangle(double x0, double y0, double x1, double y1) {
  PathBuilder builder;
  builder.move_to({x0, y0}).line_to({x1, y0}).line_to({x1, y1}).line_to({x0, y1}).close();
  Result<Path> path = builder.build();
  REQUIRE(path.is_ok());
  return std::move(path).value();
}

const std::string kFont = R"( font-family="DejaVu Sans" font-size="24" )";

}  // namespace

TEST_CASE("svg text layout: letter-spacing and word-spacing add after each glyph (CSS Text 3 8)") {
  // "Ta Va": T-a and V-a are kerned pairs in DejaVu Sans, so kerning is kept under the spacing.
  const TextLayout layout = shaped(U"Ta Va", TextDirection::kLeftToRight, false, /*ligatures=*/false);
  // letter-spacing 3 after each glyph, word-spacing 11 after the space (character 2).
  const Image expected = compose(glyphs_of(layout, [&](std::size_t i, const PositionedGlyph& g) {
    const double extra = 3.0 * static_cast<double>(i) + (g.character_index > 2 ? 11.0 : 0.0);
    return at({10.0 + g.origin.x + extra, 60.0});
  }));
  check_same(expected, render("<text x=\"10\" y=\"60\"" + kFont +
                              "letter-spacing=\"3\" word-spacing=\"11\">Ta Va</text>"));
  // em units resolve against the font size: 0.125em = 3 px.
  check_same(expected, render("<text x=\"10\" y=\"60\"" + kFont +
                              "style=\"letter-spacing:0.125em; word-spacing:11px\">Ta Va</text>"));
  // No spacing at the end of the line (CSS Text 3 8.2): anchored at its end, the text ends with its last
  // letter's advance, not with a gap of 3 after it. Five glyphs: four letter gaps and one word gap.
  const double length = layout.lines.front().advance + 3.0 * 4 + 11.0;
  check_same(compose(glyphs_of(layout, [&](std::size_t i, const PositionedGlyph& g) {
               const double extra = 3.0 * static_cast<double>(i) + (g.character_index > 2 ? 11.0 : 0.0);
               return at({250.0 - length + g.origin.x + extra, 60.0});
             })),
             render("<text x=\"250\" y=\"60\" text-anchor=\"end\"" + kFont +
                    "letter-spacing=\"3\" word-spacing=\"11\">Ta Va</text>"));
}

TEST_CASE("svg text layout: baseline-shift sub, super, length and percentage (SVG 1.1 10.9.3)") {
  const FontMetrics m = dejavu().metrics();
  const double scale = kSize / m.units_per_em;
  const TextLayout layout = shaped(U"ab");
  const auto expect = [&](double shift_b) {
    return compose(glyphs_of(layout, [&](std::size_t i, const PositionedGlyph& g) {
      return at({10.0 + g.origin.x, 60.0 + (i == 1 ? shift_b : 0.0)});
    }));
  };
  // super: up by OS/2 ySuperscriptYOffset, sub: down by ySubscriptYOffset.
  check_same(
      expect(-m.superscript_offset * scale),
      render("<text x=\"10\" y=\"60\"" + kFont + ">a<tspan baseline-shift=\"super\">b</tspan></text>"));
  check_same(expect(m.subscript_offset * scale),
             render("<text x=\"10\" y=\"60\"" + kFont + ">a<tspan baseline-shift=\"sub\">b</tspan></text>"));
  // A length shifts up; a percentage is of the font size; nested shifts add.
  check_same(expect(-7.0),
             render("<text x=\"10\" y=\"60\"" + kFont + ">a<tspan baseline-shift=\"7\">b</tspan></text>"));
  check_same(expect(-12.0),
             render("<text x=\"10\" y=\"60\"" + kFont + ">a<tspan baseline-shift=\"50%\">b</tspan></text>"));
  check_same(expect(-9.0),
             render("<text x=\"10\" y=\"60\"" + kFont +
                    ">a<tspan baseline-shift=\"4\"><tspan baseline-shift=\"5\">b</tspan></tspan></text>"));
  // It applies to tspan, tref, altGlyph and textPath only ("Applies to"), and is not inherited: on the
  // <text> itself, or on a group around it, it moves nothing; a tspan's "baseline" undoes nothing.
  check_same(expect(0.0), render("<text x=\"10\" y=\"60\"" + kFont + "baseline-shift=\"super\">ab</text>"));
  check_same(expect(0.0), render("<g baseline-shift=\"10\"><text x=\"10\" y=\"60\"" + kFont +
                                 "baseline-shift=\"inherit\">a<tspan>b</tspan></text></g>"));
  check_same(expect(0.0), render("<text x=\"10\" y=\"60\"" + kFont +
                                 "baseline-shift=\"super\">a<tspan baseline-shift=\"baseline\">b</tspan></text>"));
}

TEST_CASE("svg text layout: dominant-baseline and alignment-baseline from the font's metrics") {
  const FontMetrics m = dejavu().metrics();
  const double scale = kSize / m.units_per_em;
  const TextLayout layout = shaped(U"Hx");
  const auto expect = [&](double shift) {
    return compose(glyphs_of(layout, [&](std::size_t, const PositionedGlyph& g) {
      return at({10.0 + g.origin.x, 60.0 + shift});
    }));
  };
  // The named baseline is put at y: the glyphs move down by its height above the alphabetic baseline.
  check_same(expect(0.5 * (m.ascender + m.descender) * scale),
             render("<text x=\"10\" y=\"60\"" + kFont + "dominant-baseline=\"central\">Hx</text>"));
  check_same(expect(0.5 * m.x_height * scale),
             render("<text x=\"10\" y=\"60\"" + kFont + "dominant-baseline=\"middle\">Hx</text>"));
  check_same(expect(m.ascender * scale),
             render("<text x=\"10\" y=\"60\"" + kFont + "dominant-baseline=\"text-before-edge\">Hx</text>"));
  check_same(expect(m.descender * scale),
             render("<text x=\"10\" y=\"60\"" + kFont + "dominant-baseline=\"ideographic\">Hx</text>"));
  // alignment-baseline on a tspan holding everything: the same as the dominant baseline on the text.
  check_same(
      expect(0.5 * (m.ascender + m.descender) * scale),
      render("<text x=\"10\" y=\"60\"" + kFont + "><tspan alignment-baseline=\"central\">Hx</tspan></text>"));
}

TEST_CASE("svg text layout: textLength with lengthAdjust spacing and spacingAndGlyphs") {
  const TextLayout layout = shaped(U"abc");
  const double natural = layout.lines.front().advance;
  // spacing: the difference spread over the n - 1 gaps (SVG 2 11.8.3 step 5).
  const double delta = 200.0 - natural;
  check_same(compose(glyphs_of(layout,
                               [&](std::size_t i, const PositionedGlyph& g) {
                                 return at({10.0 + g.origin.x + delta * static_cast<double>(i) / 2.0, 60.0});
                               })),
             render("<text x=\"10\" y=\"60\"" + kFont + "textLength=\"200\">abc</text>"));
  // spacingAndGlyphs: positions and outlines scaled horizontally from the start.
  const double factor = 200.0 / natural;
  check_same(compose(glyphs_of(layout,
                               [&](std::size_t, const PositionedGlyph& g) {
                                 return at({10.0 + g.origin.x * factor, 60.0}, 0.0, factor);
                               })),
             render("<text x=\"10\" y=\"60\"" + kFont +
                    "textLength=\"200\" lengthAdjust=\"spacingAndGlyphs\">abc</text>"));
  // A negative textLength is an error: ignored with a warning, the text drawn as without it.
  const svg::RenderedDocument negative =
      render("<text x=\"10\" y=\"60\"" + kFont + "textLength=\"-5\">abc</text>");
  CHECK(negative.warnings.size() == 1);
}

TEST_CASE("svg text layout: nested textLength keeps the inner length — the inner element is one unit") {
  // SVG 2 11.8.3, "resolve text length": the <tspan>'s characters are spread to its textLength first;
  // the <text>'s difference is then spread over its units a, b, [cde], f (three gaps), the tspan moving
  // as one block whose own length stays 100.
  // After the tspan, f keeps the inner step's gap (the next test), so the <text> measures its advance
  // plus 1.5 inner differences.
  const TextLayout layout = shaped(U"abcdef");
  REQUIRE(layout.glyphs.size() == 6);
  const auto o = [&](std::size_t i) { return layout.glyphs[i].origin.x; };
  const double inner = 100.0 - (o(5) - o(2));
  const double outer = 220.0 - (layout.lines.front().advance + 1.5 * inner);
  const double step = outer / 3.0;
  const double shift[6] = {
      0.0, step, 2.0 * step, 0.5 * inner + 2.0 * step, inner + 2.0 * step, 1.5 * inner + 3.0 * step};
  check_same(compose(glyphs_of(layout,
                               [&](std::size_t i, const PositionedGlyph& g) {
                                 return at({10.0 + g.origin.x + shift[i], 60.0});
                               })),
             render("<text x=\"10\" y=\"60\"" + kFont +
                    "textLength=\"220\">ab<tspan textLength=\"100\">cde</tspan>f</text>"));
}

TEST_CASE("svg text layout: textLength spacing on a tspan leaves one step after it, as between its letters") {
  // SVG 2 11.8.3, "resolve text length": the loop over the tspan's characters adds the step
  // delta / (n - 1) after each one, the last included, and ends with a shift of n steps; the characters
  // after the tspan move by that shift (Chrome's SvgTextLayoutAlgorithm, and resvg's image of
  // text/textLength/on-a-single-tspan), so "cde" spread to 100 is followed by f one step further on
  // than by the difference alone, which would put f against e.
  const TextLayout layout = shaped(U"abcdef");
  REQUIRE(layout.glyphs.size() == 6);
  const auto o = [&](std::size_t i) { return layout.glyphs[i].origin.x; };
  const double delta = 100.0 - (o(5) - o(2));
  const double step = delta / 2.0;
  REQUIRE(step > 10.0);  // a gap several pixels wide, so the comparison below sees where f is
  const double shift[6] = {0.0, 0.0, 0.0, step, 2.0 * step, 3.0 * step};
  check_same(compose(glyphs_of(layout,
                               [&](std::size_t i, const PositionedGlyph& g) {
                                 return at({10.0 + g.origin.x + shift[i], 60.0});
                               })),
             render("<text x=\"10\" y=\"60\"" + kFont + ">ab<tspan textLength=\"100\">cde</tspan>f</text>"));
}

TEST_CASE("svg text layout: textLength spacing opens a right-to-left run in visual order (Arabic joined)") {
  // Arabic "alwyb" in a left-to-right <text>: one right-to-left run, shaped joined, its glyphs left to
  // right in the layout. The spacing goes between visually adjacent glyphs, the leftmost staying at x —
  // in logical order the glyphs would run into each other (the last letter, leftmost, moved furthest).
  const TextLayout layout = shaped(U"\u0627\u0644\u0648\u064A\u0628");
  REQUIRE(layout.glyphs.size() == 5);
  REQUIRE(layout.glyphs.front().character_index == 4);  // visual order: the last letter on the left
  const double delta = 200.0 - layout.lines.front().advance;
  const double start = layout.lines.front().origin.x;
  check_same(
      compose(glyphs_of(layout,
                        [&](std::size_t i, const PositionedGlyph& g) {
                          return at({10.0 + g.origin.x - start + delta * static_cast<double>(i) / 4.0, 60.0});
                        })),
      render("<text x=\"10\" y=\"60\"" + kFont +
             "textLength=\"200\">\xd8\xa7\xd9\x84\xd9\x88\xd9\x8a\xd8\xa8</text>"));
}

TEST_CASE("svg text layout: rotate turns each glyph about its origin — the last angle repeats") {
  const TextLayout layout = shaped(U"abc");
  const std::vector<double> angles{30.0, 90.0, 90.0};
  check_same(compose(glyphs_of(layout,
                               [&](std::size_t i, const PositionedGlyph& g) {
                                 return at({40.0 + g.origin.x, 60.0}, angles[i]);
                               })),
             render("<text x=\"40\" y=\"60\"" + kFont + "rotate=\"30 90\">abc</text>"));
}

TEST_CASE("svg text layout: bidi in a text chunk, direction and unicode-bidi") {
  // Latin and Hebrew in one chunk: the library's line layout (bidi.h; tests/unit/font/bidi_test.cpp).
  const std::u32string mixed = U"ab \u05d0\u05d1\u05d2 cd";
  const TextLayout line = shaped(mixed);
  check_same(compose(glyphs_of(line,
                               [&](std::size_t, const PositionedGlyph& g) {
                                 return at({10.0 + g.origin.x, 60.0});
                               })),
             render("<text x=\"10\" y=\"60\"" + kFont + ">ab \xd7\x90\xd7\x91\xd7\x92 cd</text>"));
  // A tspan with another fill in the middle of the Hebrew word does not change the order.
  const svg::RenderedDocument split =
      render("<text x=\"10\" y=\"60\"" + kFont + ">ab \xd7\x90<tspan>\xd7\x91</tspan>\xd7\x92 cd</text>");
  CHECK(max_delta(
            split.image,
            render("<text x=\"10\" y=\"60\"" + kFont + ">ab \xd7\x90\xd7\x91\xd7\x92 cd</text>").image) <= 1);
  // direction="rtl": the paragraph is right to left, and text-anchor start is its right end.
  const TextLayout rtl = shaped(mixed, TextDirection::kRightToLeft);
  const double advance = rtl.lines.front().advance;
  check_same(
      compose(glyphs_of(rtl,
                        [&](std::size_t, const PositionedGlyph& g) {
                          return at({250.0 - advance + g.origin.x - rtl.lines.front().origin.x, 60.0});
                        })),
      render("<text x=\"250\" y=\"60\"" + kFont + "direction=\"rtl\">ab \xd7\x90\xd7\x91\xd7\x92 cd</text>"));
  // unicode-bidi: bidi-override with direction rtl on a tspan draws its letters right to left.
  const TextLayout reversed = shaped(U"abc", TextDirection::kRightToLeft, true);
  REQUIRE(reversed.glyphs.front().character_index == 2);
  check_same(compose(glyphs_of(reversed,
                               [&](std::size_t, const PositionedGlyph& g) {
                                 return at({10.0 + g.origin.x - reversed.lines.front().origin.x, 60.0});
                               })),
             render("<text x=\"10\" y=\"60\"" + kFont +
                    "><tspan direction=\"rtl\" unicode-bidi=\"bidi-override\">abc</tspan></text>"));
}

TEST_CASE("svg text layout: text-decoration from the font's post and OS/2 metrics") {
  const FontMetrics m = dejavu().metrics();
  const double scale = kSize / m.units_per_em;
  const TextLayout layout = shaped(U"ab");
  const double advance = layout.lines.front().advance;
  const std::vector<HandGlyph> glyphs = glyphs_of(layout, [&](std::size_t, const PositionedGlyph& g) {
    return at({10.0 + g.origin.x, 60.0});
  });
  // Underline: its top at post.underlinePosition, which the OpenType spec defines as the top of the
  // stroke, post.underlineThickness thick, the text's advance long. DejaVu Sans's post table says -40
  // and 90 (units of 2048 to the em), so the line runs from 40 to 130 units below the baseline.
  REQUIRE(m.units_per_em == 2048.0);
  REQUIRE(m.underline_thickness == 90.0);
  const double u = 60.0 + (40.0 + 45.0) * scale, ut = 45.0 * scale;  // centre and half thickness
  check_same(compose(glyphs, {rectangle(10.0, 60.0 + 40.0 * scale, 10.0 + advance, 60.0 + 130.0 * scale)}),
             render("<text x=\"10\" y=\"60\"" + kFont + "text-decoration=\"underline\">ab</text>"));
  // Overline: its top at the ascender (no table gives an overline; CSS Text Decoration 3 puts it on the
  // side opposite the underline), the underline's thickness.
  check_same(compose(glyphs, {rectangle(10.0, 60.0 - m.ascender * scale, 10.0 + advance,
                                        60.0 - (m.ascender - m.underline_thickness) * scale)}),
             render("<text x=\"10\" y=\"60\"" + kFont + "text-decoration=\"overline\">ab</text>"));
  // Line-through: OS/2 yStrikeoutPosition is the top of the stroke (OpenType spec, OS/2 table),
  // yStrikeoutSize its thickness.
  const double s0 = 60.0 - m.strikeout_position * scale,
               s1 = 60.0 - (m.strikeout_position - m.strikeout_thickness) * scale;
  check_same(compose(glyphs, {rectangle(10.0, s0, 10.0 + advance, s1)}),
             render("<text x=\"10\" y=\"60\"" + kFont + "text-decoration=\"line-through\">ab</text>"));
  // Painted with the declaring element's fill: a red underline under black text in a tspan.
  const svg::RenderedDocument red =
      render("<text x=\"10\" y=\"60\"" + kFont +
             "fill=\"red\" text-decoration=\"underline\"><tspan fill=\"black\">ab</tspan></text>");
  // The underline is 1.05 px thick (90/2048 em) and not pixel-aligned: of the two rows it crosses one is
  // at least half covered. Look for such red pixels in the rows around it, and for no red anywhere else.
  int red_pixels = 0, red_elsewhere = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const Rgba8 p = red.image.at(x, y);
      const bool is_red = p.a > 0 && p.r > 0 && p.g == 0;
      const bool near_line = std::abs(y + 0.5 - u) < 1.5 && x >= 10 && x < 10.0 + advance;
      if (is_red && p.a >= 128 && near_line) ++red_pixels;
      if (is_red && !near_line) ++red_elsewhere;
    }
  }
  CHECK(red_pixels > 10);
  CHECK(red_elsewhere == 0);
  // A stroked decoration is one line along the run, not one box per glyph (no seams between "a" and "b"):
  // the same stroke as a <rect> of the underline's extent. The glyphs are in a tspan without paint.
  const auto number = [](double v) {
    char text[64];
    std::snprintf(text, sizeof text, "%.17g", v);
    return std::string(text);
  };
  const svg::RenderedDocument stroked = render(
      "<text x=\"10\" y=\"60\"" + kFont + "fill=\"none\" stroke=\"red\" stroke-width=\"0.5\" "
      "text-decoration=\"underline\"><tspan stroke=\"none\">ab</tspan></text>");
  const svg::RenderedDocument box = render("<rect x=\"10\" y=\"" + number(u - ut) + "\" width=\"" + number(advance) +
                                           "\" height=\"" + number(2 * ut) +
                                           "\" fill=\"none\" stroke=\"red\" stroke-width=\"0.5\"/>");
  CHECK(inked_pixels(box.image) > 50);
  CHECK(max_delta(box.image, stroked.image) <= 1);
  // Declared on groups around the <text>, decorations propagate to it (CSS Text Decoration 3 2.1) and
  // are drawn as its own, with its paint: the group's red fill does not reach them.
  check_same(compose(glyphs, {rectangle(10.0, u - ut, 10.0 + advance, u + ut), rectangle(10.0, s0, 10.0 + advance, s1)}),
             render("<g text-decoration=\"underline\" fill=\"red\"><g text-decoration=\"line-through\">"
                    "<text x=\"10\" y=\"60\" fill=\"black\"" + kFont + ">ab</text></g></g>"));
}

TEST_CASE("svg text layout: textPath places glyphs by their midpoints along the path") {
  const TextLayout layout = shaped(U"abc");
  // On a horizontal line from (10, 60) the text is where it would be at x = 10 (each glyph's midpoint
  // at its distance, turned by 0 degrees); startOffset moves it along.
  const std::vector<HandGlyph> straight = glyphs_of(layout, [&](std::size_t, const PositionedGlyph& g) {
    return at({30.0 + g.origin.x, 60.0});
  });
  check_same(compose(straight), render("<path id=\"p\" d=\"M 10 60 L 250 60\"/><text" + kFont +
                                       "><textPath href=\"#p\" startOffset=\"20\">abc</textPath></text>"));
  // SVG 2's path attribute, and startOffset as a percentage of the path's length (240 -> 20 = 8.333%).
  check_same(
      compose(straight),
      render(
          "<text" + kFont +
          "><textPath path=\"M 10 60 L 250 60\" startOffset=\"8.3333333333333333%\">abc</textPath></text>"));
  // pathLength on the referenced path: a startOffset length is in its units (120 for 240: 10 -> 20), a
  // percentage stays a fraction of the path (SVG 2 11.8.1).
  check_same(compose(straight), render("<path id=\"p\" d=\"M 10 60 L 250 60\" pathLength=\"120\"/><text" + kFont +
                                       "><textPath href=\"#p\" startOffset=\"10\">abc</textPath></text>"));
  check_same(compose(straight),
             render("<path id=\"p\" d=\"M 10 60 L 250 60\" pathLength=\"120\"/><text" + kFont +
                    "><textPath href=\"#p\" startOffset=\"8.3333333333333333%\">abc</textPath></text>"));
  // On a vertical line going down the glyphs are turned by 90 degrees about the path's points.
  const std::vector<HandGlyph> down = glyphs_of(layout, [&](std::size_t, const PositionedGlyph& g) {
    return at({60.0, 10.0 + g.origin.x}, 90.0);
  });
  check_same(compose(down), render("<path id=\"v\" d=\"M 60 10 L 60 110\"/><text" + kFont +
                                   "><textPath href=\"#v\">abc</textPath></text>"));
  // side="right" walks the path backwards: the horizontal line drawn from its right end, upside down.
  const std::vector<HandGlyph> backwards = glyphs_of(layout, [&](std::size_t, const PositionedGlyph& g) {
    return at({250.0 - g.origin.x, 60.0}, 180.0);
  });
  check_same(
      compose(backwards),
      render("<text" + kFont + "><textPath path=\"M 10 60 L 250 60\" side=\"right\">abc</textPath></text>"));
  // A glyph whose midpoint is past the end of the path is not drawn: a path as long as the first two
  // glyphs' advances plus a bit less than half the third's.
  const double short_length = layout.glyphs[2].origin.x + 0.4 * layout.glyphs[2].advance;
  const std::vector<HandGlyph> two(straight.begin(), straight.begin() + 2);
  const svg::RenderedDocument cut =
      render("<text" + kFont + "><textPath path=\"M 30 60 L " + std::to_string(30.0 + short_length) +
             " 60\">abc</textPath></text>");
  check_same(compose(two), cut);
  // A textPath to nothing draws nothing and says so.
  const svg::RenderedDocument missing =
      render("<text" + kFont + "><textPath href=\"#none\">abc</textPath></text>");
  CHECK(missing.warnings.size() == 1);
  CHECK(inked_pixels(missing.image) == 0);
  // The text around it stays one chunk: "a<textPath/>b" draws as "ab" does, kerned and anchored as one
  // (regression: the pen went to the missing path's origin, and "b" was drawn out of sight).
  const svg::RenderedDocument around =
      render("<text x=\"10\" y=\"60\"" + kFont + ">a<textPath href=\"#none\">zzz</textPath>b</text>");
  CHECK(around.warnings.size() == 1);
  check_same(compose(glyphs_of(shaped(U"ab"), [&](std::size_t, const PositionedGlyph& g) {
               return at({10.0 + g.origin.x, 60.0});
             })),
             svg::RenderedDocument{around.image, {}, {}});
}

TEST_CASE("svg text layout: text after a textPath goes on from the end point of the path") {
  // SVG 2 11.8.3, "Position on path", 5.2.1.3: path_end is the end point of the path minus the position
  // of the first character after the textPath, so that character is drawn at the path's end point,
  // however far the text on the path reached: "ab" on a 100-unit line from (10, 60), then "cd" from
  // (110, 60), not from the end of "ab"'s advance.
  const TextLayout on_path = shaped(U"ab");
  const TextLayout after = shaped(U"cd");
  REQUIRE(on_path.lines.front().advance < 60.0);  // "ab" ends well before the path does
  std::vector<HandGlyph> glyphs = glyphs_of(on_path, [&](std::size_t, const PositionedGlyph& g) {
    return at({10.0 + g.origin.x, 60.0});
  });
  for (const HandGlyph& glyph : glyphs_of(after, [&](std::size_t, const PositionedGlyph& g) {
         return at({110.0 + g.origin.x, 60.0});
       }))
    glyphs.push_back(glyph);
  check_same(compose(glyphs),
             render("<text" + kFont + "><textPath path=\"M 10 60 L 110 60\">ab</textPath>cd</text>"));
}

TEST_CASE("svg text layout: an absolute x inside a textPath is a new distance along the path") {
  // SVG 1.1 10.13.3: the value is the distance along the path. On a straight path from (20, 60) to the
  // right, "ab" from the <text>'s x = 60 and "cd" from the tspan's x = 170 draw as two plain texts at
  // x = 80 and 190; the <text>'s y is not a position on the path (ignored). The tspan positions its own
  // characters, so it is shaped apart on both sides (no kerning across b|c).
  const std::string path = "<textPath path=\"M 20 60 L 250 60\">";
  const svg::RenderedDocument plain =
      render("<text x=\"80\" y=\"60\"" + kFont + ">ab</text><text x=\"190\" y=\"60\"" + kFont + ">cd</text>");
  CHECK(inked_pixels(plain.image) > 100);
  const svg::RenderedDocument on_path = render("<text x=\"60\" y=\"5\"" + kFont + ">" + path +
                                               "ab<tspan x=\"170\">cd</tspan></textPath></text>");
  CHECK(on_path.warnings.empty());
  CHECK(max_delta(plain.image, on_path.image) <= 1);
}

TEST_CASE("svg text layout: a textPath is followed as closely when its path is drawn small and scaled up") {
  // Regression: the path was flattened within 0.01 user units, a whole pixel under scale(100), and the
  // glyphs on a curve sat visibly off it. The same drawing at 1/100 of the size under scale(100) must
  // draw what the full-size one draws: the flattening tolerance follows the path's size, so both sides
  // place the glyphs on polylines that are scaled copies; only rounding (1/255, as check_same) differs.
  const std::string curve = "M 20 60 C 60 110 120 10 240 60";
  const std::string tiny = "M 0.2 0.6 C 0.6 1.1 1.2 0.1 2.4 0.6";
  const svg::RenderedDocument full =
      render("<text font-family=\"DejaVu Sans\" font-size=\"24\"><textPath path=\"" + curve +
             "\">Some long text</textPath></text>");
  CHECK(inked_pixels(full.image) > 100);
  check_same(full.image, render("<g transform=\"scale(100)\"><text font-family=\"DejaVu Sans\" "
                                "font-size=\"0.24\"><textPath path=\"" +
                                tiny + "\">Some long text</textPath></text></g>"));
}

TEST_CASE("svg text layout: upright glyphs of vertical text on a textPath turn with the path") {
  // Upright glyphs stand with their own down along the line: on a vertical line that is no turn, so a
  // straight path down the page draws what the plain vertical line draws; on any other path they turn
  // with the tangent as sideways glyphs do, so the whole drawing turns with the path: text on a path to
  // the right is the same drawing as text on a path down, turned by -90 degrees about the start. Both
  // sides fill the same curves; the quarter turn about a whole-pixel point maps pixels onto pixels, so
  // only the rounding of 255 x coverage may differ (1/255, as check_same).
  const std::string upright = kFont + "writing-mode=\"tb\" text-orientation=\"upright\"";
  const std::string abc = ">Abc</textPath></text>";
  const svg::RenderedDocument line = render("<text x=\"20\" y=\"10\"" + upright + ">Abc</text>");
  check_same(line.image, render("<text" + upright + "><textPath path=\"M 20 10 L 20 300\"" + abc));
  const svg::RenderedDocument down = render("<g transform=\"rotate(-90 20 100)\"><text" + upright +
                                            "><textPath path=\"M 20 100 L 20 400\"" + abc + "</g>");
  check_same(down.image, render("<text" + upright + "><textPath path=\"M 20 100 L 300 100\"" + abc));
  // Not the glyphs left standing as on a vertical line (what was drawn before): those differ.
  CHECK(max_delta(
            down.image,
            render("<text x=\"20\" y=\"10\"" + upright + " transform=\"translate(0 90)\">Abc</text>").image) >
        100);
}

TEST_CASE("svg text layout: writing-mode sideways-rl and sideways-lr set every glyph sideways") {
  // CSS Writing Modes 3 section 3.1: sideways-rl is a vertical-rl line with every glyph sideways (tops to
  // the right), sideways-lr one that runs bottom to top with the tops to the left; both are in horizontal
  // typographic mode, so on the alphabetic baseline (section 4.2), not the central one of vertical-rl.
  // The ideograph U+4E2D (.notdef here: no test font has it) is turned like the Latin letters.
  const TextLayout layout = shaped(U"Ab\u4E2D");
  const auto down = [&](std::size_t, const PositionedGlyph& g) {
    return Affine::translate(100.0, 0.0) * Affine{0.0, 1.0, -1.0, 0.0, 0.0, 0.0} *
           at({10.0 + g.origin.x, 0.0});
  };
  const auto up = [&](std::size_t, const PositionedGlyph& g) {
    return Affine::translate(100.0, 0.0) * Affine{0.0, -1.0, 1.0, 0.0, 0.0, 0.0} *
           at({-110.0 + g.origin.x, 0.0});
  };
  const svg::RenderedDocument rl = render("<text x=\"100\" y=\"10\"" + kFont +
                                          "style=\"writing-mode: sideways-rl\">Ab\xe4\xb8\xad</text>");
  REQUIRE(rl.warnings.size() == 1);  // the missing ideograph, and no "not supported"
  CHECK(max_delta(compose(glyphs_of(layout, down)), rl.image) <= 1);
  CHECK(inked_pixels(rl.image) > 100);
  // sideways-lr from y = 110 up. dy moves along the line and dx across it; both stay shifts in user space
  // (dy -7 is 7 up the page, with the line), as on the other vertical lines.
  const svg::RenderedDocument lr = render("<text x=\"100\" y=\"110\"" + kFont +
                                          "style=\"writing-mode: sideways-lr\">Ab\xe4\xb8\xad</text>");
  CHECK(max_delta(compose(glyphs_of(layout, up)), lr.image) <= 1);
  CHECK(inked_pixels(lr.image) > 100);
  const auto moved = [&](std::size_t i, const PositionedGlyph& g) {
    return Affine::translate(i == 0 ? 100.0 : 104.0, i == 0 ? 0.0 : -7.0) *
           Affine{0.0, -1.0, 1.0, 0.0, 0.0, 0.0} * at({-110.0 + g.origin.x, 0.0});
  };
  CHECK(max_delta(compose(glyphs_of(layout, moved)),
                  render("<text x=\"100\" y=\"110\"" + kFont +
                         "style=\"writing-mode: sideways-lr\" dx=\"0 4\" dy=\"0 -7\">Ab\xe4\xb8\xad</text>")
                      .image) <= 1);
}

TEST_CASE("svg text layout: vertical writing mode turns Latin sideways and stands CJK upright") {
  const FontMetrics m = dejavu().metrics();
  const double scale = kSize / m.units_per_em;
  // Latin on a vertical line: the horizontal layout turned by 90 degrees about the start (x, y), on the
  // central baseline (halfway between ascender and descender), so its tops face right (vertical-rl).
  const TextLayout layout = shaped(U"Abc");
  const double central = 0.5 * (m.ascender + m.descender) * scale;
  const auto sideways = [&](std::size_t, const PositionedGlyph& g) {
    return Affine::translate(100.0, 0.0) * Affine{0.0, 1.0, -1.0, 0.0, 0.0, 0.0} *
           at({10.0 + g.origin.x, central});
  };
  check_same(compose(glyphs_of(layout, sideways)),
             render("<text x=\"100\" y=\"10\"" + kFont + "writing-mode=\"tb\">Abc</text>"));
  check_same(compose(glyphs_of(layout, sideways)),
             render("<text x=\"100\" y=\"10\"" + kFont + "style=\"writing-mode: vertical-rl\">Abc</text>"));
  // dy moves along the line, dx across it.
  const auto moved = [&](std::size_t i, const PositionedGlyph& g) {
    return Affine::translate(i == 0 ? 100.0 : 104.0, i == 0 ? 0.0 : 7.0) *
           Affine{0.0, 1.0, -1.0, 0.0, 0.0, 0.0} * at({10.0 + g.origin.x, central});
  };
  check_same(
      compose(glyphs_of(layout, moved)),
      render("<text x=\"100\" y=\"10\"" + kFont + "writing-mode=\"tb\" dx=\"0 4\" dy=\"0 7\">Abc</text>"));
  // U+4E2D (a CJK ideograph; no font of the tests has it, so the face's .notdef box is drawn, with a
  // warning) stands upright, shaped with the vertical direction (text_layout.h, TextStyle::vertical: the
  // font's vertical advance and origin, here HarfBuzz's fallbacks as DejaVu Sans has no vmtx), the line
  // at x = 100 from y = 10 — the library's vertical layout at that origin, drawn upright.
  TextStyle vertical_style;
  vertical_style.size = kSize;
  vertical_style.vertical = true;
  const Result<TextLayout> column = layout_text(dejavu(), U"\u4E2D\u4E2D", {100.0, 10.0}, vertical_style);
  REQUIRE(column.is_ok());
  REQUIRE(column->glyphs.size() == 2);
  // Centred across the line, one advance apart down it.
  // (HarfBuzz halves the advance in whole font units: within half a unit.)
  CHECK(column->glyphs[0].origin.x == Approx(100.0 - 0.5 * dejavu().advance(kNotdefGlyph) * scale).margin(0.5 * scale));
  CHECK(column->glyphs[1].origin.y == Approx(column->glyphs[0].origin.y + column->glyphs[0].advance));
  const svg::RenderedDocument upright =
      render("<text x=\"100\" y=\"10\"" + kFont + "writing-mode=\"tb\">\xe4\xb8\xad\xe4\xb8\xad</text>");
  const Image expected = compose({{kNotdefGlyph, at(column->glyphs[0].origin)}, {kNotdefGlyph, at(column->glyphs[1].origin)}});
  REQUIRE(upright.warnings.size() == 1);
  CHECK(upright.warnings.front().find("U+4E2D") != std::string::npos);
  CHECK(inked_pixels(expected) > 100);
  CHECK(max_delta(expected, upright.image) <= 1);
  // text-orientation: upright (and SVG 1.1's glyph-orientation-vertical="0") stands Latin upright too,
  // shaped vertically as the ideographs are; sideways (glyph-orientation-vertical="90") turns every
  // character, the ideographs too, as horizontal text on the central baseline.
  const Result<TextLayout> latin_column = layout_text(dejavu(), U"Abc", {100.0, 10.0}, vertical_style);
  REQUIRE(latin_column.is_ok());
  const Image latin_upright = compose(glyphs_of(*latin_column, [&](std::size_t, const PositionedGlyph& g) { return at(g.origin); }));
  check_same(latin_upright, render("<text x=\"100\" y=\"10\"" + kFont + "writing-mode=\"tb\" text-orientation=\"upright\">Abc</text>"));
  check_same(latin_upright,
             render("<text x=\"100\" y=\"10\"" + kFont + "writing-mode=\"tb\" glyph-orientation-vertical=\"0\">Abc</text>"));
  CHECK(max_delta(latin_upright, compose(glyphs_of(layout, sideways))) > 100);
  const TextLayout ideographs = shaped(U"\u4E2D\u4E2D");
  const Image turned = compose(glyphs_of(ideographs, sideways));
  const svg::RenderedDocument sideways_ideographs = render("<text x=\"100\" y=\"10\"" + kFont +
                                                           "writing-mode=\"tb\" text-orientation=\"sideways\">\xe4\xb8\xad\xe4\xb8\xad</text>");
  CHECK(inked_pixels(turned) > 100);
  CHECK(max_delta(turned, sideways_ideographs.image) <= 1);
  const svg::RenderedDocument turned_90 = render("<text x=\"100\" y=\"10\"" + kFont +
                                                 "writing-mode=\"tb\" glyph-orientation-vertical=\"90deg\">\xe4\xb8\xad\xe4\xb8\xad</text>");
  CHECK(max_delta(turned, turned_90.image) <= 1);
}

TEST_CASE("svg text layout: a percentage letter-spacing or word-spacing is of the font size (CSS Text 4)") {
  // The same glyphs as letter-spacing 3 and word-spacing 11 at 24 px: 12.5 % and 45.8333 % of 24.
  const TextLayout layout = shaped(U"Ta Va", TextDirection::kLeftToRight, false, /*ligatures=*/false);
  const Image expected = compose(glyphs_of(layout, [&](std::size_t i, const PositionedGlyph& g) {
    const double extra = 3.0 * static_cast<double>(i) + (g.character_index > 2 ? 11.0 : 0.0);
    return at({10.0 + g.origin.x + extra, 60.0});
  }));
  check_same(expected, render("<text x=\"10\" y=\"60\"" + kFont +
                              "letter-spacing=\"12.5%\" word-spacing=\"45.833333333333%\">Ta Va</text>"));
  // The percentage is inherited as a percentage and resolved against the text's own 24 px, not the
  // group's 16 px (the web-platform test css/css-text/letter-spacing/letter-spacing-percent-001).
  check_same(expected,
             render("<g style=\"letter-spacing:12.5%; word-spacing:45.833333333333%\"><text x=\"10\" "
                    "y=\"60\"" +
                    kFont + ">Ta Va</text></g>"));
}

TEST_CASE("svg text layout: letter-spacing leaves the letters of a cursive script joined (CSS Text 4)") {
  // Arabic "slam slam": DejaVu Sans has the Arabic letters and their joining forms.
  const std::string words = "\xd8\xb3\xd9\x84\xd8\xa7\xd9\x85 \xd8\xb3\xd9\x84\xd8\xa7\xd9\x85";
  const svg::RenderedDocument plain = render("<text x=\"10\" y=\"60\"" + kFont + ">" + words + "</text>");
  CHECK(inked_pixels(plain.image) > 100);
  // The letters get no letter-spacing: a single word draws as without it...
  const std::string word = words.substr(0, 8);
  CHECK(max_delta(
            render("<text x=\"10\" y=\"60\"" + kFont + ">" + word + "</text>").image,
            render("<text x=\"10\" y=\"60\"" + kFont + "letter-spacing=\"6\">" + word + "</text>").image) <=
        1);
  // ...and the space between two words, not of a cursive script, still gets it: the same as a word-spacing
  // of the same length.
  const svg::RenderedDocument spaced =
      render("<text x=\"10\" y=\"60\"" + kFont + "letter-spacing=\"6\">" + words + "</text>");
  CHECK(max_delta(spaced.image, plain.image) > 100);
  CHECK(max_delta(
            spaced.image,
            render("<text x=\"10\" y=\"60\"" + kFont + "word-spacing=\"6\">" + words + "</text>").image) <=
        1);
}

TEST_CASE("svg text layout: dominant-baseline no-change and reset-size keep the parent's baseline") {
  const FontMetrics m = dejavu().metrics();
  const double central = 0.5 * (m.ascender + m.descender) * kSize / m.units_per_em;
  const TextLayout layout = shaped(U"Hx");
  const Image expected = compose(glyphs_of(layout, [&](std::size_t, const PositionedGlyph& g) {
    return at({10.0 + g.origin.x, 60.0 + central});
  }));
  // SVG 1.1 10.9.2: both keep the parent's dominant baseline (central), where use-script and auto
  // would give the alphabetic one to Latin text.
  for (const char* value : {"no-change", "reset-size"}) {
    INFO(value);
    check_same(expected, render("<text x=\"10\" y=\"60\"" + kFont +
                                "dominant-baseline=\"central\">H<tspan dominant-baseline=\"" + value +
                                "\">x</tspan></text>"));
  }
}

TEST_CASE("svg text layout: a fallback face's glyphs sit on the dominant baseline by its own metrics") {
  // Cantarell has no U+2660 (spade): it is drawn from DejaVu Sans (tests/fonts/fonts.conf.in ranks it
  // first), and on the central baseline it is centred by DejaVu's ascent and descent, not Cantarell's
  // (CSS Inline 3 section 2: each glyph aligns its own baseline of the dominant type). The same as two
  // <text> elements, one per face, the second at the first's advance (no kerning across faces).
  const double spade = shaped(U"\u2660").lines.front().advance;
  const std::string central = "font-size=\"24\" dominant-baseline=\"central\"";
  const svg::RenderedDocument mixed =
      render("<text x=\"10\" y=\"60\" font-family=\"Cantarell\" " + central + ">\xe2\x99\xa0H</text>");
  const svg::RenderedDocument separate = render(
      "<text x=\"10\" y=\"60\" font-family=\"DejaVu Sans\" " + central + ">\xe2\x99\xa0</text><text x=\"" +
      std::to_string(10.0 + spade) + "\" y=\"60\" font-family=\"Cantarell\" " + central + ">H</text>");
  CHECK(inked_pixels(mixed.image) > 100);
  CHECK(max_delta(mixed.image, separate.image) <= 1);
}

TEST_CASE("svg text layout: a rotated glyph turns its piece of the text decoration with it") {
  // One glyph turned by rotate about its origin (x, y) is the unturned text turned about (x, y) by a
  // group, its underline and line-through included (each rotated character carries its own piece of the
  // decoration, as browsers draw it).
  for (const char* decoration : {"underline", "line-through", "overline"}) {
    INFO(decoration);
    const svg::RenderedDocument turned = render(
        "<text x=\"60\" y=\"60\"" + kFont + "rotate=\"30\" text-decoration=\"" + decoration + "\">W</text>");
    const svg::RenderedDocument grouped =
        render("<g transform=\"rotate(30 60 60)\"><text x=\"60\" y=\"60\"" + kFont + "text-decoration=\"" +
               decoration + "\">W</text></g>");
    CHECK(inked_pixels(turned.image) > 100);
    CHECK(max_delta(turned.image, grouped.image) <= 1);
  }
}
