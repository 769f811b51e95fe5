// The CSS tokenizer (svg/css/tokenizer.h) against CSS Syntax Module Level 3, section 4.
#include <catch2/catch.hpp>

#include "svg/css/tokenizer.h"

using namespace curvescan::svg::css;

namespace {

std::vector<TokenType> types(std::string_view text) {
  std::vector<TokenType> out;
  for (const Token& token : tokenize(text).tokens) out.push_back(token.type);
  return out;
}

Token only_token(std::string_view text) {
  const TokenList list = tokenize(text);
  REQUIRE(list.tokens.size() == 1);
  return list.tokens.front();
}

}  // namespace

TEST_CASE("css tokenizer: punctuation, whitespace runs and comments (4.3.1, 4.3.2)") {
  using T = TokenType;
  CHECK(types("a{b:c;}") == std::vector<T>{T::kIdent, T::kOpenCurly, T::kIdent, T::kColon, T::kIdent,
                                           T::kSemicolon, T::kCloseCurly});
  CHECK(types(" \t\n a /* x */ ,") ==
        std::vector<T>{T::kWhitespace, T::kIdent, T::kWhitespace, T::kWhitespace, T::kComma});
  CHECK(types("[]()") == std::vector<T>{T::kOpenSquare, T::kCloseSquare, T::kOpenParen, T::kCloseParen});
  CHECK(types("<!-- -->") == std::vector<T>{T::kCdo, T::kWhitespace, T::kCdc});
  CHECK(types("/* unterminated").empty());
}

TEST_CASE("css tokenizer: identifiers, functions, at-keywords, hashes and escapes (4.3.4, 4.3.7, 4.3.11)") {
  CHECK(only_token("-moz-thing").type == TokenType::kIdent);
  CHECK(only_token("--custom").value == "--custom");
  CHECK(only_token("r\\65 d").value == "red");         // hex escape, the space after it consumed
  CHECK(only_token("\\31 23").value == "123");         // an escape may start an identifier
  CHECK(only_token("a\\0").value == "a\xEF\xBF\xBD");  // U+0000 becomes U+FFFD
  CHECK(only_token("\xC3\xA9t\xC3\xA9").type == TokenType::kIdent);  // non-ASCII is a name code point
  const TokenList function = tokenize("rgb(1,2,3)");
  CHECK(function.tokens.front().type == TokenType::kFunction);
  CHECK(function.tokens.front().value == "rgb");
  CHECK(only_token("@media").type == TokenType::kAtKeyword);
  CHECK(only_token("@media").value == "media");
  const Token id = only_token("#rect1");
  CHECK(id.type == TokenType::kHash);
  CHECK(id.is_id_hash);
  CHECK_FALSE(only_token("#123").is_id_hash);  // a hash, but not a valid #id selector
  CHECK(types("#") == std::vector<TokenType>{TokenType::kDelim});
}

TEST_CASE("css tokenizer: numbers, percentages and dimensions (4.3.3, 4.3.12)") {
  const Token number = only_token("-1.5e2");
  CHECK(number.type == TokenType::kNumber);
  CHECK(number.number == -150.0);
  CHECK_FALSE(number.is_integer);
  CHECK(only_token("+7").is_integer);
  CHECK(only_token(".5").number == 0.5);
  const Token percent = only_token("50%");
  CHECK(percent.type == TokenType::kPercentage);
  CHECK(percent.number == 50.0);
  const Token dimension = only_token("2px");
  CHECK(dimension.type == TokenType::kDimension);
  CHECK(dimension.value == "px");
  CHECK(only_token("2n-1").value == "n-1");               // the An+B forms tokenize as a dimension
  CHECK(only_token("1e").type == TokenType::kDimension);  // "e" without digits is a unit
  CHECK(only_token("1e999").number == HUGE_VAL);          // out of range: infinity, refused later
}

TEST_CASE("css tokenizer: strings, urls and their bad forms (4.3.5, 4.3.6, 4.3.14)") {
  CHECK(only_token("'a\\'b'").value == "a'b");
  CHECK(only_token("\"a\\\nb\"").value == "ab");  // an escaped newline continues the string
  CHECK(only_token("'open").value == "open");     // EOF ends the string
  CHECK(types("'a\nb'").front() == TokenType::kBadString);
  const Token url = only_token("url( #grad )");
  CHECK(url.type == TokenType::kUrl);
  CHECK(url.value == "#grad");
  CHECK(only_token("url(a b)").type == TokenType::kBadUrl);
  CHECK(only_token("url(a(b)").type == TokenType::kBadUrl);
  CHECK(tokenize("url('x')").tokens.front().type == TokenType::kFunction);  // quoted: a function
}

TEST_CASE("css tokenizer: preprocessing and serialization of values (3.3)") {
  const TokenList list = tokenize("a\r\nb\fc");
  CHECK(list.source == "a\nb\nc");
  const TokenList value = tokenize("1/**/2  url(#a)\t'x'  r\\65 d");
  CHECK(serialize_tokens(value, 0, value.tokens.size()) == "1 2 url(#a) 'x' red");
}
