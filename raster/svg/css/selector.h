// CSS selectors: the model, the parser and specificity (Selectors Level 3; :not() with a selector list
// and the attribute case flag from Selectors Level 4).
//
// Supported: type and universal selectors, .class, #id, attribute selectors [a], [a=v], [a~=v], [a|=v],
// [a^=v], [a$=v], [a*=v] (values quoted or not, optional "i" / "s" flag), the combinators descendant,
// child '>', next-sibling '+' and subsequent-sibling '~', the pseudo-classes :first-child, :last-child,
// :only-child, :nth-child(An+B | odd | even), :nth-last-child(), :root, :empty and :not(<compound
// selector list>), and selector lists. Anything else -- pseudo-elements, dynamic pseudo-classes such as
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
    kRoot,
    kEmpty,
    kNot
  };
  Kind kind = Kind::kUniversal;
  std::string name;  ///< kType: local name; kId, kClass: the identifier
  AttributeSelector attribute;
  /// kNthChild, kNthLastChild: matches positions a*n + b for some n >= 0 (first-child is 0n+1).
  std::int64_t a = 0, b = 1;
  std::vector<CompoundSelector> negated;  ///< kNot: matches when none of these matches
};

/// Simple selectors that all apply to one element ("a sequence of simple selectors").
struct CompoundSelector {
  std::vector<SimpleSelector> simple;
};

enum class Combinator { kDescendant, kChild, kNextSibling, kSubsequentSibling };

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
