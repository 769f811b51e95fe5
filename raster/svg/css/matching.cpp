// Selector matching (matching.h). Section numbers refer to Selectors Level 3.
#include "matching.h"

#include <algorithm>
#include <iterator>
#include <string_view>

#include "xml_names.h"

namespace curvescan::svg::css {
namespace {

bool is_element(const pugi::xml_node& node) {
  return node.type() == pugi::node_element;
}

pugi::xml_node parent_element(const pugi::xml_node& node) {
  const pugi::xml_node parent = node.parent();
  return is_element(parent) ? parent : pugi::xml_node();
}

pugi::xml_node previous_element(pugi::xml_node node) {
  for (node = node.previous_sibling(); node; node = node.previous_sibling()) {
    if (is_element(node)) return node;
  }
  return {};
}

pugi::xml_node next_element(pugi::xml_node node) {
  for (node = node.next_sibling(); node; node = node.next_sibling()) {
    if (is_element(node)) return node;
  }
  return {};
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f';
}

char lower(char c) {
  return c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
}

bool equal(std::string_view a, std::string_view b, bool ignore_case) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (ignore_case ? lower(a[i]) != lower(b[i]) : a[i] != b[i]) return false;
  }
  return true;
}

bool contains(std::string_view haystack, std::string_view needle, bool ignore_case) {
  if (needle.size() > haystack.size()) return false;
  for (std::size_t i = 0; i + needle.size() <= haystack.size(); ++i) {
    if (equal(haystack.substr(i, needle.size()), needle, ignore_case)) return true;
  }
  return false;
}

// "~=": `value` is one of the whitespace-separated words of `list` (6.3.1).
bool includes_word(std::string_view list, std::string_view value, bool ignore_case) {
  if (value.empty()) return false;
  for (const char c : value) {
    if (is_space(c)) return false;
  }
  std::size_t i = 0;
  while (i < list.size()) {
    while (i < list.size() && is_space(list[i])) ++i;
    std::size_t end = i;
    while (end < list.size() && !is_space(list[end])) ++end;
    if (end > i && equal(list.substr(i, end - i), value, ignore_case)) return true;
    i = end;
  }
  return false;
}

// 6.3.1 and 6.3.2.
bool matches_attribute(const AttributeSelector& selector, const pugi::xml_node& element) {
  const pugi::xml_attribute attribute = element.attribute(selector.name.c_str());
  if (!attribute) return false;
  const std::string_view actual = attribute.value();
  const std::string_view wanted = selector.value;
  const bool icase = selector.ignore_case;
  using Op = AttributeSelector::Operator;
  switch (selector.op) {
    case Op::kExists:
      return true;
    case Op::kEquals:
      return equal(actual, wanted, icase);
    case Op::kIncludes:
      return includes_word(actual, wanted, icase);
    case Op::kDashMatch:
      return equal(actual, wanted, icase) || (actual.size() > wanted.size() && actual[wanted.size()] == '-' &&
                                              equal(actual.substr(0, wanted.size()), wanted, icase));
    // 6.3.2: an empty value matches nothing for ^=, $= and *=.
    case Op::kPrefix:
      return !wanted.empty() && actual.size() >= wanted.size() &&
             equal(actual.substr(0, wanted.size()), wanted, icase);
    case Op::kSuffix:
      return !wanted.empty() && actual.size() >= wanted.size() &&
             equal(actual.substr(actual.size() - wanted.size()), wanted, icase);
    case Op::kSubstring:
      return !wanted.empty() && contains(actual, wanted, icase);
  }
  return false;
}

// 6.6.5.2: whether 1-based `position` is a*n + b for some integer n >= 0.
bool matches_an_plus_b(std::int64_t a, std::int64_t b, std::int64_t position) {
  if (a == 0) return position == b;
  const std::int64_t difference = position - b;
  return difference % a == 0 && difference / a >= 0;
}

bool matches_simple(const SimpleSelector& simple, const pugi::xml_node& element, const MatchCache& cache) {
  using Kind = SimpleSelector::Kind;
  switch (simple.kind) {
    case Kind::kUniversal:
      return true;
    case Kind::kType:
      return detail::local_name(element) == simple.name;
    case Kind::kId:
      return std::string_view(element.attribute("id").value()) == simple.name;
    case Kind::kClass:
      return includes_word(element.attribute("class").value(), simple.name, false);
    case Kind::kAttribute:
      return matches_attribute(simple.attribute, element);
    // 6.6.5: the position among the parent's element children; the root has no parent element and so
    // no position (Selectors 4 counts it as the first and last child of its document; Selectors 3 does
    // not say). Following Selectors 4.
    case Kind::kNthChild:
      return matches_an_plus_b(simple.a, simple.b, cache.position(element).from_start);
    case Kind::kNthLastChild:
      return matches_an_plus_b(simple.a, simple.b, cache.position(element).from_end);
    case Kind::kOnlyChild:
      return !previous_element(element) && !next_element(element);
    // Selectors 4, 14.4.5 to 14.4.10: the position among the siblings of the element's type.
    case Kind::kNthOfType:
      return matches_an_plus_b(simple.a, simple.b, cache.position(element).of_type_from_start);
    case Kind::kNthLastOfType:
      return matches_an_plus_b(simple.a, simple.b, cache.position(element).of_type_from_end);
    case Kind::kOnlyOfType: {
      const MatchCache::Position position = cache.position(element);
      return position.of_type_from_start == 1 && position.of_type_from_end == 1;
    }
    case Kind::kRoot:
      return element.parent().type() == pugi::node_document;  // 6.6.5.1
    case Kind::kEmpty:
      return !element.first_child();  // 6.6.5.10: no element and no text children
    case Kind::kNot:
      for (const CompoundSelector& negated : simple.negated) {
        if (matches_compound(negated, element, cache)) return false;
      }
      return true;
    case Kind::kIs:
    case Kind::kWhere:
      for (const CompoundSelector& compound : simple.any_of) {
        if (matches_compound(compound, element, cache)) return true;
      }
      return false;
  }
  return false;
}

enum class Outcome : std::uint8_t { kMatched, kRetryLaterSibling, kRetryDescendant, kFailedGlobally };

// Up to this many earlier siblings, a `~` walks; beyond, it looks the answer up (MatchCache).
constexpr std::int64_t kSiblingsWalked = 32;

// Matches compounds[index..] of `selector` with compounds[index] against `element`.
Outcome match_from(const ComplexSelector& selector, std::size_t index, const pugi::xml_node& element,
                   const MatchCache& cache) {
  if (!matches_compound(selector.compounds[index], element, cache)) return Outcome::kRetryLaterSibling;
  if (index + 1 == selector.compounds.size()) return Outcome::kMatched;
  const Combinator combinator = selector.combinators[index];
  const bool sibling = combinator == Combinator::kNextSibling || combinator == Combinator::kSubsequentSibling;
  // When the candidates run out: a sibling combinator may still succeed from another ancestor (an
  // enclosing descendant combinator retries); an ancestor combinator cannot.
  const Outcome exhausted = sibling ? Outcome::kRetryDescendant : Outcome::kFailedGlobally;
  if (combinator == Combinator::kSubsequentSibling) {
    // The walk below ends at the nearest earlier sibling whose outcome is not kRetryLaterSibling. That
    // outcome depends on the sibling only, so past a few siblings it is looked up (matching.h).
    const std::int64_t position = cache.position(element).from_start;
    if (position > kSiblingsWalked) {
      const MatchCache::DecisiveSiblings* decisive =
          cache.decisive_siblings(selector, index + 1, element.parent(), [&] {
            MatchCache::DecisiveSiblings found;
            std::int64_t at = 0;
            for (pugi::xml_node child = element.parent().first_child(); child; child = child.next_sibling()) {
              if (!is_element(child)) continue;
              ++at;
              const Outcome outcome = match_from(selector, index + 1, child, cache);
              if (outcome != Outcome::kRetryLaterSibling)
                found.emplace_back(at, static_cast<std::uint8_t>(outcome));
            }
            return found;
          });
      if (decisive) {
        const auto after =
            std::lower_bound(decisive->begin(), decisive->end(), position,
                             [](const auto& entry, std::int64_t p) { return entry.first < p; });
        return after == decisive->begin() ? exhausted : static_cast<Outcome>(std::prev(after)->second);
      }
    }
  }
  pugi::xml_node candidate = element;
  while (true) {
    candidate = sibling ? previous_element(candidate) : parent_element(candidate);
    if (!candidate) return exhausted;
    const Outcome outcome = match_from(selector, index + 1, candidate, cache);
    if (outcome == Outcome::kMatched || outcome == Outcome::kFailedGlobally) return outcome;
    switch (combinator) {
      case Combinator::kNextSibling:
        return outcome;  // one candidate only
      case Combinator::kChild:
        return Outcome::kRetryDescendant;  // one candidate only
      case Combinator::kSubsequentSibling:
        // A failure that needs another ancestor cannot be mended by an earlier sibling.
        if (outcome == Outcome::kRetryDescendant) return outcome;
        break;
      case Combinator::kDescendant:
        break;  // try the next ancestor
    }
  }
}

}  // namespace

MatchCache::Position MatchCache::position(const pugi::xml_node& element) const {
  const std::lock_guard lock(mutex_);
  if (const auto found = positions_.find(element.internal_object()); found != positions_.end())
    return found->second;
  // Number every element child of the parent at once (the root's parent is the document node), and
  // each type's children.
  std::int64_t count = 0;
  std::unordered_map<std::string_view, std::int64_t> of_type;
  for (pugi::xml_node child = element.parent().first_child(); child; child = child.next_sibling()) {
    if (is_element(child))
      positions_[child.internal_object()] = Position{++count, 0, ++of_type[detail::local_name(child)], 0};
  }
  for (pugi::xml_node child = element.parent().first_child(); child; child = child.next_sibling()) {
    if (is_element(child)) {
      Position& position = positions_[child.internal_object()];
      position.from_end = count + 1 - position.from_start;
      position.of_type_from_end = of_type[detail::local_name(child)] + 1 - position.of_type_from_start;
    }
  }
  return positions_[element.internal_object()];
}

bool matches_compound(const CompoundSelector& compound, const pugi::xml_node& element,
                      const MatchCache& cache) {
  for (const SimpleSelector& simple : compound.simple) {
    if (!matches_simple(simple, element, cache)) return false;
  }
  return true;
}

bool matches(const ComplexSelector& selector, const pugi::xml_node& element, const MatchCache& cache) {
  return !selector.compounds.empty() && match_from(selector, 0, element, cache) == Outcome::kMatched;
}

}  // namespace curvescan::svg::css
