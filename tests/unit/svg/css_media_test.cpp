// @media rules (svg/css/media_query.h, svg/css/style_sheet.h): the queries of Media Queries Level 4
// evaluated for a screen of the output size, and the rules inside applied in source order.
//
// Colours are checked at pixel centres well inside 10 x 10 squares, where coverage is exactly 1: no
// tolerance is needed.
#include <catch2/catch.hpp>
#include <set>
#include <string>

#include "curvescan/svg/document.h"
#include "svg/css/media_query.h"
#include "svg/css/style_sheet.h"
#include "svg/css/tokenizer.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;

using namespace curvescan::svg::testing;

namespace {

struct Evaluated {
  bool matches;
  std::set<std::string> unsupported;
};

// `query` evaluated for a 400 x 300 px screen (or one of unknown size).
Evaluated evaluate(const std::string& query, bool size_known = true) {
  const css::TokenList tokens = css::tokenize(query);
  Evaluated result{false, {}};
  const css::MediaQueryList list =
      css::MediaQueryList::parse(tokens, 0, tokens.tokens.size(), result.unsupported);
  result.matches = list.matches(css::MediaFeatures{size_known, 400.0, 300.0, 96.0});
  return result;
}

bool matches(const std::string& query) {
  INFO(query);
  return evaluate(query).matches;
}

}  // namespace

TEST_CASE("media queries: media types (MQ4 2.3) and the query list") {
  CHECK(matches(""));  // an empty list is true
  CHECK(matches("all"));
  CHECK(matches("screen"));
  CHECK(matches("SCREEN"));
  CHECK(matches("only screen"));
  CHECK_FALSE(matches("print"));
  CHECK_FALSE(matches("tv"));  // deprecated types match nothing
  CHECK(matches("not print"));
  CHECK_FALSE(matches("not screen"));
  CHECK(matches("print, screen"));
  CHECK(matches("screen and, screen"));  // the malformed first query is "not all", the second holds
  CHECK_FALSE(matches("screen and"));
  CHECK_FALSE(matches("not"));
  CHECK_FALSE(matches("and"));
}

TEST_CASE("media queries: width and height, with min-, max- and ranges (MQ4 2.4.4, 4.1, 4.2)") {
  CHECK(matches("(min-width: 400px)"));
  CHECK_FALSE(matches("(min-width: 401px)"));
  CHECK(matches("(max-width: 400px)"));
  CHECK(matches("(width: 400px)"));
  CHECK(matches("screen and (min-width: 100px) and (max-height: 300px)"));
  CHECK_FALSE(matches("screen and (min-width: 100px) and (max-height: 299px)"));
  CHECK(matches("(width > 399.5px)"));
  CHECK_FALSE(matches("(width < 400px)"));
  CHECK(matches("(width <= 400px)"));
  CHECK(matches("(399px < width <= 400px)"));
  CHECK_FALSE(matches("(400px < width <= 500px)"));
  CHECK(matches("(500px > width >= 400px)"));
  CHECK(matches("(300px = height)"));
  CHECK(matches("(min-width: 25em)"));    // 25 x 16 px
  CHECK(matches("(max-width: 4.17in)"));  // 400.3 px
  CHECK(matches("(min-width: 0)"));
  CHECK_FALSE(matches("(min-width: 400)"));  // a number other than 0 is no length: unknown, false
  CHECK(matches("(orientation: landscape)"));
  CHECK_FALSE(matches("(orientation: portrait)"));
  CHECK(matches("(min-aspect-ratio: 4/3)"));
  CHECK_FALSE(matches("(min-aspect-ratio: 16/9)"));
  CHECK(matches("(aspect-ratio: 4 / 3)"));
  CHECK(matches("(width)"));  // boolean context: not zero
  // Before the output size is known, the size features are unknown.
  CHECK_FALSE(evaluate("(min-width: 0px)", false).matches);
  CHECK_FALSE(evaluate("not all and (min-width: 0px)", false).matches);
  CHECK(evaluate("(prefers-color-scheme: light)", false).matches);
}

TEST_CASE("media queries: not, and, or, nesting and the features of a still screen image") {
  CHECK(matches("(prefers-color-scheme: light)"));
  CHECK_FALSE(matches("(prefers-color-scheme: dark)"));
  CHECK(matches("not (prefers-color-scheme: dark)"));
  CHECK(matches("(prefers-color-scheme: dark) or (min-width: 10px)"));
  CHECK_FALSE(matches("(prefers-color-scheme: dark) and (min-width: 10px)"));
  CHECK_FALSE(matches("(min-width: 10px) and (max-width: 20px) or (color)"));  // and and or mixed: malformed
  CHECK(matches("((min-width: 10px) and (max-width: 500px)) or (color)"));
  CHECK(matches("screen and (not (hover))"));
  CHECK_FALSE(matches("screen and (min-width: 10px) or (color)"));  // no or after a media type
  CHECK(matches("(color)"));
  CHECK(matches("(min-color: 8)"));
  CHECK_FALSE(matches("(monochrome)"));
  CHECK_FALSE(matches("(grid)"));
  CHECK(matches("(prefers-reduced-motion: no-preference)"));
  CHECK_FALSE(matches("(prefers-reduced-motion)"));
  CHECK(matches("(hover: none) and (pointer: none)"));
  CHECK(matches("(update: none)"));
  CHECK(matches("(min-resolution: 96dpi) and (max-resolution: 1dppx)"));
  CHECK_FALSE(matches("(min-resolution: 2dppx)"));
  // Deep nesting: past kMaxMediaConditionDepth parentheses the inner part is unknown, never a crash.
  std::string deep;
  for (int i = 0; i < 10000; ++i) deep += "(";
  CHECK_FALSE(matches(deep));
  deep = std::string(20, '(') + "color" + std::string(20, ')');
  CHECK(matches(deep));
}

TEST_CASE("media queries: an unknown feature or general-enclosed part is unknown, false, and named") {
  const Evaluated unknown = evaluate("(min-wibble: 3)");
  CHECK_FALSE(unknown.matches);
  CHECK(unknown.unsupported == std::set<std::string>{"wibble"});
  CHECK_FALSE(evaluate("not (wibble)").matches);   // not unknown is unknown
  CHECK(evaluate("(wibble) or (color)").matches);  // unknown or true is true
  CHECK_FALSE(evaluate("(color) and (wibble)").matches);
  CHECK_FALSE(evaluate("selector(a > b)").matches);
  CHECK_FALSE(evaluate("(min-orientation: portrait)").matches);  // min- on a discrete feature
}

TEST_CASE("@media in documents: rules apply by the output size, in source order, nested") {
  const std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 40 10\" width=\"40\" height=\"10\">"
      "<style>rect { fill: #ff0000 }"
      "@media screen and (min-width: 40px) { .a { fill: #008000 } }"
      "@media (max-width: 39px) { .a { fill: #0000ff } }"
      ".b { fill: #008000 } @media all { .b { fill: #0000ff } }"  // later in source order: wins
      "@media all { .c { fill: #0000ff } } .c { fill: #008000 }"
      "@media screen { @media (prefers-color-scheme: light) { .d { fill: #008000 } } }"
      "@media print { .e { fill: #0000ff } } .e { fill: #008000 }"
      "</style>"
      "<rect class=\"a\" width=\"10\" height=\"10\"/><rect class=\"b\" x=\"10\" width=\"10\" height=\"10\"/>"
      "<rect class=\"c e\" x=\"20\" width=\"10\" height=\"10\"/><rect class=\"d\" x=\"30\" width=\"10\" "
      "height=\"10\"/>"
      "</svg>";
  Result<RenderedDocument> full = render_svg_document(document, {});
  REQUIRE(full.is_ok());
  CHECK(square_colour(full->image, 0) == "#008000");
  CHECK(square_colour(full->image, 1) == "#0000ff");
  CHECK(square_colour(full->image, 2) == "#008000");
  CHECK(square_colour(full->image, 3) == "#008000");
  CHECK(full->warnings.empty());
  // At half the width (-w 20): the max-width rule applies instead. Squares are 5 px wide then.
  RenderOptions narrow;
  narrow.width = 20.0;
  Result<RenderedDocument> small = render_svg_document(document, narrow);
  REQUIRE(small.is_ok());
  CHECK(small->image.width() == 20);
  const Rgba8 first = small->image.at(2, 2);
  CHECK((first.r == 0 && first.g == 0 && first.b == 255 && first.a == 255));
}

TEST_CASE("@media: unsupported features and other at-rules are named once each") {
  const std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"40\" height=\"10\"><style>"
      "@font-face { font-family: a } @font-face { font-family: b } @supports (fill: red) { rect { fill: red "
      "} }"
      "@media (wibble: 1) { rect { fill: #ff0000 } } @media (wibble: 2) { rect { fill: #ff0000 } }"
      "</style><rect width=\"10\" height=\"10\"/></svg>";
  Result<RenderedDocument> rendered = render_svg_document(document, {});
  REQUIRE(rendered.is_ok());
  CHECK(square_colour(rendered->image, 0) == "#000000");
  std::size_t font_face = 0, wibble = 0;
  for (const std::string& warning : rendered->warnings) {
    font_face += warning.find("@font-face is not supported") != std::string::npos;
    wibble += warning.find("@media feature 'wibble' is not supported") != std::string::npos;
  }
  CHECK(font_face == 1);
  CHECK(wibble == 1);
  CHECK(contains(rendered->warnings, "@supports is not supported; the at-rule is skipped"));
}

TEST_CASE("@media: the media attribute of <style> wraps the whole sheet") {
  const std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"40\" height=\"10\">"
      "<style media=\"\">.a { fill: #008000 }</style><style media=\"print\">.a { fill: #ff0000 }</style>"
      "<style media=\"screen and (min-width: 40px)\">.b { fill: #008000 }</style>"
      "<rect class=\"a\" width=\"10\" height=\"10\"/><rect class=\"b\" x=\"10\" width=\"10\" height=\"10\"/>"
      "</svg>";
  Result<RenderedDocument> rendered = render_svg_document(document, {});
  REQUIRE(rendered.is_ok());
  CHECK(square_colour(rendered->image, 0) == "#008000");
  CHECK(square_colour(rendered->image, 1) == "#008000");
}

TEST_CASE("@media limits: nesting past kMaxMediaNesting is skipped with a warning, a block-less @media too") {
  std::string nested;
  for (int i = 0; i < 1000; ++i) nested += "@media all {";
  nested += ".a { fill: #ff0000 }";
  for (int i = 0; i < 1000; ++i) nested += "}";
  std::string shallow;
  for (int i = 0; i < css::kMaxMediaNesting; ++i) shallow += "@media all {";
  shallow += ".b { fill: #008000 }";
  for (int i = 0; i < css::kMaxMediaNesting; ++i) shallow += "}";
  const std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"40\" height=\"10\"><style>" + nested + shallow +
      "@media (((color)</style><rect class=\"a\" width=\"10\" height=\"10\"/>"
      "<rect class=\"b\" x=\"10\" width=\"10\" height=\"10\"/></svg>";
  Result<RenderedDocument> rendered = render_svg_document(document, {});
  REQUIRE(rendered.is_ok());
  CHECK(square_colour(rendered->image, 0) == "#000000");  // beyond the bound: not applied
  CHECK(square_colour(rendered->image, 1) == "#008000");  // 16 deep: applied
  CHECK(contains(rendered->warnings, "@media nested more than 16 deep is skipped"));
  CHECK(contains(rendered->warnings, "has no {} block; skipped"));

  std::string many;
  for (std::size_t i = 0; i < css::kMaxMediaBlocks; ++i) many += "@media all{.c{fill:#0000ff}}";
  many += "@media all { .b { fill: #ff0000 } }";
  const std::string counted = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"40\" height=\"10\"><style>" +
                              shallow + many +
                              "</style><rect class=\"b\" x=\"10\" width=\"10\" height=\"10\"/></svg>";
  Result<RenderedDocument> bounded = render_svg_document(counted, {});
  REQUIRE(bounded.is_ok());
  CHECK(square_colour(bounded->image, 1) == "#008000");  // the block past the bound is skipped
  CHECK(contains(bounded->warnings, "more than 4096 @media blocks in all; the rest are skipped"));
}

TEST_CASE("css limits: a sheet past the token limit keeps its rules before the cut, drops the one cut") {
  // The first rule is 11 tokens; the filler ("a " is two tokens: an ident and whitespace) sits inside the
  // second rule's block, which the cut leaves unclosed; the third rule lies past the cut.
  std::string spaced;
  for (std::size_t i = 0; i < css::kMaxStyleSheetTokens / 2; ++i) spaced += "a ";
  const std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"30\" height=\"10\"><style>"
      ".a { fill: #008000 } .b { fill: #ff0000; " + spaced + "} .c { fill: #ff0000 }</style>"
      "<rect class=\"a\" width=\"10\" height=\"10\"/><rect class=\"b\" x=\"10\" width=\"10\" height=\"10\"/>"
      "<rect class=\"c\" x=\"20\" width=\"10\" height=\"10\"/></svg>";
  const Result<RenderedDocument> rendered = render_svg_document(document, {});
  REQUIRE(rendered.is_ok());
  CHECK(square_colour(rendered->image, 0) == "#008000");  // before the cut: applied
  CHECK(square_colour(rendered->image, 1) == "#000000");  // the rule the cut falls in: dropped whole
  CHECK(square_colour(rendered->image, 2) == "#000000");  // past the cut
  CHECK(contains(rendered->warnings, "CSS tokens: the rest of the style sheet is skipped"));
  // The tokenizer itself: exactly the limit, and the flag.
  const css::TokenList list = css::tokenize("a b c d", 3);
  CHECK(list.tokens.size() == 3);
  CHECK(list.truncated);
  CHECK_FALSE(css::tokenize("a b", 3).truncated);
}

// A document without width, height or viewBox takes its size from its drawing's ink box, and the size
// queries depend on the size: a circle. It is cut in one place (docs/svg.md, "@media"): the ink box is
// measured once with size queries unknown (false, Media Queries 4 section 3's three-valued logic), other
// queries (media types, prefers-color-scheme) already applying; the render then evaluates every query
// for the page that measurement gave. There is no second measurement, so the result is one and the same
// whatever the rules (a rule that would shrink the drawing below a query's threshold cannot oscillate).
TEST_CASE("@media in a document without a size: measured without size queries, drawn with them") {
  const std::string document =
      "<svg xmlns=\"http://www.w3.org/2000/svg\"><style>"
      "rect { fill: #ff0000 }"
      "@media screen { .a { fill: #008000 } }"            // applies while measuring and drawing
      "@media (min-width: 1px) { .b { fill: #008000 } }"  // the page is 30 px wide when drawn
      "@media (min-width: 25px) { .c { width: 40px } }"   // not while measuring: the page stays 30 px
      "@media not (min-width: 1px) { .d { x: 100px } }"   // unknown while measuring is false, negated too
      "</style>"
      "<rect class=\"a\" width=\"10\" height=\"10\"/><rect class=\"b\" x=\"10\" width=\"10\" height=\"10\"/>"
      "<rect class=\"c d\" x=\"20\" width=\"10\" height=\"10\"/></svg>";
  Result<RenderedDocument> rendered = render_svg_document(document, {});
  REQUIRE(rendered.is_ok());
  // The measured ink box: the three 10 px squares, the third at its own 10 px width (not 40, not at 100).
  CHECK(rendered->image.width() == 30);
  CHECK(rendered->image.height() == 10);
  CHECK(square_colour(rendered->image, 0) == "#008000");
  CHECK(square_colour(rendered->image, 1) == "#008000");
  // Drawn with the 30 px page's queries: the third square's rule now applies (40 px wide, cut by the page).
  CHECK(square_colour(rendered->image, 2) == "#ff0000");
  CHECK(rendered->image.at(29, 5).a == 255);
}
