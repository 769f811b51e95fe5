// text-transform of SVG text (raster/svg/text_transform.h, CSS Text 3 section 2.1): the characters each
// value gives, and which characters are added (no position of their own).
#include "svg/text_transform.h"

#include <catch2/catch.hpp>
#include <string>
#include <utility>
#include <vector>

using namespace curvescan::svg::detail;

namespace {

using Case = TextTransform::Case;

TextFragment fragment(std::u32string text, TextTransform transform) {
  TextFragment out;
  out.text = std::move(text);
  out.transform = transform;
  return out;
}

TextTransform with(Case case_transform, bool full_width = false, bool full_size_kana = false) {
  TextTransform transform;
  transform.case_transform = case_transform;
  transform.full_width = full_width;
  transform.full_size_kana = full_size_kana;
  return transform;
}

std::u32string transformed(std::u32string text, TextTransform transform) {
  std::vector<TextFragment> fragments{fragment(std::move(text), transform)};
  apply_text_transform(fragments);
  return fragments.front().text;
}

}  // namespace

TEST_CASE("text-transform uppercase and lowercase use the full case mappings") {
  CHECK(transformed(U"stra\u00dfe \u00e9t\u00e9", with(Case::kUppercase)) == U"STRASSE \u00c9T\u00c9");
  CHECK(transformed(U"\ufb01x", with(Case::kUppercase)) == U"FIX");  // the fi ligature: SpecialCasing.txt
  CHECK(transformed(U"HELLO \u00c9T\u00c9", with(Case::kLowercase)) == U"hello \u00e9t\u00e9");
  // Final_Sigma: a capital sigma at the end of a word lowercases to the final form, inside one to σ.
  CHECK(transformed(U"\u039f\u0394\u039f\u03a3 \u03a3\u039f", with(Case::kLowercase)) ==
        U"\u03bf\u03b4\u03bf\u03c2 \u03c3\u03bf");
}

TEST_CASE("text-transform: a character that becomes several keeps one addressable position") {
  std::vector<TextFragment> fragments{fragment(U"a\u00dfb", with(Case::kUppercase))};
  apply_text_transform(fragments);
  CHECK(fragments[0].text == U"ASSB");
  CHECK(fragments[0].middle == std::vector<bool>{false, false, true, false});
}

TEST_CASE("text-transform capitalize: the first letter of each word, if lowercase, to titlecase") {
  // Words break at spaces and hyphens, not at an apostrophe between letters (UAX #29 MidNumLet); a word
  // that starts with a digit has its digit as its first letter unit, so "3rd" stays; capitals stay.
  CHECK(transformed(U"hello wORLD don't x-ray 3rd (it)", with(Case::kCapitalize)) ==
        U"Hello WORLD Don't X-Ray 3rd (It)");
  // Titlecase, not uppercase: the digraph dž becomes Dž; ß, whose full uppercase is SS, becomes Ss.
  CHECK(transformed(U"\u01c6ungla \u00dfa", with(Case::kCapitalize)) == U"\u01c5ungla Ssa");
}

TEST_CASE("text-transform capitalize judges words across fragments (elements)") {
  // "<tspan>hel</tspan><tspan>lo</tspan> world": one word "hello", its first letter in the first tspan.
  std::vector<TextFragment> fragments{fragment(U"hel", with(Case::kCapitalize)),
                                      fragment(U"lo world", with(Case::kCapitalize))};
  apply_text_transform(fragments);
  CHECK(fragments[0].text == U"Hel");
  CHECK(fragments[1].text == U"lo World");
}

TEST_CASE("text-transform full-width and full-size-kana, alone and after a case transform") {
  // ASCII and the space to their full-width forms (U+FF01.., U+3000); halfwidth katakana to the ordinary
  // (full-width) katakana; a character without a full-width form stays.
  CHECK(transformed(U"a B!1 \u00e9", with(Case::kNone, true)) ==
        U"\uff41\u3000\uff22\uff01\uff11\u3000\u00e9");
  CHECK(transformed(U"\uff71\uff67", with(Case::kNone, true)) == U"\u30a2\u30a1");
  CHECK(transformed(U"\u3041\u30a1\u30f5\u31f0\uff67x", with(Case::kNone, false, true)) ==
        U"\u3042\u30a2\u30ab\u30af\uff71x");
  // uppercase first, then full-width (CSS Text 3 2.1): ß -> SS -> ＳＳ; halfwidth small ｧ -> full-width ァ ->
  // full-size ア.
  CHECK(transformed(U"\u00dfa", with(Case::kUppercase, true)) == U"\uff33\uff33\uff21");
  CHECK(transformed(U"\uff67", with(Case::kNone, true, true)) == U"\u30a2");
}
