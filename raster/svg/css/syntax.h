// CSS parsing: style sheets into rules, blocks into declarations (CSS Syntax Module Level 3, section 5).
//
// One parser serves both the <style> element (parse_style_sheet: a list of rules, section 5.3.3 "Parse a
// stylesheet") and the style attribute (parse_declaration_list: section 5.3.8 "Parse a list of
// declarations", as CSS Style Attributes section 2 prescribes). Rules are kept as token ranges; the
// selector parser (selector.h) reads a qualified rule's prelude, the caller decides about at-rules.
//
// The parser works on the flat token list: a {}-, []- or ()-block or a function is skipped by counting
// brackets with an explicit stack, so no input nests the parser's recursion.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "token.h"

namespace curvescan::svg::css {

/// One "name: value" of a declaration block (5.4.6 "Consume a declaration").
struct Declaration {
  std::string name;        ///< ASCII lower-cased (CSS property names are case-insensitive), but for
                           ///< custom property names ("--x"), which are case-sensitive
  std::string value;       ///< serialize_tokens of the value: comments removed, whitespace collapsed, trimmed
  bool important = false;  ///< the value ended with "!important" (removed from `value`)
};

/// A top-level rule: a qualified rule (selectors and a {} block) or an at-rule.
struct Rule {
  bool is_at_rule = false;
  std::string at_name;                             ///< at-rules: the name without '@', ASCII lower-cased
  std::size_t prelude_begin = 0, prelude_end = 0;  ///< token indices of the prelude
  bool has_block = false;                          ///< at-rules ended by ';' have none
  std::size_t block_begin = 0, block_end = 0;      ///< token indices inside the {} block
};

struct StyleSheetSyntax {
  TokenList tokens;
  std::vector<Rule> rules;
};

/// The rules of a style sheet (5.3.3; CDO and CDC at the top level are skipped). A qualified rule
/// without a block (cut off by the end of the input) is dropped, as 5.4.3 says. At most `max_tokens`
/// tokens are read: when the sheet has more (StyleSheetSyntax::tokens.truncated), the rules after the
/// cut are not there and a rule the cut falls in is dropped too, so that no rule is read half.
[[nodiscard]] StyleSheetSyntax parse_style_sheet(std::string_view text, std::size_t max_tokens = SIZE_MAX);

/// The rules in tokens [begin, end) of `list`, such as the block of an @media rule (5.3.4 "Parse a list of
/// rules"; the same steps as parse_style_sheet).
[[nodiscard]] std::vector<Rule> parse_rule_list(const TokenList& list, std::size_t begin, std::size_t end);

/// The declarations in tokens [begin, end) of `list` (5.4.5 "Consume a list of declarations"): at-rules
/// and malformed declarations are dropped, so are declarations with an empty value. In order: for one
/// property the last declaration of equal importance wins.
[[nodiscard]] std::vector<Declaration> parse_declarations(const TokenList& list, std::size_t begin,
                                                          std::size_t end);

/// The declarations of a style attribute (5.3.8).
[[nodiscard]] std::vector<Declaration> parse_declaration_list(std::string_view text);

/// The index just after the component value starting at token `index` (5.4.7): a block or function
/// with everything up to its matching closing token, or one token. Never beyond `end`.
[[nodiscard]] std::size_t skip_component_value(const TokenList& list, std::size_t index, std::size_t end);

/// ASCII lower case (CSS keywords are ASCII case-insensitive).
[[nodiscard]] std::string ascii_lower(std::string_view text);

/// Whether `a` and `b` are equal but for ASCII case: CSS keywords, and also XML encoding names and
/// language tags, which are ASCII case-insensitive too.
[[nodiscard]] bool ascii_equal_ignoring_case(std::string_view a, std::string_view b) noexcept;

}  // namespace curvescan::svg::css
