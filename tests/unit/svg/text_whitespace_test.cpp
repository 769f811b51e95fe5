// xml:space handling of SVG text (raster/svg/text_whitespace.h, SVG 1.1 10.15).
#include "svg/text_whitespace.h"

#include <catch2/catch.hpp>
#include <string>
#include <vector>

using namespace curvescan::svg::detail;

namespace {

std::vector<std::u32string> processed(std::vector<TextFragment> fragments) {
  apply_xml_space(fragments);
  std::vector<std::u32string> out;
  for (const TextFragment& fragment : fragments) out.push_back(fragment.text);
  return out;
}

std::vector<std::u32string> one(std::u32string text) {
  return {std::move(text)};
}

}  // namespace

TEST_CASE("xml:space default: newlines removed, tabs to spaces, ends stripped, runs collapsed") {
  CHECK(processed({{U"  a   b\t\tc  ", false}}) == one(U"a b c"));
  // Newlines are removed, not turned into spaces (SVG 1.1, unlike CSS white-space: normal).
  CHECK(processed({{U"new\nline", false}}) == one(U"newline"));
  CHECK(processed({{U"\n    indented\n  ", false}}) == one(U"indented"));
  CHECK(processed({{U"\r\n", false}}) == one(U""));
  CHECK(processed({{U"   ", false}}) == one(U""));
}

TEST_CASE("xml:space preserve: newlines and tabs become spaces, every space kept") {
  CHECK(processed({{U"  a\n\tb  ", true}}) == one(U"  a  b  "));
}

TEST_CASE("xml:space: spaces are judged across fragments of one text element") {
  // "a <tspan> b</tspan>": one space between the words.
  CHECK(processed({{U"a ", false}, {U" b", false}}) == std::vector<std::u32string>{U"a ", U"b"});
  // A whitespace-only fragment between two words keeps one space.
  CHECK(processed({{U"one", false}, {U" ", false}, {U"two", false}}) ==
        std::vector<std::u32string>{U"one", U" ", U"two"});
  // Leading spaces of the element span fragments; so do trailing ones.
  CHECK(processed({{U"  ", false}, {U"  x", false}, {U"y  ", false}, {U" ", false}}) ==
        std::vector<std::u32string>{U"", U"x", U"y", U""});
  // A preserved fragment keeps its spaces and stops the trailing strip before it.
  CHECK(processed({{U"a", false}, {U"  ", true}, {U"  ", false}}) ==
        std::vector<std::u32string>{U"a", U"  ", U""});
  // Non-ASCII characters pass through.
  CHECK(processed({{U" \u00e9t\u00e9  \u4e2d ", false}}) == one(U"\u00e9t\u00e9 \u4e2d"));
}
