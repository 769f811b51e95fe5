// CSS selectors: the model, the parser and specificity (Selectors Level 3; :not() with a selector list,
// :is(), :where() and the attribute case flag from Selectors Level 4).
//
// Supported: type and universal selectors, .class, #id, attribute selectors [a], [a=v], [a~=v], [a|=v],
// [a^=v], [a$=v], [a*=v] (values quoted or not, optional "i" / "s" flag), the combinators descendant,
// child '>', next-sibling '+' and subsequent-sibling '~', the pseudo-classes :first-child, :last-child,
// :only-child, :nth-child(An+B | odd | even), :nth-last-child(), :first-of-type, :last-of-type,
// :only-of-type, :nth-of-type(), :nth-last-of-type(), :root, :empty, :not(<compound selector list>),
// :is(<compound selector list>) and :where(<compound selector list>) (Selectors 4 section 4: they match
// what one of their arguments matches; :where() counts nothing in specificity), and selector lists.
// Functional pseudo-classes nest at most kMaxPseudoNesting deep, and :not() takes no :not().
// Selectors 4 allows complex selectors (with combinators) inside :not(), :is() and :where(); here, as
// for :not(), they are compounds: a combinator inside makes the rule skipped with a warning. That keeps
// matching linear (a combinator inside would walk the ancestors again for every ancestor tried). :is()
// and :where() take their list strictly, not "forgivingly" as Selectors 4 section 4.1 has it: an
// unsupported selector among their arguments skips the rule with a warning naming it, as elsewhere. Anything else -- pseudo-elements, dynamic pseudo-classes such as
// :hover, namespace prefixes -- makes parse_selector_list fail with a message naming it, and the caller
// skips the whole rule, as Selectors 3 section 5 requires of an invalid selector in a list.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "curvescan/status.h"
#include "token.h"

namespace curvescan::svg::css {

/// An attribute selector (Selectors 3 section 6.3).
struct AttributeSelector {
  enum class Operator { kExists, kEquals, kIncludes, kDashMatch, kPrefix, kSuffix, kSubstring };
  std::string name;
  Operator op = Operator::kExists;
  std::string value;
  bool ignore_case = false;  ///< the Selectors 4 "i" flag: ASCII case-insensitive value comparison
};

struct CompoundSelector;

/// One simple selector (Selectors 3 section 6).
struct SimpleSelector {
  enum class Kind {
    kType,
    kUniversal,
    kId,
    kClass,
    kAttribute,
    kNthChild,
    kNthLastChild,
    kOnlyChild,
    kNthOfType,      ///< also :first-of-type (0n+1)
    kNthLastOfType,  ///< also :last-of-type
    kOnlyOfType,
    kRoot,
    kEmpty,
    kNot,
    kIs,     ///< :is() -- specificity of its most specific argument
    kWhere,  ///< :where() -- specificity 0
  };
  Kind kind = Kind::kUniversal;
  std::string name;  ///< kType: local name; kId, kClass: the identifier
  AttributeSelector attribute;
  /// kNthChild, kNthLastChild, kNthOfType, kNthLastOfType: matches positions a*n + b for some n >= 0
  /// (first-child is 0n+1).
  std::int64_t a = 0, b = 1;
  std::vector<CompoundSelector> negated;  ///< kNot: matches when none of these matches
  std::vector<CompoundSelector> any_of;   ///< kIs, kWhere: matches when one of these matches
};

/// Simple selectors that all apply to one element ("a sequence of simple selectors").
struct CompoundSelector {
  std::vector<SimpleSelector> simple;
};

enum class Combinator { kDescendant, kChild, kNextSibling, kSubsequentSibling };

/// Functional pseudo-classes (:not, :is, :where) nested deeper than this are not supported (the rule is
/// skipped with a warning): bounds the parser's and the matcher's recursion.
inline constexpr int kMaxPseudoNesting = 4;

/// A complex selector stored right to left: compounds[0] is the subject (the element styled), and
/// combinators[i] relates compounds[i] to compounds[i + 1], the one written before it.
struct ComplexSelector {
  std::vector<CompoundSelector> compounds;
  std::vector<Combinator> combinators;  ///< compounds.size() - 1 entries
  std::uint32_t specificity = 0;        ///< see specificity()
};

/// Bounds on one selector list.
struct SelectorLimits {
  std::size_t max_selectors = 64;  ///< complex selectors in one list
  std::size_t max_compounds = 32;  ///< compound selectors in one complex selector
  std::size_t max_simple = 64;     ///< simple selectors in one compound (and in one :not())
};

/// Packs (ids, classes + attributes + pseudo-classes, types) into one comparable number, each count
/// saturated at 1023 (Selectors 3 section 9).
[[nodiscard]] constexpr std::uint32_t pack_specificity(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const auto saturate = [](std::uint32_t v) { return v > 1023u ? 1023u : v; };
  return saturate(a) << 20 | saturate(b) << 10 | saturate(c);
}

/// The selector list in tokens [begin, end) of `list`; an error names the first unsupported or malformed
/// part (the caller then skips the rule).
[[nodiscard]] Result<std::vector<ComplexSelector>> parse_selector_list(const TokenList& list,
                                                                       std::size_t begin, std::size_t end,
                                                                       const SelectorLimits& limits = {});

/// An+B (CSS Syntax 3 section 6, "odd", "even") from its text, e.g. "2n+1", "-n + 3", "odd".
[[nodiscard]] std::optional<std::pair<std::int64_t, std::int64_t>> parse_an_plus_b(std::string_view text);

}  // namespace curvescan::svg::css
