// CSS tokens (CSS Syntax Module Level 3, section 4 "Tokenization").
//
// The tokenizer turns a style sheet or a declaration list into these; the parser (syntax.h) groups them
// into rules and declarations, the selector parser (selector.h) reads a rule's prelude.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace curvescan::svg::css {

/// The token kinds of CSS Syntax 3 section 4. <EOF> is not stored: a token list simply ends.
enum class TokenType {
  kIdent,
  kFunction,   ///< "name(" -- value is the name
  kAtKeyword,  ///< "@name" -- value is the name
  kHash,       ///< "#name" -- value is the name; is_id_hash when the name would be an identifier
  kString,     ///< value is the unescaped content, without the quotes
  kBadString,
  kUrl,  ///< unquoted url(...) -- value is the unescaped URL
  kBadUrl,
  kDelim,  ///< one code point that starts no other token; value is its UTF-8 text
  kNumber,
  kPercentage,
  kDimension,  ///< number plus unit (value is the unit)
  kWhitespace,
  kCdo,  ///< "<!--"
  kCdc,  ///< "-->"
  kColon,
  kSemicolon,
  kComma,
  kOpenSquare,
  kCloseSquare,
  kOpenParen,
  kCloseParen,
  kOpenCurly,
  kCloseCurly,
};

struct Token {
  TokenType type = TokenType::kDelim;
  std::string value;        ///< see TokenType; empty for punctuation and whitespace
  double number = 0.0;      ///< kNumber, kPercentage (the number before '%'), kDimension
  bool is_integer = false;  ///< the number had no '.' and no exponent (the "integer" type flag)
  bool is_id_hash = false;  ///< kHash: the "id" type flag (what an #id selector requires)
  std::size_t begin = 0;    ///< byte offsets of the token in the preprocessed input (TokenList::source)
  std::size_t end = 0;
};

/// The tokens of one input and the preprocessed text their offsets refer to.
struct TokenList {
  std::string source;  ///< the input after preprocessing (section 3.3): newlines normalized, NUL replaced
  std::vector<Token> tokens;
  bool truncated = false;  ///< the tokenizer stopped at its token limit before the end of `source`
};

}  // namespace curvescan::svg::css
