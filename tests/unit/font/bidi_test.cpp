// The Unicode Bidirectional Algorithm in the layout (bidi.h, text_layout.h), with DejaVu Sans, which has
// Latin, Hebrew and Arabic with its joining forms (GSUB init/medi/fina). Visual order is read from the
// glyph origins: glyphs sorted by x, each glyph knowing the character it draws.
#include "curvescan/text/bidi.h"

#include <algorithm>
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "curvescan/text/text_layout.h"
#include "font_files.h"

using namespace curvescan;

namespace {

Font dejavu() {
  Result<Font> font = Font::open(kDejaVuSansFile);
  REQUIRE(font.is_ok());
  return std::move(font).value();
}

TextLayout lay_out(const Font& font, std::u32string_view text, TextDirection direction = TextDirection::kAuto,
                   bool override_direction = false) {
  TextStyle style;
  style.size = 20.0;
  style.direction = direction;
  style.bidi_override = override_direction;
  Result<TextLayout> layout = layout_text(font, text, {0.0, 0.0}, style);
  REQUIRE(layout.is_ok());
  return std::move(layout).value();
}

// The character indices of the glyphs from left to right (one entry per glyph; ties keep layout order).
std::vector<std::size_t> visual_characters(const TextLayout& layout) {
  std::vector<PositionedGlyph> glyphs = layout.glyphs;
  std::stable_sort(glyphs.begin(), glyphs.end(), [](const PositionedGlyph& a, const PositionedGlyph& b) {
    return a.origin.x < b.origin.x;
  });
  std::vector<std::size_t> order;
  for (const PositionedGlyph& glyph : glyphs) order.push_back(glyph.character_index);
  return order;
}

const PositionedGlyph& glyph_of(const TextLayout& layout, std::size_t character) {
  const auto found = std::find_if(layout.glyphs.begin(), layout.glyphs.end(),
                                  [&](const PositionedGlyph& g) { return g.character_index == character; });
  REQUIRE(found != layout.glyphs.end());
  return *found;
}

}  // namespace

TEST_CASE("bidi: levels of a mixed line follow UAX #9", "[font][bidi]") {
  // "abc " L, Arabic AL, " (" neutrals between R and R -> R (N1), Hebrew R, ") " -> R, "123" EN after R
  // -> level 2 (I2). The trailing space of the line is reset to the paragraph level (L1).
  const BidiParagraph p = resolve_bidi(U"abc \u0645\u0631 (\u05e9\u05dc) 123 ", TextDirection::kAuto);
  CHECK_FALSE(p.right_to_left);
  const std::vector<std::uint8_t> expected{0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 0};
  CHECK(p.levels == expected);
  // First strong character Hebrew: a right-to-left paragraph; Latin inside at level 2.
  const BidiParagraph hebrew = resolve_bidi(U"\u05e9 ab", TextDirection::kAuto);
  CHECK(hebrew.right_to_left);
  CHECK(hebrew.levels == std::vector<std::uint8_t>{1, 1, 2, 2});
  // Forced direction wins over the first strong character.
  CHECK_FALSE(resolve_bidi(U"\u05e9 ab", TextDirection::kLeftToRight).right_to_left);
  // An override puts every character at the base level.
  CHECK(resolve_bidi(U"ab\u05e9", TextDirection::kRightToLeft, true).levels ==
        std::vector<std::uint8_t>{1, 1, 1});
  // Explicit embedding: RLE ... PDF raises Latin to level 2 inside an LTR paragraph.
  const BidiParagraph embedded = resolve_bidi(U"a\u202Bb\u202Cc", TextDirection::kAuto);
  CHECK(embedded.levels[2] == 2);
  CHECK(embedded.levels[4] == 0);
}

TEST_CASE("bidi: rule L2 on runs", "[font][bidi]") {
  // Levels 0 1 2 1 0: the level-2 run alone is reversed (no change), then the 1-2-1 sequence.
  const std::vector<std::uint8_t> levels{0, 1, 2, 1, 0};
  CHECK(visual_run_order(levels) == std::vector<std::size_t>{0, 3, 2, 1, 4});
  const std::vector<std::uint8_t> rtl{1, 2, 2, 1, 3};
  // Level 3 alone; level >= 2: runs 1-2 reversed and 4 alone; level >= 1: everything reversed.
  CHECK(visual_run_order(rtl) == std::vector<std::size_t>{4, 3, 1, 2, 0});
  CHECK(visual_run_order(std::vector<std::uint8_t>{0, 0, 2}) == std::vector<std::size_t>{0, 1, 2});
  CHECK(visual_run_order(std::vector<std::uint8_t>{}).empty());
}

TEST_CASE("bidi: Hebrew inside a Latin line is drawn right to left", "[font][bidi]") {
  const Font font = dejavu();
  // a b space alef bet gimel space c: the Hebrew word reversed in place.
  const TextLayout layout = lay_out(font, U"ab \u05d0\u05d1\u05d2 c");
  CHECK_FALSE(layout.lines.front().right_to_left);
  CHECK(visual_characters(layout) == std::vector<std::size_t>{0, 1, 2, 5, 4, 3, 6, 7});
  CHECK(glyph_of(layout, 3).bidi_level == 1);
  // The same line forced right to left: the Latin runs swap sides, each still left to right inside.
  const TextLayout rtl = lay_out(font, U"ab \u05d0\u05d1\u05d2 c", TextDirection::kRightToLeft);
  CHECK(rtl.lines.front().right_to_left);
  CHECK(visual_characters(rtl) == std::vector<std::size_t>{7, 6, 5, 4, 3, 2, 0, 1});
  // A right-to-left override reverses everything.
  const TextLayout override = lay_out(font, U"abc", TextDirection::kRightToLeft, true);
  CHECK(visual_characters(override) == std::vector<std::size_t>{2, 1, 0});
}

TEST_CASE("bidi: digits in right-to-left text keep their order", "[font][bidi]") {
  const Font font = dejavu();
  // gimel bet alef, space, 1 2 3 in a right-to-left paragraph: the number is at level 2, left to right,
  // and sits left of the Hebrew word.
  const TextLayout layout = lay_out(font, U"\u05d2\u05d1\u05d0 123");
  CHECK(layout.lines.front().right_to_left);
  CHECK(visual_characters(layout) == std::vector<std::size_t>{4, 5, 6, 3, 2, 1, 0});
  CHECK(glyph_of(layout, 4).bidi_level == 2);
}

TEST_CASE("bidi: parentheses are mirrored at odd levels", "[font][bidi]") {
  const Font font = dejavu();
  const TextLayout layout = lay_out(font, U"\u05d0(\u05d1)");
  // "(" is at level 1: drawn with the glyph of ")" (UAX #9 L4, Bidi_Mirroring_Glyph), and vice versa;
  // visually: ( bet ) alef read left to right, with "(" drawn where ")" is in memory.
  CHECK(glyph_of(layout, 1).glyph == font.glyph_for(U')'));
  CHECK(glyph_of(layout, 3).glyph == font.glyph_for(U'('));
  CHECK(visual_characters(layout) == std::vector<std::size_t>{3, 2, 1, 0});
  // At level 0 they are not mirrored.
  const TextLayout latin = lay_out(font, U"a(b)");
  CHECK(glyph_of(latin, 1).glyph == font.glyph_for(U'('));
}

TEST_CASE("bidi: Arabic letters join and the word reads right to left", "[font][bidi]") {
  const Font font = dejavu();
  // beh beh beh: initial, medial and final forms (U+FE91, U+FE92, U+FE90 are those forms' presentation
  // characters, which DejaVu Sans maps to the same glyphs its GSUB substitutes).
  const TextLayout layout = lay_out(font, U"\u0628\u0628\u0628");
  REQUIRE(layout.glyphs.size() == 3);
  const GlyphId isolated = font.glyph_for(U'\u0628');
  for (const PositionedGlyph& glyph : layout.glyphs) CHECK(glyph.glyph != isolated);
  CHECK(glyph_of(layout, 0).glyph == font.glyph_for(U'\uFE91'));
  CHECK(glyph_of(layout, 1).glyph == font.glyph_for(U'\uFE92'));
  CHECK(glyph_of(layout, 2).glyph == font.glyph_for(U'\uFE90'));
  CHECK(visual_characters(layout) == std::vector<std::size_t>{2, 1, 0});
  // Inside a Latin line too, and the Latin stays left to right around it.
  const TextLayout mixed = lay_out(font, U"ab \u0628\u0628 cd");
  CHECK(glyph_of(mixed, 3).glyph == font.glyph_for(U'\uFE91'));
  CHECK(glyph_of(mixed, 4).glyph == font.glyph_for(U'\uFE90'));
  CHECK(visual_characters(mixed) == std::vector<std::size_t>{0, 1, 2, 4, 3, 5, 6, 7});
}

TEST_CASE("bidi: the start of a right-to-left line is its right end", "[font][bidi]") {
  const Font font = dejavu();
  TextStyle style;
  style.size = 20.0;
  const Result<TextLayout> layout = layout_text(font, U"\u05d0\u05d1\nab", {100.0, 50.0}, style);
  REQUIRE(layout.is_ok());
  REQUIRE(layout->lines.size() == 2);
  const TextLine& hebrew = layout->lines[0];
  CHECK(hebrew.right_to_left);
  // text-anchor start at x = 100: the line ends there (exact: origin = 100 - advance).
  CHECK(hebrew.origin.x + hebrew.advance == Approx(100.0).margin(1e-9));
  CHECK(layout->lines[1].origin.x == Approx(100.0).margin(1e-9));
}

// The visual order of mixed lines, cluster by cluster. Each expected order is UAX #9's (the levels noted
// beside it); each was also checked against pango-view 1.50's (its serialized layout, same font), which
// draws every one of them in this order with the same glyphs and advances except where noted.
TEST_CASE("bidi: mixed lines in the visual order of UAX #9, as pango-view draws them", "[font][bidi]") {
  const Font font = dejavu();
  struct Case {
    std::u32string text;
    bool right_to_left;
    std::vector<std::size_t> order;
  };
  const std::vector<Case> cases{
      // Neutrals between runs of two directions take the paragraph's direction (N1, N2).
      {U"\u05e9\u05dc\u05d5\u05dd !!! abc", true, {9, 10, 11, 8, 7, 6, 5, 4, 3, 2, 1, 0}},
      {U"abc !!! \u05e9\u05dc\u05d5\u05dd", false, {0, 1, 2, 3, 4, 5, 6, 7, 11, 10, 9, 8}},
      // A number with its separators and a currency sign in right-to-left text reads left to right (W4,
      // W5: "$100" and "12.5%" at level 2), the colon stays with the Hebrew.
      {U"\u05de\u05d7\u05d9\u05e8: $100 \u05d3\u05d5\u05dc\u05e8",
       true,
       {14, 13, 12, 11, 10, 6, 7, 8, 9, 5, 4, 3, 2, 1, 0}},
      {U"\u05e9\u05dc\u05d5\u05dd 12.5% \u05e2\u05d5\u05dc\u05dd",
       true,
       {14, 13, 12, 11, 10, 5, 6, 7, 8, 9, 4, 3, 2, 1, 0}},
      // A line that starts with digits then Hebrew: the first strong character is R (P2), so the line is
      // right to left and each number, at level 2, sits left of what follows it in memory.
      {U"1 2 3 \u05e9\u05dc\u05d5\u05dd", true, {9, 8, 7, 6, 5, 4, 3, 2, 1, 0}},
      // Numbers on both sides of a Hebrew word in a Latin line: the first stays Latin (level 0), the one
      // after the Hebrew joins its run (W7 leaves it EN, at level 2 inside the level 1 run).
      {U"abc 123 \u05e9\u05dc\u05d5\u05dd 456 def", false, {0,  1,  2,  3,  4, 5, 6,  7,  13, 14,
                                                            15, 12, 11, 10, 9, 8, 16, 17, 18, 19}},
      // Brackets around Latin inside Hebrew take the paragraph's direction (N0) and are mirrored.
      {U"\u05e9\u05dc\u05d5\u05dd (abc) \u05e2\u05d5\u05dc\u05dd",
       true,
       {14, 13, 12, 11, 10, 9, 6, 7, 8, 5, 4, 3, 2, 1, 0}},
      // An embedding (RLE ... PDF) inside a Latin line: the Hebrew at 1, the Latin inside it at 2.
      {U"abc \u202b\u05e9\u05dc\u05d5\u05dd abc \u05e2\u05d5\u05dc\u05dd\u202c def",
       false,
       {0, 1, 2, 3, 4, 18, 17, 16, 15, 14, 13, 10, 11, 12, 9, 8, 7, 6, 5, 19, 20, 21, 22}},
      // An isolate (RLI ... PDI): its content is ordered on its own, the initiator and PDI stay outside.
      {U"abc \u2067\u05e9\u05dc\u05d5\u05dd abc\u2069 def",
       false,
       {0, 1, 2, 3, 4, 10, 11, 12, 9, 8, 7, 6, 5, 13, 14, 15, 16, 17}},
      {U"\u05e9\u05dc\u05d5\u05dd \u2066abc 123\u2069 \u05e2\u05d5\u05dc\u05dd",
       true,
       {18, 17, 16, 15, 14, 13, 6, 7, 8, 9, 10, 11, 12, 5, 4, 3, 2, 1, 0}},
      // A right-to-left override reverses Latin letters.
      {U"abc \u202ertl\u202c def", false, {0, 1, 2, 3, 4, 8, 7, 6, 5, 9, 10, 11, 12}},
      // The first strong character inside an isolate does not set the line's direction (P2 skips
      // isolates): left to right from "a". pango-view sets this line right to left (its paragraph
      // direction does not skip isolates): docs/text.md, "Bidirectional text".
      {U"\u2067\u05e9\u05dc\u05d5\u05dd\u2069 abc", false, {0, 4, 3, 2, 1, 5, 6, 7, 8, 9}},
  };
  for (const Case& c : cases) {
    INFO("case " << (&c - cases.data()));
    const TextLayout layout = lay_out(font, c.text);
    CHECK(layout.lines.front().right_to_left == c.right_to_left);
    CHECK(visual_characters(layout) == c.order);
  }
}

TEST_CASE("bidi: the brackets of a bracket pair inside Hebrew are mirrored, Latin between them",
          "[font][bidi]") {
  const Font font = dejavu();
  // In memory "(" is character 5 and ")" character 9; at level 1 the ")" is drawn left of "abc" with the
  // glyph of "(", and the "(" right of it with the glyph of ")".
  const TextLayout layout = lay_out(font, U"\u05e9\u05dc\u05d5\u05dd (abc) \u05e2\u05d5\u05dc\u05dd");
  CHECK(glyph_of(layout, 9).glyph == font.glyph_for(U'('));
  CHECK(glyph_of(layout, 5).glyph == font.glyph_for(U')'));
  CHECK(glyph_of(layout, 9).origin.x < glyph_of(layout, 6).origin.x);
  CHECK(glyph_of(layout, 5).origin.x > glyph_of(layout, 8).origin.x);
}

TEST_CASE("bidi: explicit formatting characters draw nothing and take no room", "[font][bidi]") {
  const Font font = dejavu();
  const std::u32string controls = U"\u202a\u202b\u202c\u202d\u202e\u2066\u2067\u2068\u2069\u200e\u200f";
  const TextLayout layout = lay_out(font, U"a" + controls + U"b");
  for (const PositionedGlyph& glyph : layout.glyphs) {
    if (glyph.character_index == 0 || glyph.character_index == controls.size() + 1) continue;
    INFO(glyph.character_index);
    CHECK(glyph.advance == 0.0);
    // HarfBuzz's invisible glyph: the space glyph (hb_buffer_set_invisible_glyph's default), no outline.
    CHECK(glyph.glyph == font.glyph_for(U' '));
  }
  CHECK(layout.missing_characters.empty());
}

TEST_CASE("bidi: lines of both directions form one block aligned at each line's start", "[font][bidi]") {
  const Font font = dejavu();
  TextStyle style;
  style.size = 20.0;
  // A long Latin line, a short Hebrew one, a short Latin one.
  Result<TextLayout> layout =
      layout_text(font, U"abc def ghi\n\u05e9\u05dc\u05d5\u05dd\nxy", {100.0, 50.0}, style);
  REQUIRE(layout.is_ok());
  REQUIRE(layout->lines.size() == 3);
  // Alone, layout_text ends the Hebrew line at the origin, left of the Latin lines' start.
  CHECK(layout->lines[1].origin.x + layout->lines[1].advance == Approx(100.0).margin(1e-9));
  const std::vector<PositionedGlyph> before = layout->glyphs;
  align_lines_at_start(*layout);
  // The block is the widest line's width from the leftmost start (100 - the Hebrew advance): the Latin
  // lines start at its left edge, the Hebrew line ends at its right edge (exact sums of the same doubles).
  const double left = 100.0 - layout->lines[1].advance;
  const double right = left + layout->lines[0].advance;
  CHECK(layout->lines[0].origin.x == Approx(left).margin(1e-9));
  CHECK(layout->lines[2].origin.x == Approx(left).margin(1e-9));
  CHECK(layout->lines[1].origin.x + layout->lines[1].advance == Approx(right).margin(1e-9));
  // Every glyph moves with its line, and only along it.
  for (const TextLine& line : layout->lines) {
    for (std::size_t g = line.first_glyph; g < line.first_glyph + line.glyph_count; ++g) {
      CHECK(layout->glyphs[g].origin.y == before[g].origin.y);
      CHECK(layout->glyphs[g].origin.x - before[g].origin.x ==
            Approx(line.origin.x - (&line == &layout->lines[1] ? 100.0 - line.advance : 100.0)).margin(1e-9));
    }
  }
  // Lines of one direction already share their start: nothing moves.
  Result<TextLayout> hebrew = layout_text(font, U"\u05e9\u05dc\u05d5\u05dd\n\u05d0", {0.0, 0.0}, style);
  REQUIRE(hebrew.is_ok());
  const double end = hebrew->lines[0].origin.x + hebrew->lines[0].advance;
  align_lines_at_start(*hebrew);
  CHECK(hebrew->lines[0].origin.x + hebrew->lines[0].advance == end);
  CHECK(hebrew->lines[1].origin.x + hebrew->lines[1].advance == Approx(end).margin(1e-9));
}

// UAX #9 rule P2: the paragraph direction comes from the first strong character that is not inside an
// isolate (LRI/RLI/FSI ... PDI, or to the end of the paragraph when no PDI closes it).
TEST_CASE("bidi: the first strong character inside an isolate does not set the paragraph direction",
          "[font][bidi]") {
  // RLI, Hebrew, PDI, then Latin: the Latin letter decides: left to right.
  const BidiParagraph isolated_hebrew = resolve_bidi(U"\u2067\u05e9\u2069 ab", TextDirection::kAuto);
  CHECK_FALSE(isolated_hebrew.right_to_left);
  CHECK(isolated_hebrew.levels[1] == 1);  // the isolate's own content is right to left (RLI: level 1)
  // LRI, Latin, PDI, then Hebrew: right to left.
  CHECK(resolve_bidi(U"\u2066ab\u2069 \u05e9", TextDirection::kAuto).right_to_left);
  // An isolate no PDI closes runs to the end: no strong character outside it, so left to right (P3).
  CHECK_FALSE(resolve_bidi(U"\u2067\u05e9\u05dc", TextDirection::kAuto).right_to_left);
  // A PDI that closes nothing is a neutral: the Hebrew after it decides.
  CHECK(resolve_bidi(U"\u2069\u05e9 ab", TextDirection::kAuto).right_to_left);
  // The same rule for a whole-line override with the direction taken from the text (unicode-bidi:
  // bidi-override with direction auto): every character at the level of that direction.
  const BidiParagraph overridden = resolve_bidi(U"\u2067\u05e9\u2069 ab", TextDirection::kAuto, true);
  CHECK_FALSE(overridden.right_to_left);
  CHECK(overridden.levels == std::vector<std::uint8_t>(6, 0));
  CHECK(resolve_bidi(U"\u2066ab\u2069 \u05e9", TextDirection::kAuto, true).right_to_left);
}
