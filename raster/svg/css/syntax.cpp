// CSS parsing (syntax.h). Section numbers refer to CSS Syntax Module Level 3.
#include "syntax.h"

#include "tokenizer.h"

namespace curvescan::svg::css {
namespace {

bool is(const TokenList& list, std::size_t index, TokenType type) {
  return index < list.tokens.size() && list.tokens[index].type == type;
}

// Whether `type` opens a block or function; if so, `closer` is the token that closes it.
bool closer_of(TokenType type, TokenType& closer) {
  switch (type) {
    case TokenType::kOpenCurly:
      closer = TokenType::kCloseCurly;
      return true;
    case TokenType::kOpenSquare:
      closer = TokenType::kCloseSquare;
      return true;
    case TokenType::kOpenParen:
    case TokenType::kFunction:
      closer = TokenType::kCloseParen;
      return true;
    default:
      return false;
  }
}

// 5.4.6 "Consume a declaration" from tokens [begin, end), which start with an <ident-token>.
void consume_declaration(const TokenList& list, std::size_t begin, std::size_t end,
                         std::vector<Declaration>& out) {
  Declaration declaration;
  // Property names are ASCII case-insensitive, custom property names are not (CSS Variables 1, 2).
  const std::string& name = list.tokens[begin].value;
  declaration.name = name.size() > 2 && name.compare(0, 2, "--") == 0 ? name : ascii_lower(name);
  std::size_t i = begin + 1;
  while (i < end && is(list, i, TokenType::kWhitespace)) ++i;
  if (i >= end || !is(list, i, TokenType::kColon)) return;  // a parse error: the declaration is dropped
  ++i;
  while (i < end && is(list, i, TokenType::kWhitespace)) ++i;
  std::size_t last = end;
  while (last > i && is(list, last - 1, TokenType::kWhitespace)) --last;
  // "!important": the last two non-whitespace tokens are '!' and an ident matching "important".
  if (last > i && is(list, last - 1, TokenType::kIdent) &&
      ascii_lower(list.tokens[last - 1].value) == "important") {
    std::size_t bang = last - 1;
    while (bang > i && is(list, bang - 1, TokenType::kWhitespace)) --bang;
    if (bang > i && is(list, bang - 1, TokenType::kDelim) && list.tokens[bang - 1].value == "!") {
      declaration.important = true;
      last = bang - 1;
      while (last > i && is(list, last - 1, TokenType::kWhitespace)) --last;
    }
  }
  // An empty value is invalid for every property, but the declaration is kept (with value "") so that
  // the cascade can say so where it would apply (cascade.cpp), as for any other invalid value.
  if (last > i) declaration.value = serialize_tokens(list, i, last);
  out.push_back(std::move(declaration));
}

// skip_component_value; `closed` (when given) tells whether a block found its closing token.
std::size_t skip_component(const TokenList& list, std::size_t index, std::size_t end, bool* closed) {
  TokenType closer;
  if (closed) *closed = false;
  if (index >= end) return end;
  if (!closer_of(list.tokens[index].type, closer)) return index + 1;
  // 5.4.8 "Consume a simple block" / 5.4.9 "Consume a function": inside, only the matching closer ends
  // the block; other closers are plain tokens. Nested blocks are tracked on an explicit stack.
  std::vector<TokenType> expected{closer};
  std::size_t i = index + 1;
  for (; i < end && !expected.empty(); ++i) {
    const TokenType type = list.tokens[i].type;
    if (type == expected.back()) {
      expected.pop_back();
    } else if (closer_of(type, closer)) {
      expected.push_back(closer);
    }
  }
  if (closed) *closed = expected.empty();
  return i;
}

// The {} block opening at token `open`: sets the rule's block range and returns the index after it.
std::size_t take_block(const TokenList& list, std::size_t open, std::size_t end, Rule& rule) {
  bool closed = false;
  const std::size_t after = skip_component(list, open, end, &closed);
  rule.has_block = true;
  rule.block_begin = open + 1;
  rule.block_end = closed ? after - 1 : after;
  return after;
}

}  // namespace

std::string ascii_lower(std::string_view text) {
  std::string out(text);
  for (char& c : out) {
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
  }
  return out;
}

bool ascii_equal_ignoring_case(std::string_view a, std::string_view b) noexcept {
  const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c; };
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

std::size_t skip_component_value(const TokenList& list, std::size_t index, std::size_t end) {
  return skip_component(list, index, end, nullptr);
}

std::vector<Rule> parse_rule_list(const TokenList& list, std::size_t begin, std::size_t end) {
  std::vector<Rule> rules;
  std::size_t i = begin;
  // 5.4.1 "Consume a list of rules" (CDO and CDC skipped wherever they are: in a nested block they would
  // start a qualified rule whose selector is invalid, which comes to the same).
  while (i < end) {
    const TokenType type = list.tokens[i].type;
    if (type == TokenType::kWhitespace || type == TokenType::kCdo || type == TokenType::kCdc) {
      ++i;
      continue;
    }
    Rule rule;
    if (type == TokenType::kAtKeyword) {
      // 5.4.2 "Consume an at-rule": the prelude runs to ';' or to a {} block.
      rule.is_at_rule = true;
      rule.at_name = ascii_lower(list.tokens[i].value);
      rule.prelude_begin = ++i;
      while (i < end && !is(list, i, TokenType::kSemicolon) && !is(list, i, TokenType::kOpenCurly)) {
        i = skip_component_value(list, i, end);
      }
      rule.prelude_end = i;
      if (i < end && is(list, i, TokenType::kOpenCurly)) {
        i = take_block(list, i, end, rule);
      } else if (i < end) {
        ++i;  // the ';'
      }
      rules.push_back(std::move(rule));
      continue;
    }
    // 5.4.3 "Consume a qualified rule": the prelude runs to a {} block; at the end of input it is dropped.
    rule.prelude_begin = i;
    while (i < end && !is(list, i, TokenType::kOpenCurly)) i = skip_component_value(list, i, end);
    rule.prelude_end = i;
    if (i >= end) break;
    i = take_block(list, i, end, rule);
    rules.push_back(std::move(rule));
  }
  return rules;
}

StyleSheetSyntax parse_style_sheet(std::string_view text, std::size_t max_tokens) {
  StyleSheetSyntax sheet{tokenize(text, max_tokens), {}};
  sheet.rules = parse_rule_list(sheet.tokens, 0, sheet.tokens.tokens.size());
  // The last rule kept ends at the cut or before it; if at the cut, its block may be missing its end
  // (a declaration "stroke-width: 10" cut to "stroke-width: 1" would read wrong): drop it.
  if (sheet.tokens.truncated && !sheet.rules.empty()) {
    const Rule& last = sheet.rules.back();
    if ((last.has_block ? last.block_end : last.prelude_end) >= sheet.tokens.tokens.size()) sheet.rules.pop_back();
  }
  return sheet;
}

std::vector<Declaration> parse_declarations(const TokenList& list, std::size_t begin, std::size_t end) {
  std::vector<Declaration> out;
  std::size_t i = begin;
  while (i < end) {
    const TokenType type = list.tokens[i].type;
    if (type == TokenType::kWhitespace || type == TokenType::kSemicolon) {
      ++i;
      continue;
    }
    // Everything up to the next top-level ';' belongs to this declaration (or to this at-rule, whose
    // block, if any, skip_component_value steps over).
    const std::size_t start = i;
    while (i < end && !is(list, i, TokenType::kSemicolon)) {
      const bool block = is(list, i, TokenType::kOpenCurly);
      i = skip_component_value(list, i, end);
      if (block && type == TokenType::kAtKeyword) break;  // an at-rule with a block ends with it
    }
    if (type == TokenType::kIdent) consume_declaration(list, start, i, out);
    // Anything else (an at-rule, a stray token) is a parse error: dropped up to the ';'.
  }
  return out;
}

std::vector<Declaration> parse_declaration_list(std::string_view text) {
  const TokenList list = tokenize(text);
  return parse_declarations(list, 0, list.tokens.size());
}

}  // namespace curvescan::svg::css
