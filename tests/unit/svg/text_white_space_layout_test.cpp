// white-space and text-transform in whole SVG documents (raster/svg/text_whitespace.h,
// text_transform.h), against the exact oracle of text_document_test.cpp: the same glyph outlines laid out by
// the library's own text API (text_layout.h) at the positions the specifications prescribe — forced line
// breaks one line height apart (SVG 2 11.4 "Multi-line text via white-space"), x lists on the addressable
// characters (SVG 2 11.8.3: a kept segment break is one, characters text-transform adds are not).
//
// Tolerance: max |Δ| <= 1/255 per channel, as in text_document_test.cpp: the same curves through the same
// rasterizer, glyph origins summed in another order (~1e-13 px) can flip one rounding level; a wrong line,
// position or character moves whole edges (differences of ~100/255 and more).
#include <catch2/catch.hpp>
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

constexpr int kWidth = 240;
constexpr int kHeight = 100;
constexpr double kSize = 20.0;

svg::RenderedDocument render(const std::string& body) {
  return svg::testing::render_sized(kWidth, kHeight, body);
}

const Font& dejavu() {
  return svg::testing::dejavu_sans();
}

// CSS line-height: normal as the renderer takes it: the font's ascender - descender + line gap.
double line_height() {
  const FontMetrics m = dejavu().metrics();
  return m.line_height * kSize / m.units_per_em;
}

struct Line {
  std::string text;
  Point origin;
  TextAnchor anchor = TextAnchor::kStart;
};

Image oracle(const std::vector<Line>& lines) {
  Result<Canvas> canvas = Canvas::create(kWidth, kHeight);
  REQUIRE(canvas.is_ok());
  for (const Line& line : lines) {
    TextStyle style;
    style.size = kSize;
    style.anchor = line.anchor;
    const Result<Path> path = text_path(dejavu(), line.text, line.origin, style);
    REQUIRE(path.is_ok());
    REQUIRE(canvas->fill(*path, Paint::solid({0, 0, 0, 1}), FillRule::kNonZero, Affine::identity()).is_ok());
  }
  return std::move(*canvas).take_image();
}

// The text must draw something substantial, or "equal" would prove nothing.
void check_same(const Image& expected, const svg::RenderedDocument& actual) {
  CHECK(actual.warnings.empty());
  CHECK(inked_pixels(expected) > 100);
  CHECK(max_delta(expected, actual.image) <= 1);
}

std::string text(const std::string& attributes, const std::string& content) {
  return "<text font-family=\"DejaVu Sans\" font-size=\"20\" " + attributes + ">" + content + "</text>";
}

}  // namespace

TEST_CASE("white-space pre: a newline is a forced line break, the next line one line height lower") {
  const double lh = line_height();
  REQUIRE(lh > kSize);  // DejaVu Sans: (1901 + 483) / 2048 em
  check_same(oracle({{"a  b", {10, 30}}, {"cd", {10, 30 + lh}}, {"e", {10, 30 + 2 * lh}}}),
             render(text("x=\"10\" y=\"30\" style=\"white-space: pre\"", "a  b\ncd\ne")));
  // The presentation attribute (SVG 2 6.6) and pre-wrap, break-spaces do the same.
  for (const char* value : {"pre", "pre-wrap", "break-spaces"}) {
    INFO(value);
    check_same(oracle({{"a  b", {10, 30}}, {"cd", {10, 30 + lh}}}),
               render(text("x=\"10\" y=\"30\" white-space=\"" + std::string(value) + "\"", "a  b\ncd")));
  }
}

TEST_CASE("white-space pre-line: spaces collapse, each line is anchored on its own") {
  const double lh = line_height();
  // "chunks shifted by text-anchor do not span multiple lines" (SVG 2 11.8.3): both lines centred on x.
  // The newline before "one" is kept too: the first line is empty, "one two" is the second.
  check_same(oracle({{"one two", {120, 30 + lh}, TextAnchor::kMiddle},
                     {"three", {120, 30 + 2 * lh}, TextAnchor::kMiddle}}),
             render(text("x=\"120\" y=\"30\" text-anchor=\"middle\" style=\"white-space: pre-line\"",
                         "\n   one   two  \n  three  ")));
}

TEST_CASE("white-space normal: a newline becomes a space, where xml:space=\"default\" removes it") {
  check_same(oracle({{"a b", {10, 30}}}),
             render(text("x=\"10\" y=\"30\" style=\"white-space: normal\"", "a\n  b")));
  check_same(oracle({{"ab", {10, 30}}}), render(text("x=\"10\" y=\"30\"", "a\nb")));
  // nowrap collapses as normal does (its wrapping half is moot without inline-size).
  check_same(oracle({{"a b", {10, 30}}}), render(text("x=\"10\" y=\"30\" white-space=\"nowrap\"", "a\n  b")));
}

TEST_CASE("white-space wins over xml:space, on the element and from an ancestor") {
  // SVG 2 11.7 "Duplicate white-space directives": where white-space is set, xml:space is ignored.
  check_same(oracle({{"x y", {10, 30}}}),
             render(text("x=\"10\" y=\"30\" xml:space=\"preserve\" white-space=\"normal\"", "x   y")));
  check_same(oracle({{"x y", {10, 30}}}),
             render(text("x=\"10\" y=\"30\" white-space=\"normal\" xml:space=\"preserve\"", "x   y")));
  check_same(oracle({{"a  b  c", {10, 30}}}), render(text("x=\"10\" y=\"30\" style=\"white-space: pre\"",
                                                          "a  <tspan xml:space=\"default\">b  c</tspan>")));
  // Without white-space, xml:space still rules, inherited and overridden by a tspan.
  check_same(oracle({{"a  b c", {10, 30}}}), render(text("x=\"10\" y=\"30\" xml:space=\"preserve\"",
                                                         "a  <tspan xml:space=\"default\">b  c</tspan>")));
}

TEST_CASE("white-space pre: a kept newline is an addressable character of the x list") {
  const double lh = line_height();
  // x="10 50 90 130": a at 10, the newline takes 50, b starts the second line at 90, c at 130.
  check_same(oracle({{"a", {10, 30}}, {"b", {90, 30 + lh}}, {"c", {130, 30 + lh}}}),
             render(text("x=\"10 50 90 130\" y=\"30\" style=\"white-space: pre\"", "a\nbc")));
}

TEST_CASE("text-transform: transformed characters are drawn, positions stay on the source characters") {
  check_same(oracle({{"STRASSE Hello", {10, 30}}}),
             render(text("x=\"10\" y=\"30\" style=\"text-transform: uppercase\"",
                         "stra\u00dfe <tspan style=\"text-transform: capitalize\">hello</tspan>")));
  // ß becomes SS, one addressable character: x="10 60 110" puts SS at 10, A at 60 and B at 110.
  check_same(oracle({{"SS", {10, 30}}, {"A", {60, 30}}, {"B", {110, 30}}}),
             render(text("x=\"10 60 110\" y=\"30\" style=\"text-transform: uppercase\"", "\u00dfab")));
  // text-transform inherits; `none` on a tspan stops it; it is no presentation attribute (SVG 2 6.6).
  check_same(oracle({{"ABcd", {10, 30}}}),
             render(text("x=\"10\" y=\"30\" style=\"text-transform: uppercase\"",
                         "a<tspan>b</tspan><tspan style=\"text-transform: none\">cd</tspan>")));
  const svg::RenderedDocument attribute =
      render(text("x=\"10\" y=\"30\" text-transform=\"uppercase\"", "ab"));
  CHECK(max_delta(oracle({{"ab", {10, 30}}}), attribute.image) <= 1);
  CHECK(attribute.warnings.size() == 1);
}

TEST_CASE("text-transform full-width draws what the full-width characters draw") {
  // Document against document: the same characters through the same font fallback.
  const svg::RenderedDocument transformed =
      render(text("x=\"10\" y=\"30\" style=\"text-transform: uppercase full-width\"", "ab 1"));
  const svg::RenderedDocument literal = render(text("x=\"10\" y=\"30\"", "\uff21\uff22\u3000\uff11"));
  CHECK(transformed.warnings == literal.warnings);
  CHECK(inked_pixels(literal.image) > 50);
  CHECK(max_delta(literal.image, transformed.image) == 0);
}

TEST_CASE("white-space and text-transform: invalid values are named and ignored, keywords in any case") {
  // CSS Values 3 2.1: keywords are ASCII case-insensitive; each part of text-transform at most once
  // (CSS Values 3 2.2, the || combinator), so "uppercase lowercase" and "full-width full-width" are invalid.
  for (const char* declaration :
       {"white-space: wrap", "text-transform: uppercase lowercase", "text-transform: full-width full-width",
        "text-transform: none uppercase"}) {
    INFO(declaration);
    const svg::RenderedDocument rendered =
        render(text("x=\"10\" y=\"30\" style=\"" + std::string(declaration) + "\"", "a  b"));
    CHECK(max_delta(oracle({{"a b", {10, 30}}}), rendered.image) <= 1);
    REQUIRE(rendered.warnings.size() == 1);
    CHECK(rendered.warnings.front().find("invalid value") != std::string::npos);
  }
  check_same(oracle({{"A  B", {10, 30}}}),
             render(text("x=\"10\" y=\"30\" style=\"white-space: PRE; text-transform: UpperCase\"", "a  b")));
}
