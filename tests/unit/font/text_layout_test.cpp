// Text layout: advances and kerning against FreeType's own numbers, lines, anchors, .notdef fallback,
// ligatures, limits, and text_path.
#include <ft2build.h>
#include FT_FREETYPE_H

#include <catch2/catch.hpp>
#include <string>

#include "curvescan/text/text_layout.h"
#include "font_files.h"

using namespace curvescan;

namespace {

// FreeType's unscaled (font-unit) numbers, from an FT_Face of its own.
struct FreeTypeMetrics {
  FT_Library library = nullptr;
  FT_Face face = nullptr;
  explicit FreeTypeMetrics(const char* file) {
    REQUIRE(FT_Init_FreeType(&library) == 0);
    REQUIRE(FT_New_Face(library, file, 0, &face) == 0);
  }
  ~FreeTypeMetrics() {
    FT_Done_Face(face);
    FT_Done_FreeType(library);
  }
  FreeTypeMetrics(const FreeTypeMetrics&) = delete;
  FreeTypeMetrics& operator=(const FreeTypeMetrics&) = delete;

  double advance(char32_t c) const {
    REQUIRE(FT_Load_Char(face, c, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING) == 0);
    return static_cast<double>(face->glyph->advance.x);
  }
  double kerning(char32_t left, char32_t right) const {
    FT_Vector k{};
    REQUIRE(FT_Get_Kerning(face, FT_Get_Char_Index(face, left), FT_Get_Char_Index(face, right),
                           FT_KERNING_UNSCALED, &k) == 0);
    return static_cast<double>(k.x);
  }
};

Font open_font(const char* file) {
  Result<Font> font = Font::open(file);
  REQUIRE(font.is_ok());
  return std::move(font).value();
}

}  // namespace

TEST_CASE("layout: unkerned advances are FreeType's, scaled by size / units_per_em", "[font][layout]") {
  for (const char* file : {kDejaVuSansFile, kCantarellFile}) {
    const Font font = open_font(file);
    const FreeTypeMetrics ft(file);
    TextStyle style;
    style.size = 37.0;
    style.kerning = false;
    style.ligatures = false;
    const std::u32string text = U"Hamburgefonstiv, WAVE 0123!";
    const Result<TextLayout> layout = layout_text(font, text, {10.0, 50.0}, style);
    REQUIRE(layout.is_ok());
    REQUIRE(layout->glyphs.size() == text.size());
    const double scale = 37.0 / font.metrics().units_per_em;
    double pen = 10.0;
    for (std::size_t i = 0; i < text.size(); ++i) {
      // Sums of at most 30 font-unit integers times one scale: relative error ~1e-15.
      CHECK(layout->glyphs[i].origin.x == Approx(pen).margin(1e-9));
      CHECK(layout->glyphs[i].origin.y == 50.0);
      CHECK(font.advance(layout->glyphs[i].glyph) == ft.advance(text[i]));
      pen += ft.advance(text[i]) * scale;
    }
    CHECK(layout->lines.front().advance == Approx(pen - 10.0).margin(1e-9));
  }
}

TEST_CASE("layout: kerning pairs match FreeType's kern table (DejaVu Sans)", "[font][layout]") {
  const Font font = open_font(kDejaVuSansFile);
  const FreeTypeMetrics ft(kDejaVuSansFile);
  REQUIRE(FT_HAS_KERNING(ft.face));
  TextStyle style;
  style.size = static_cast<double>(font.metrics().units_per_em);  // user units = font units
  int kerned_pairs = 0;
  for (const std::u32string pair : {U"AV", U"AT", U"To", U"LT", U"Ty", U"VA", U"Yo", U"P.", U"HH"}) {
    const Result<TextLayout> layout = layout_text(font, pair, {0.0, 0.0}, style);
    REQUIRE(layout.is_ok());
    REQUIRE(layout->glyphs.size() == 2);
    const double expected = ft.advance(pair[0]) + ft.kerning(pair[0], pair[1]);
    INFO("pair " << static_cast<char>(pair[0]) << static_cast<char>(pair[1]));
    CHECK(layout->glyphs[1].origin.x == expected);  // integers in font units: exact
    kerned_pairs += ft.kerning(pair[0], pair[1]) != 0.0 ? 1 : 0;
  }
  CHECK(kerned_pairs >= 5);  // the test must see real kerning, not only zeros
}

TEST_CASE("layout: a combining mark is positioned by the font and takes no advance (Cantarell)",
          "[font][layout]") {
  // Cantarell (CFF) has GDEF and GPOS but no kerning pairs for ASCII; its mark positioning is what
  // shaping adds here. Without shaping U+0301 would advance the pen by its own width.
  const Font font = open_font(kCantarellFile);
  TextStyle style;
  style.size = static_cast<double>(font.metrics().units_per_em);  // user units = font units
  // "x" + COMBINING ACUTE: no precomposed character exists, so HarfBuzz cannot compose it away.
  const Result<TextLayout> layout = layout_text(font, U"x\u0301y", {0.0, 0.0}, style);
  REQUIRE(layout.is_ok());
  REQUIRE(layout->glyphs.size() == 3);
  CHECK(layout->glyphs[1].character_index == 0);  // HarfBuzz merges a mark into its base's cluster
  CHECK(layout->glyphs[2].origin.x == font.advance(font.glyph_for(U'x')));  // integers: exact
  CHECK(layout->glyphs[1].origin.x < layout->glyphs[2].origin.x);           // the mark sits over the x
}

TEST_CASE("layout: lines, line height, anchors and the line box", "[font][layout]") {
  const Font font = open_font(kDejaVuSansFile);
  const FontMetrics m = font.metrics();
  TextStyle style;
  style.size = 20.0;
  const double scale = 20.0 / m.units_per_em;
  const Result<TextLayout> start = layout_text(font, U"a\r\nbbb\n\nc", {100.0, 40.0}, style);
  REQUIRE(start.is_ok());
  REQUIRE(start->lines.size() == 4);
  CHECK(start->glyphs.size() == 5);  // the CR is dropped, the empty line has no glyph
  for (std::size_t i = 0; i < 4; ++i) {
    CHECK(start->lines[i].origin.x == 100.0);
    CHECK(start->lines[i].origin.y == Approx(40.0 + static_cast<double>(i) * m.line_height * scale));
  }
  CHECK(start->lines[2].glyph_count == 0);
  CHECK(start->lines[2].advance == 0.0);
  const Rect box = start->line_box();
  CHECK(box.x0 == 100.0);
  CHECK(box.x1 == Approx(100.0 + start->lines[1].advance));  // the widest line
  CHECK(box.y0 == Approx(40.0 - m.ascender * scale));
  CHECK(box.y1 == Approx(40.0 + 3 * m.line_height * scale - m.descender * scale));

  style.anchor = TextAnchor::kMiddle;
  const Result<TextLayout> middle = layout_text(font, U"a\nbbb", {100.0, 40.0}, style);
  REQUIRE(middle.is_ok());
  for (const TextLine& line : middle->lines) CHECK(line.origin.x == Approx(100.0 - 0.5 * line.advance));
  style.anchor = TextAnchor::kEnd;
  const Result<TextLayout> end = layout_text(font, U"a\nbbb", {100.0, 40.0}, style);
  REQUIRE(end.is_ok());
  for (const TextLine& line : end->lines) CHECK(line.origin.x + line.advance == Approx(100.0));
}

TEST_CASE("layout: characters without a glyph become .notdef and are reported once", "[font][layout]") {
  const Font font = open_font(kCantarellFile);
  REQUIRE(font.glyph_for(U'\u4E2D') == kNotdefGlyph);  // Cantarell has no CJK
  const Result<TextLayout> layout = layout_text(font, U"x\u4E2Dy\u4E2D\u0F00", {0.0, 0.0}, {});
  REQUIRE(layout.is_ok());
  CHECK(layout->missing_characters == U"\u4E2D\u0F00");
  REQUIRE(layout->glyphs.size() == 5);
  CHECK(layout->glyphs[1].glyph == kNotdefGlyph);
  CHECK(layout->glyphs[1].character_index == 1);
  // .notdef has an outline (Cantarell's is a box), so the fallback is visible.
  const Result<Path> notdef = font.glyph_path(kNotdefGlyph);
  REQUIRE(notdef.is_ok());
  CHECK_FALSE(notdef->empty());
}

TEST_CASE("layout: ligatures follow the style", "[font][layout]") {
  const Font font = open_font(kCantarellFile);
  TextStyle style;
  const Result<TextLayout> on = layout_text(font, U"fi", {0.0, 0.0}, style);
  style.ligatures = false;
  const Result<TextLayout> off = layout_text(font, U"fi", {0.0, 0.0}, style);
  REQUIRE(on.is_ok());
  REQUIRE(off.is_ok());
  CHECK(off->glyphs.size() == 2);
  CHECK(on->glyphs.size() == 1);
}

TEST_CASE("layout: sizes, origins and lengths outside the limits are refused", "[font][layout]") {
  const Font font = open_font(kDejaVuSansFile);
  for (const double size : {0.0, -1.0, kMaxTextSize * 2, std::nan("")}) {
    TextStyle style;
    style.size = size;
    const Result<TextLayout> layout = layout_text(font, U"x", {0.0, 0.0}, style);
    REQUIRE_FALSE(layout.is_ok());
    CHECK(layout.error().kind == ErrorKind::kInvalidArgument);
  }
  CHECK_FALSE(layout_text(font, U"x", {std::nan(""), 0.0}, {}).is_ok());
  const std::u32string long_text(kMaxTextCharacters + 1, U'x');
  const Result<TextLayout> too_long = layout_text(font, long_text, {0.0, 0.0}, {});
  REQUIRE_FALSE(too_long.is_ok());
  CHECK(too_long.error().kind == ErrorKind::kLimitExceeded);
}

TEST_CASE("text_path: outlines at the layout's positions — invalid UTF-8 is an error", "[font][layout]") {
  const Font font = open_font(kDejaVuSansFile);
  TextStyle style;
  style.size = 100.0;
  const Result<Path> path = text_path(font, "H\xC3\x89", {10.0, 200.0}, style);  // "HÉ": flat bottoms
  REQUIRE(path.is_ok());
  const Rect bounds = path->bounds();
  const double s = 100.0 / font.metrics().units_per_em;
  const Result<Path> h = font.glyph_path(font.glyph_for(U'H'), {s, 0.0, 0.0, -s, 10.0, 200.0});
  REQUIRE(h.is_ok());
  CHECK(bounds.x0 == Approx(h->bounds().x0));      // the H starts the text, at the origin
  CHECK(bounds.y1 == Approx(200.0).margin(1e-9));  // neither glyph descends below the baseline
  CHECK(bounds.y0 < h->bounds().y0);               // the accent of the É rises above the H
  const Result<Path> bad = text_path(font, "ok\xC3", {0.0, 0.0}, style);
  REQUIRE_FALSE(bad.is_ok());
  CHECK(bad.error().message.find("UTF-8") != std::string::npos);
}

// Regression: a letter followed by 10^5 combining acute accents took 20 s in HarfBuzz 6, whose mark
// attachment is quadratic in the marks after one base. Past 32 marks in a row the layout shapes the marks
// in pieces of 32; this checks the structure of that cut (the time is measured in bench/, not here).
TEST_CASE("layout: a long run of combining marks is shaped in pieces of 32", "[font][layout]") {
  const Font font = open_font(kDejaVuSansFile);
  // DejaVu Sans attaches acute accents to "a" and stacks them on each other (mark-to-base, then
  // mark-to-mark); HarfBuzz composes "a" and the first accent into one glyph, U+00E1.
  std::u32string text = U"a";
  text.append(100, U'\u0301');
  text += U"b";
  const Result<TextLayout> layout = layout_text(font, text, {0.0, 0.0}, {});
  REQUIRE(layout.is_ok());
  REQUIRE(layout->glyphs.size() == 101);
  // Characters "a" + 32 marks (32 glyphs), 32 marks, 32 marks, then 4 marks and "b" (a base: it joins the
  // run it follows, as the face is the same and no cut is due).
  REQUIRE(layout->runs.size() == 4);
  CHECK(layout->runs[0].glyph_count == 32);
  CHECK(layout->runs[1].glyph_count == 32);
  CHECK(layout->runs[2].glyph_count == 32);
  CHECK(layout->runs[3].glyph_count == 5);
  // Within the first piece each accent sits above the one before; the next piece starts again from the
  // pen, as marks without a base.
  for (std::size_t g = 2; g < 32; ++g) CHECK(layout->glyphs[g].origin.y < layout->glyphs[g - 1].origin.y);
  CHECK(layout->glyphs[32].origin.y == layout->glyphs[1].origin.y);
  // Every mark takes no advance, so "b" starts where "a" ends, as it does after a single accent.
  const Result<TextLayout> one = layout_text(font, U"a\u0301b", {0.0, 0.0}, {});
  REQUIRE(one.is_ok());
  CHECK(layout->glyphs.back().origin.x == one->glyphs.back().origin.x);
}

// Regression: missing characters were collected with a linear search per .notdef glyph, quadratic in the
// number of distinct missing characters.
TEST_CASE("layout: many distinct missing characters are each reported once, in order", "[font][layout]") {
  const Font font = open_font(kCantarellFile);
  std::u32string text, expected;
  for (char32_t c = U'\u4E00'; c < U'\u4E00' + 2000; ++c) {
    REQUIRE(font.glyph_for(c) == kNotdefGlyph);
    expected += c;
    text += c;
    text += c;
  }
  const Result<TextLayout> layout = layout_text(font, text, {0.0, 0.0}, {});
  REQUIRE(layout.is_ok());
  CHECK(layout->missing_characters == expected);
}

namespace {

// The tab tests' style: 20 px, no kerning, so that advances add up exactly.
TextStyle tab_test_style() {
  TextStyle style;
  style.size = 20.0;
  style.kerning = false;
  return style;
}

// The advance of `character`'s glyph in pixels at `style`'s size.
double advance_px(const Font& font, char32_t character, const TextStyle& style) {
  return font.advance(font.glyph_for(character)) * style.size / font.metrics().units_per_em;
}

}  // namespace

// Regression: a tab was shaped as a character, and DejaVu Sans has no glyph for U+0009, so `curvescan text`
// drew a .notdef box and warned that no installed font had the character.
TEST_CASE("layout: a tab advances to the next tab stop, every 8 spaces from the line's start",
          "[font][layout]") {
  const Font font = open_font(kDejaVuSansFile);
  TextStyle style = tab_test_style();
  const double space = advance_px(font, U' ', style);
  const double interval = 8.0 * space;
  // The positions are sums and products of the same few doubles: exact up to rounding, far below 1e-9.
  const auto x_of = [](const TextLayout& layout, std::size_t character) {
    for (const PositionedGlyph& glyph : layout.glyphs)
      if (glyph.character_index == character) return glyph.origin.x;
    FAIL("no glyph for character " << character);
    return 0.0;
  };
  const Result<TextLayout> one = layout_text(font, U"a\tb", {0.0, 0.0}, style);
  REQUIRE(one.is_ok());
  CHECK(one->missing_characters.empty());
  CHECK(x_of(*one, 2) == Approx(interval).margin(1e-9));
  // The tab is drawn as the space glyph: nothing.
  CHECK(one->glyphs[1].glyph == font.glyph_for(U' '));
  // Two tabs: two stops; a tab right at a stop goes to the next one.
  const Result<TextLayout> two = layout_text(font, U"\t\tx", {0.0, 0.0}, style);
  REQUIRE(two.is_ok());
  CHECK(x_of(*two, 2) == Approx(2.0 * interval).margin(1e-9));
  // Eight spaces then a tab: the pen is at the first stop, so the tab goes to the second.
  const Result<TextLayout> spaces = layout_text(font, U"        \ty", {0.0, 0.0}, style);
  REQUIRE(spaces.is_ok());
  CHECK(x_of(*spaces, 9) == Approx(2.0 * interval).margin(1e-9));
  // Seven and a bit spaces' worth before the tab: a stop nearer than half a space is passed over.
  const Result<TextLayout> near_stop = layout_text(font, U"       .\tz", {0.0, 0.0}, style);
  REQUIRE(near_stop.is_ok());
  const double pen = x_of(*near_stop, 8);
  const double expected = interval - pen < 0.5 * space ? 2.0 * interval : interval;
  CHECK(x_of(*near_stop, 9) == Approx(expected).margin(1e-9));
}

// CSS Text 3 section 4.2: tab stops are measured from the start edge of the line, which on a right-to-left
// line is its right end (before, such a tab advanced a fixed 8 spaces wherever it stood).
TEST_CASE("layout: on a right-to-left line a tab advances to the next stop measured from the right end",
          "[font][layout][bidi]") {
  const Font font = open_font(kDejaVuSansFile);
  TextStyle style = tab_test_style();
  const double space = advance_px(font, U' ', style);
  const double interval = 8.0 * space;
  const double alef = advance_px(font, U'\u05d0', style);
  REQUIRE(alef > 0.5 * space);  // one letter before the tab is more than half a space from the stop
  REQUIRE(alef < interval - 0.5 * space);
  // The line's right end, its start, is at x = line.origin.x + line.advance; distances from it are sums and
  // differences of the same few doubles: exact up to rounding, far below 1e-9.
  const auto from_start = [](const TextLayout& layout, std::size_t character) {
    const TextLine& line = layout.lines.front();
    for (const PositionedGlyph& glyph : layout.glyphs)
      if (glyph.character_index == character) return line.origin.x + line.advance - glyph.origin.x;
    FAIL("no glyph for character " << character);
    return 0.0;
  };
  // Alef, tab, bet: bet's right side is at the first stop from the right end, its left side one advance on.
  const Result<TextLayout> one = layout_text(font, U"\u05d0\t\u05d1", {0.0, 0.0}, style);
  REQUIRE(one.is_ok());
  REQUIRE(one->lines.front().right_to_left);
  const double bet = advance_px(font, U'\u05d1', style);
  CHECK(from_start(*one, 0) == Approx(alef).margin(1e-9));
  CHECK(from_start(*one, 2) == Approx(interval + bet).margin(1e-9));
  CHECK(one->lines.front().advance == Approx(interval + bet).margin(1e-9));
  // Two tabs after the alef: the second stop; a tab at the start goes to the first stop.
  const Result<TextLayout> two = layout_text(font, U"\u05d0\t\t\u05d1", {0.0, 0.0}, style);
  REQUIRE(two.is_ok());
  CHECK(from_start(*two, 3) == Approx(2.0 * interval + bet).margin(1e-9));
  const Result<TextLayout> leading = layout_text(font, U"\t\u05d1", {0.0, 0.0}, style);
  REQUIRE(leading.is_ok());
  REQUIRE(leading->lines.front().right_to_left);
  CHECK(from_start(*leading, 1) == Approx(interval + bet).margin(1e-9));
  // The same text forced left to right measures from the left end: the tabs fall at the same distances.
  style.direction = TextDirection::kLeftToRight;
  const Result<TextLayout> ltr = layout_text(font, U"a\t\tb", {0.0, 0.0}, style);
  REQUIRE(ltr.is_ok());
  for (const PositionedGlyph& glyph : ltr->glyphs)
    if (glyph.character_index == 3) CHECK(glyph.origin.x == Approx(2.0 * interval).margin(1e-9));
}

// CSS Text 3 section 4.2: on a vertical line too, tab stops are measured from the line's start edge, its
// top (before, a tab there advanced a fixed 8 spaces wherever it stood).
TEST_CASE("layout: on a vertical line a tab advances to the next stop measured from the top",
          "[font][layout][vertical]") {
  const Font font = open_font(kDejaVuSansFile);
  TextStyle style = tab_test_style();
  style.vertical = true;
  const double interval = 8.0 * advance_px(font, U' ', style);
  // The pen along the line: a glyph's origin is its pen moved by its vertical origin (HarfBuzz's offsets),
  // the same for one glyph wherever it stands, so "b" alone gives the offset to take away.
  const auto y_of = [](const TextLayout& layout, std::size_t character) {
    for (const PositionedGlyph& glyph : layout.glyphs)
      if (glyph.character_index == character) return glyph.origin.y;
    FAIL("no glyph for character " << character);
    return 0.0;
  };
  const Result<TextLayout> alone = layout_text(font, U"b", {0.0, 0.0}, style);
  const Result<TextLayout> one = layout_text(font, U"a\tb", {0.0, 0.0}, style);
  REQUIRE(alone.is_ok());
  REQUIRE(one.is_ok());
  // "a" advances by its vertical advance (DejaVu Sans has no vmtx: HarfBuzz's ascender - descender, 23.3 px
  // at 20 px), less than the first stop (50.9 px) by more than half a space: "b" starts at the stop.
  const double a = one->glyphs.front().advance;
  REQUIRE(a > 0.0);
  REQUIRE(interval - a > 0.5 * advance_px(font, U' ', style));
  CHECK(y_of(*one, 2) - y_of(*alone, 0) == Approx(interval).margin(1e-9));
}
