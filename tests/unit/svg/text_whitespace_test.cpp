// White space handling of SVG text (raster/svg/text_whitespace.h): xml:space (SVG 1.1 10.15) and the
// white-space property (CSS Text 3 section 4.1, SVG 2 11.7).
#include "svg/text_whitespace.h"

#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <vector>

using namespace curvescan::svg::detail;

namespace {

constexpr WhiteSpace kDefault = WhiteSpace::kXmlDefault;
constexpr WhiteSpace kPreserved = WhiteSpace::kXmlPreserve;

TextFragment fragment(std::u32string text, WhiteSpace mode) {
  TextFragment out;
  out.text = std::move(text);
  out.white_space = mode;
  return out;
}

std::vector<std::u32string> processed(const std::vector<std::pair<std::u32string, WhiteSpace>>& parts) {
  std::vector<TextFragment> fragments;
  for (const auto& [text, mode] : parts) fragments.push_back(fragment(text, mode));
  apply_white_space(fragments);
  std::vector<std::u32string> out;
  for (const TextFragment& f : fragments) out.push_back(f.text);
  return out;
}

std::vector<std::u32string> one(std::u32string text) {
  return {std::move(text)};
}

}  // namespace

TEST_CASE("xml:space default: newlines removed, tabs to spaces, ends stripped, runs collapsed") {
  CHECK(processed({{U"  a   b\t\tc  ", kDefault}}) == one(U"a b c"));
  // Newlines are removed, not turned into spaces (SVG 1.1, unlike CSS white-space: normal).
  CHECK(processed({{U"new\nline", kDefault}}) == one(U"newline"));
  CHECK(processed({{U"\n    indented\n  ", kDefault}}) == one(U"indented"));
  CHECK(processed({{U"\r\n", kDefault}}) == one(U""));
  CHECK(processed({{U"   ", kDefault}}) == one(U""));
}

TEST_CASE("xml:space preserve: newlines and tabs become spaces, every space kept") {
  CHECK(processed({{U"  a\n\tb  ", kPreserved}}) == one(U"  a  b  "));
}

TEST_CASE("xml:space: spaces are judged across fragments of one text element") {
  // "a <tspan> b</tspan>": one space between the words.
  CHECK(processed({{U"a ", kDefault}, {U" b", kDefault}}) == std::vector<std::u32string>{U"a ", U"b"});
  // A whitespace-only fragment between two words keeps one space.
  CHECK(processed({{U"one", kDefault}, {U" ", kDefault}, {U"two", kDefault}}) ==
        std::vector<std::u32string>{U"one", U" ", U"two"});
  // Leading spaces of the element span fragments; so do trailing ones.
  CHECK(processed({{U"  ", kDefault}, {U"  x", kDefault}, {U"y  ", kDefault}, {U" ", kDefault}}) ==
        std::vector<std::u32string>{U"", U"x", U"y", U""});
  // A preserved fragment keeps its spaces and stops the trailing strip before it.
  CHECK(processed({{U"a", kDefault}, {U"  ", kPreserved}, {U"  ", kDefault}}) ==
        std::vector<std::u32string>{U"a", U"  ", U""});
  // Non-ASCII characters pass through.
  CHECK(processed({{U" \u00e9t\u00e9  \u4e2d ", kDefault}}) == one(U"\u00e9t\u00e9 \u4e2d"));
}

TEST_CASE("white-space normal and nowrap: a segment break becomes a space, spaces around it go") {
  {
    const WhiteSpace mode = WhiteSpace::kCollapse;  // normal and nowrap both
    // CSS Text 3 4.1.1 step 1 removes the spaces and tabs around the break, 4.1.3 turns the break into a
    // space (unlike xml:space="default", which removes it: "newline" there).
    CHECK(processed({{U"new \t\n\t line", mode}}) == one(U"new line"));
    // Runs of spaces and tabs collapse to one space; the ends of the line are trimmed (phase II).
    CHECK(processed({{U"\n   a \t  b\n  ", mode}}) == one(U"a b"));
    // A segment break after another (spaces between them removed first) is removed.
    CHECK(processed({{U"a\n  \n\nb", mode}}) == one(U"a b"));
    // Across fragments (the tspan boundary): "a <tspan>\n b</tspan>" keeps one space.
    CHECK(processed({{U"a ", mode}, {U"\n b", mode}}) == std::vector<std::u32string>{U"a", U" b"});
  }
}

TEST_CASE("white-space normal: a segment break between East Asian wide characters is removed") {
  // CSS Text 3 4.1.3: both sides F, W or H and neither Hangul: removed; Hangul or Latin on one side: a
  // space; next to U+200B ZERO WIDTH SPACE: removed.
  CHECK(processed({{U"\u5343\u5229\n\u5948\u6d41", WhiteSpace::kCollapse}}) ==
        one(U"\u5343\u5229\u5948\u6d41"));
  CHECK(processed({{U"\uff76\n\uff77", WhiteSpace::kCollapse}}) ==
        one(U"\uff76\uff77"));  // halfwidth katakana
  CHECK(processed({{U"\uac00\n\u5343", WhiteSpace::kCollapse}}) == one(U"\uac00 \u5343"));  // Hangul
  CHECK(processed({{U"\u5343\na", WhiteSpace::kCollapse}}) == one(U"\u5343 a"));
  CHECK(processed({{U"a\u200b\nb", WhiteSpace::kCollapse}}) == one(U"a\u200bb"));
}

TEST_CASE("white-space pre, pre-wrap, break-spaces: spaces, tabs and segment breaks are kept") {
  // The kept segment break is the forced line break U+000A (a carriage return too); tabs stay tabs (placed
  // at tab stops by the layout).
  CHECK(processed({{U"  a \t b\r\nc  ", WhiteSpace::kPreserve}}) == one(U"  a \t b\n\nc  "));
  // A collapsible space after a preserved one is kept (CSS Text 3 4.1.1: only one after a collapsible
  // space collapses), while xml:space="default" drops it.
  CHECK(processed({{U"a ", WhiteSpace::kPreserve}, {U" b", WhiteSpace::kCollapse}}) ==
        std::vector<std::u32string>{U"a ", U" b"});
}

TEST_CASE("white-space pre-line: spaces collapse, segment breaks are kept as forced line breaks") {
  CHECK(processed({{U"  one   two  \n  three\n", WhiteSpace::kPreserveBreaks}}) == one(U"one two\nthree\n"));
  // Spaces at the start of each line go (after the break) and at its end (before it), across fragments.
  CHECK(processed({{U"a  ", WhiteSpace::kPreserveBreaks},
                   {U"\n", WhiteSpace::kPreserveBreaks},
                   {U"  b", WhiteSpace::kPreserveBreaks}}) == std::vector<std::u32string>{U"a", U"\n", U"b"});
  // A collapsible space before a preserved forced break of another element is at a line's end: removed.
  CHECK(processed({{U"a ", WhiteSpace::kCollapse}, {U"\nb", WhiteSpace::kPreserve}}) ==
        std::vector<std::u32string>{U"a", U"\nb"});
}
