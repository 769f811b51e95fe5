// The CSS parser (svg/css/syntax.h): rules, at-rules and declaration lists (CSS Syntax 3, section 5).
#include <catch2/catch.hpp>

#include "svg/css/syntax.h"
#include "svg/css/tokenizer.h"

using namespace curvescan::svg::css;

TEST_CASE("css declarations: names lower-cased, values trimmed, !important recognised (5.4.5, 5.4.6)") {
  const std::vector<Declaration> list =
      parse_declaration_list(" FILL : red ;stroke-width:2px/* c; d */;; bogus; opacity: .5 ! IMPORTANT ;x:");
  REQUIRE(list.size() == 4);  // "x:" is kept with an empty value, which the cascade reports as invalid
  CHECK(list[3].name == "x");
  CHECK(list[3].value.empty());
  CHECK(list[0].name == "fill");
  CHECK(list[0].value == "red");
  CHECK_FALSE(list[0].important);
  CHECK(list[1].name == "stroke-width");
  CHECK(list[1].value == "2px");
  CHECK(list[2].name == "opacity");
  CHECK(list[2].value == ".5");
  CHECK(list[2].important);
}

TEST_CASE("css declarations: blocks keep their semicolons, errors drop one declaration only") {
  const std::vector<Declaration> list =
      parse_declaration_list("font-family: 'a;b'; 12: x; fill: url(#g) blue; @foo { a: b; } stroke: red");
  REQUIRE(list.size() == 3);
  CHECK(list[0].value == "'a;b'");  // the ';' is inside a string
  CHECK(list[1].value == "url(#g) blue");
  CHECK(list[2].name == "stroke");                            // the at-rule with its block was skipped whole
  // An empty value is invalid, but kept (value "") for the cascade to warn about where it applies.
  const std::vector<Declaration> empty = parse_declaration_list("fill: !important; stroke:");
  REQUIRE(empty.size() == 2);
  CHECK(empty[0].name == "fill");
  CHECK(empty[0].value.empty());
  CHECK(empty[0].important);
  CHECK(empty[1].name == "stroke");
  CHECK(empty[1].value.empty());
  CHECK(parse_declaration_list("fill red; stroke: blue").size() == 1);        // no colon: dropped up to ';'
  CHECK(parse_declaration_list("fill: rgb(1;2); stroke: blue").size() == 2);  // ';' inside ( ) is kept
}

TEST_CASE("css style sheets: qualified rules and at-rules with and without blocks (5.4.1 - 5.4.3)") {
  const StyleSheetSyntax sheet = parse_style_sheet(
      "<!-- @import 'x.css'; .a, b > c { fill: red } @media print { .b { fill: blue } } -->"
      " .c { fill: green; stroke: url(#x) } d { unterminated");
  REQUIRE(sheet.rules.size() == 5);
  CHECK(sheet.rules[0].is_at_rule);
  CHECK(sheet.rules[0].at_name == "import");
  CHECK_FALSE(sheet.rules[0].has_block);
  CHECK_FALSE(sheet.rules[1].is_at_rule);
  CHECK(serialize_tokens(sheet.tokens, sheet.rules[1].prelude_begin, sheet.rules[1].prelude_end) ==
        ".a, b > c ");
  CHECK(sheet.rules[2].at_name == "media");
  CHECK(sheet.rules[2].has_block);
  const std::vector<Declaration> green =
      parse_declarations(sheet.tokens, sheet.rules[3].block_begin, sheet.rules[3].block_end);
  REQUIRE(green.size() == 2);
  CHECK(green[1].value == "url(#x)");
  // A block cut off by the end of the sheet still closes at the end (5.4.8: EOF is a parse error, the
  // block is returned).
  CHECK(parse_declarations(sheet.tokens, sheet.rules[4].block_begin, sheet.rules[4].block_end).empty());
  CHECK(parse_style_sheet(".a { fill: red } .b").rules.size() == 1);  // a prelude without a block is dropped
}

TEST_CASE("css style sheets: nested and mismatched brackets are skipped without recursion") {
  // 100 000 nested blocks: a recursive parser would exhaust the stack; this one counts.
  std::string deep = ".a { fill: ";
  deep += std::string(100000, '(') + std::string(100000, ']') + "; } .b { fill: red }";
  const StyleSheetSyntax sheet = parse_style_sheet(deep);
  REQUIRE(sheet.rules.size() == 1);  // the ( never close, so the first block swallows the rest
  CHECK(parse_style_sheet(".a { x: ( ] ) } .b { fill: red }").rules.size() ==
        2);  // ']' inside ( ) is a token
}
