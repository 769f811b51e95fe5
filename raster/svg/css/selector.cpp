// The selector parser and specificity (selector.h). Section numbers refer to Selectors Level 3 unless
// marked otherwise.
#include "selector.h"

#include <algorithm>
#include <charconv>
#include <string_view>
#include <tuple>
#include <utility>

#include "syntax.h"
#include "tokenizer.h"

namespace curvescan::svg::css {
namespace {

Error unsupported(std::string what) {
  return Error{ErrorKind::kUnsupported, std::move(what) + " is not supported"};
}
Error malformed(std::string what) {
  return Error{ErrorKind::kInvalidArgument, "malformed selector: " + what};
}

std::uint32_t specificity_of(const CompoundSelector& compound);

// Section 9: ids count in a, classes, attributes and pseudo-classes in b, type selectors in c; the
// universal selector counts nothing. :not() and :is() count as their most specific argument, :where()
// counts nothing (Selectors 4, 17).
void add_specificity(const SimpleSelector& simple, std::uint32_t& a, std::uint32_t& b, std::uint32_t& c) {
  switch (simple.kind) {
    case SimpleSelector::Kind::kId:
      ++a;
      break;
    case SimpleSelector::Kind::kType:
      ++c;
      break;
    case SimpleSelector::Kind::kUniversal:
      break;
    case SimpleSelector::Kind::kNot: {
      std::uint32_t best = 0;
      for (const CompoundSelector& compound : simple.negated) best = std::max(best, specificity_of(compound));
      a += best >> 20;
      b += (best >> 10) & 1023u;
      c += best & 1023u;
      break;
    }
    case SimpleSelector::Kind::kIs: {
      std::uint32_t best = 0;
      for (const CompoundSelector& compound : simple.any_of) best = std::max(best, specificity_of(compound));
      a += best >> 20;
      b += (best >> 10) & 1023u;
      c += best & 1023u;
      break;
    }
    case SimpleSelector::Kind::kWhere:
      break;
    default:
      ++b;
  }
}

std::uint32_t specificity_of(const CompoundSelector& compound) {
  std::uint32_t a = 0, b = 0, c = 0;
  for (const SimpleSelector& simple : compound.simple) add_specificity(simple, a, b, c);
  return pack_specificity(a, b, c);
}

class SelectorParser {
 public:
  SelectorParser(const TokenList& list, const SelectorLimits& limits) : list_(list), limits_(limits) {}

  Result<std::vector<ComplexSelector>> list(std::size_t begin, std::size_t end) {
    std::vector<ComplexSelector> selectors;
    std::size_t start = begin;
    for (std::size_t i = begin;;) {
      if (i == end || type(i) == TokenType::kComma) {
        if (selectors.size() == limits_.max_selectors) {
          return Error{ErrorKind::kLimitExceeded,
                       "more than " + std::to_string(limits_.max_selectors) + " selectors in one list"};
        }
        Result<ComplexSelector> complex = parse_complex(start, i);
        if (!complex) return complex.error();
        selectors.push_back(std::move(complex).value());
        if (i == end) break;
        start = ++i;
        continue;
      }
      i = skip_component_value(list_, i, end);
    }
    return selectors;
  }

  // A list of compound selectors, the argument of :not() (Selectors 4 allows complex selectors there;
  // combinators inside :not() are not supported here).
  Result<std::vector<CompoundSelector>> compound_list(std::size_t begin, std::size_t end) {
    std::vector<CompoundSelector> compounds;
    std::size_t start = begin;
    for (std::size_t i = begin;;) {
      if (i == end || type(i) == TokenType::kComma) {
        const auto [first, last] = trimmed(start, i);
        if (first == last) return malformed("empty argument of :" + pseudo_ + "()");
        if (compounds.size() == limits_.max_selectors) {
          return Error{ErrorKind::kLimitExceeded,
                       "more than " + std::to_string(limits_.max_selectors) + " selectors in :" + pseudo_ + "()"};
        }
        std::size_t next = first;
        Result<CompoundSelector> compound = parse_compound(next, last);
        if (!compound) return compound.error();
        if (next != last) return unsupported("a combinator inside :" + pseudo_ + "()");
        compounds.push_back(std::move(compound).value());
        if (i == end) break;
        start = ++i;
        continue;
      }
      i = skip_component_value(list_, i, end);
    }
    return compounds;
  }

 private:
  TokenType type(std::size_t i) const { return list_.tokens[i].type; }
  bool is_delim(std::size_t i, std::size_t end, char c) const {
    return i < end && type(i) == TokenType::kDelim && list_.tokens[i].value.size() == 1 &&
           list_.tokens[i].value[0] == c;
  }
  std::string text(std::size_t first, std::size_t last) const { return serialize_tokens(list_, first, last); }

  std::pair<std::size_t, std::size_t> trimmed(std::size_t first, std::size_t last) const {
    while (first < last && type(first) == TokenType::kWhitespace) ++first;
    while (last > first && type(last - 1) == TokenType::kWhitespace) --last;
    return {first, last};
  }

  // Section 5: compound (combinator compound)*.
  Result<ComplexSelector> parse_complex(std::size_t begin, std::size_t end) {
    const auto [first, last] = trimmed(begin, end);
    if (first == last) return malformed("an empty selector");
    ComplexSelector complex;
    std::size_t i = first;
    while (true) {
      if (complex.compounds.size() == limits_.max_compounds) {
        return Error{
            ErrorKind::kLimitExceeded,
            "a selector of more than " + std::to_string(limits_.max_compounds) + " compound selectors"};
      }
      Result<CompoundSelector> compound = parse_compound(i, last);
      if (!compound) return compound.error();
      complex.compounds.push_back(std::move(compound).value());
      if (i == last) break;
      // Whitespace alone is the descendant combinator; '>', '+', '~' may have whitespace around them.
      bool whitespace = false;
      while (i < last && type(i) == TokenType::kWhitespace) {
        whitespace = true;
        ++i;
      }
      Combinator combinator = Combinator::kDescendant;
      if (is_delim(i, last, '>')) {
        combinator = Combinator::kChild;
      } else if (is_delim(i, last, '+')) {
        combinator = Combinator::kNextSibling;
      } else if (is_delim(i, last, '~')) {
        combinator = Combinator::kSubsequentSibling;
      } else if (!whitespace) {
        return malformed("unexpected '" + text(i, i + 1) + "'");
      }
      if (combinator != Combinator::kDescendant) {
        ++i;
        while (i < last && type(i) == TokenType::kWhitespace) ++i;
        if (i == last) return malformed("a combinator at the end");
      }
      complex.combinators.push_back(combinator);
    }
    std::uint32_t a = 0, b = 0, c = 0;
    for (const CompoundSelector& compound : complex.compounds) {
      for (const SimpleSelector& simple : compound.simple) add_specificity(simple, a, b, c);
    }
    complex.specificity = pack_specificity(a, b, c);
    std::reverse(complex.compounds.begin(), complex.compounds.end());
    std::reverse(complex.combinators.begin(), complex.combinators.end());
    return complex;
  }

  // Section 4: [type or universal] followed by #id, .class, [attribute], :pseudo-class in any order.
  // Stops at whitespace, a combinator, or `end`; `i` is left there.
  Result<CompoundSelector> parse_compound(std::size_t& i, std::size_t end) {
    CompoundSelector compound;
    const auto add = [&](SimpleSelector simple) -> Status {
      if (compound.simple.size() == limits_.max_simple) {
        return Error{ErrorKind::kLimitExceeded, "a compound selector of more than " +
                                                    std::to_string(limits_.max_simple) + " simple selectors"};
      }
      compound.simple.push_back(std::move(simple));
      return Status::ok();
    };
    if (i < end && (type(i) == TokenType::kIdent || is_delim(i, end, '*'))) {
      if (is_delim(i + 1, end, '|')) return unsupported("the namespace prefix '" + text(i, i + 2) + "'");
      SimpleSelector simple;
      if (type(i) == TokenType::kIdent) {
        simple.kind = SimpleSelector::Kind::kType;
        simple.name = list_.tokens[i].value;
      }
      CURVESCAN_PROPAGATE(add(std::move(simple)));
      ++i;
    } else if (is_delim(i, end, '|')) {
      return unsupported("the namespace prefix '|'");
    }
    while (i < end) {
      const Token& token = list_.tokens[i];
      if (token.type == TokenType::kHash) {
        if (!token.is_id_hash) return malformed("'#" + token.value + "' is not an identifier");
        SimpleSelector simple;
        simple.kind = SimpleSelector::Kind::kId;
        simple.name = token.value;
        CURVESCAN_PROPAGATE(add(std::move(simple)));
        ++i;
      } else if (is_delim(i, end, '.')) {
        if (i + 1 >= end || type(i + 1) != TokenType::kIdent) return malformed("'.' without a class name");
        SimpleSelector simple;
        simple.kind = SimpleSelector::Kind::kClass;
        simple.name = list_.tokens[i + 1].value;
        CURVESCAN_PROPAGATE(add(std::move(simple)));
        i += 2;
      } else if (token.type == TokenType::kOpenSquare) {
        const std::size_t after = skip_component_value(list_, i, end);
        if (type(after - 1) != TokenType::kCloseSquare || after - 1 == i) return malformed("an unclosed '['");
        Result<SimpleSelector> simple = parse_attribute(i + 1, after - 1);
        if (!simple) return simple.error();
        CURVESCAN_PROPAGATE(add(std::move(simple).value()));
        i = after;
      } else if (token.type == TokenType::kColon) {
        Result<SimpleSelector> simple = parse_pseudo(i, end);
        if (!simple) return simple.error();
        CURVESCAN_PROPAGATE(add(std::move(simple).value()));
      } else if (token.type == TokenType::kWhitespace || is_delim(i, end, '>') || is_delim(i, end, '+') ||
                 is_delim(i, end, '~')) {
        break;
      } else if (token.type == TokenType::kIdent || is_delim(i, end, '*')) {
        return malformed("a type selector '" + text(i, i + 1) + "' after other simple selectors");
      } else {
        return malformed("unexpected '" + text(i, i + 1) + "'");
      }
    }
    if (compound.simple.empty()) return malformed("an empty compound selector");
    return compound;
  }

  // Section 6.3: [name], [name op value], [name op value i|s] from the tokens inside the brackets.
  Result<SimpleSelector> parse_attribute(std::size_t begin, std::size_t end) {
    auto [i, last] = trimmed(begin, end);
    SimpleSelector simple;
    simple.kind = SimpleSelector::Kind::kAttribute;
    AttributeSelector& attribute = simple.attribute;
    if (i < last && (is_delim(i, last, '|') || (is_delim(i + 1, last, '|') && !is_delim(i + 2, last, '=')))) {
      return unsupported("the namespaced attribute selector '[" + text(begin, end) + "]'");
    }
    if (i >= last || type(i) != TokenType::kIdent) return malformed("'[" + text(begin, end) + "]'");
    attribute.name = list_.tokens[i++].value;
    while (i < last && type(i) == TokenType::kWhitespace) ++i;
    if (i == last) return simple;
    using Op = AttributeSelector::Operator;
    if (is_delim(i, last, '=')) {
      attribute.op = Op::kEquals;
      ++i;
    } else if (is_delim(i + 1, last, '=') && type(i) == TokenType::kDelim) {
      switch (list_.tokens[i].value[0]) {
        case '~':
          attribute.op = Op::kIncludes;
          break;
        case '|':
          attribute.op = Op::kDashMatch;
          break;
        case '^':
          attribute.op = Op::kPrefix;
          break;
        case '$':
          attribute.op = Op::kSuffix;
          break;
        case '*':
          attribute.op = Op::kSubstring;
          break;
        default:
          return malformed("'[" + text(begin, end) + "]'");
      }
      i += 2;
    } else {
      return malformed("'[" + text(begin, end) + "]'");
    }
    while (i < last && type(i) == TokenType::kWhitespace) ++i;
    if (i == last || (type(i) != TokenType::kIdent && type(i) != TokenType::kString)) {
      return malformed("'[" + text(begin, end) + "]'");
    }
    attribute.value = list_.tokens[i++].value;
    while (i < last && type(i) == TokenType::kWhitespace) ++i;
    if (i < last && type(i) == TokenType::kIdent) {  // Selectors 4, 6.3: the case-sensitivity flag
      const std::string flag = ascii_lower(list_.tokens[i].value);
      if (flag != "i" && flag != "s") return malformed("'[" + text(begin, end) + "]'");
      attribute.ignore_case = flag == "i";
      ++i;
      while (i < last && type(i) == TokenType::kWhitespace) ++i;
    }
    if (i != last) return malformed("'[" + text(begin, end) + "]'");
    return simple;
  }

  // Section 6.6: a pseudo-class starting at the ':' at `i`; `i` is left after it.
  Result<SimpleSelector> parse_pseudo(std::size_t& i, std::size_t end) {
    const std::size_t colon = i++;
    if (i < end && type(i) == TokenType::kColon) {
      const std::size_t name_end = std::min(end, i + 2);
      return unsupported("the pseudo-element '" + text(colon, name_end) + "'");
    }
    if (i >= end) return malformed("':' without a name");
    SimpleSelector simple;
    const Token& token = list_.tokens[i];
    const std::string name = ascii_lower(token.value);
    if (token.type == TokenType::kIdent) {
      ++i;
      // The pseudo-classes without an argument (Selectors 4, 14.4). The first and last ones are the An+B
      // forms with SimpleSelector's a = 0, b = 1 (14.4.3, 14.4.4, 14.4.6, 14.4.7).
      using Kind = SimpleSelector::Kind;
      static constexpr std::pair<std::string_view, Kind> kPlain[] = {
          {"first-child", Kind::kNthChild},
          {"last-child", Kind::kNthLastChild},
          {"only-child", Kind::kOnlyChild},
          {"first-of-type", Kind::kNthOfType},
          {"last-of-type", Kind::kNthLastOfType},
          {"only-of-type", Kind::kOnlyOfType},
          {"root", Kind::kRoot},
          {"empty", Kind::kEmpty},
      };
      for (const auto& [plain, kind] : kPlain) {
        if (name != plain) continue;
        simple.kind = kind;
        return simple;
      }
      return unsupported("the pseudo-class ':" + token.value + "'");
    }
    if (token.type == TokenType::kFunction) {
      const std::size_t after = skip_component_value(list_, i, end);
      const std::size_t inner_end =
          type(after - 1) == TokenType::kCloseParen && after - 1 > i ? after - 1 : after;
      const std::size_t inner_begin = i + 1;
      i = after;
      if (name == "nth-child" || name == "nth-last-child" || name == "nth-of-type" || name == "nth-last-of-type") {
        const auto [first, last] = trimmed(inner_begin, inner_end);
        std::string argument;
        for (std::size_t k = first; k < last; ++k) argument += text(k, k + 1);
        const std::optional<std::pair<std::int64_t, std::int64_t>> an_b = parse_an_plus_b(argument);
        if (!an_b) return malformed("':" + name + "(" + text(inner_begin, inner_end) + ")'");
        using Kind = SimpleSelector::Kind;
        simple.kind = name == "nth-child"        ? Kind::kNthChild
                      : name == "nth-last-child" ? Kind::kNthLastChild
                      : name == "nth-of-type"    ? Kind::kNthOfType
                                                 : Kind::kNthLastOfType;
        std::tie(simple.a, simple.b) = *an_b;
        return simple;
      }
      if ((name == "not" || name == "is" || name == "where") && depth_ >= kMaxPseudoNesting)
        return unsupported("':" + name + "()' nested more than " + std::to_string(kMaxPseudoNesting) + " deep");
      if (name == "not") {
        // Selectors 3 allows no :not() inside :not().
        if (inside_not_) return unsupported("':not()' inside ':not()'");
        inside_not_ = true;
        ++depth_;
        const std::string outer = std::exchange(pseudo_, name);
        Result<std::vector<CompoundSelector>> negated = compound_list(inner_begin, inner_end);
        pseudo_ = outer;
        --depth_;
        inside_not_ = false;
        if (!negated) return negated.error();
        simple.kind = SimpleSelector::Kind::kNot;
        simple.negated = std::move(negated).value();
        return simple;
      }
      if (name == "is" || name == "where") {  // Selectors 4, 4.2 and 4.4
        ++depth_;
        const std::string outer = std::exchange(pseudo_, name);
        Result<std::vector<CompoundSelector>> any_of = compound_list(inner_begin, inner_end);
        pseudo_ = outer;
        --depth_;
        if (!any_of) return any_of.error();
        simple.kind = name == "is" ? SimpleSelector::Kind::kIs : SimpleSelector::Kind::kWhere;
        simple.any_of = std::move(any_of).value();
        return simple;
      }
      return unsupported("the pseudo-class ':" + token.value + "()'");
    }
    return malformed("':' followed by '" + text(i, i + 1) + "'");
  }

  const TokenList& list_;
  const SelectorLimits& limits_;
  bool inside_not_ = false;
  std::string pseudo_ = "not";  // the functional pseudo-class whose argument compound_list reads
  int depth_ = 0;  // functional pseudo-classes around the part being parsed
};

// A signed decimal integer of at most 9 digits (larger positions never match a real document).
std::optional<std::int64_t> parse_small_integer(std::string_view text) {
  bool negative = false;
  if (!text.empty() && (text.front() == '+' || text.front() == '-')) {
    negative = text.front() == '-';
    text.remove_prefix(1);
  }
  if (text.empty() || text.size() > 9) return std::nullopt;
  std::int64_t value = 0;
  const auto parsed = std::from_chars(text.data(), text.data() + text.size(), value);
  if (parsed.ec != std::errc() || parsed.ptr != text.data() + text.size()) return std::nullopt;
  return negative ? -value : value;
}

}  // namespace

Result<std::vector<ComplexSelector>> parse_selector_list(const TokenList& list, std::size_t begin,
                                                         std::size_t end, const SelectorLimits& limits) {
  return SelectorParser(list, limits).list(begin, end);
}

std::optional<std::pair<std::int64_t, std::int64_t>> parse_an_plus_b(std::string_view text) {
  // The argument's tokens re-joined without whitespace, so "2n + 1", "2n+1" and "2n +1" read alike.
  std::string compact;
  for (const char c : text) {
    if (c != ' ' && c != '\t' && c != '\n')
      compact += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
  }
  if (compact == "odd") return std::pair<std::int64_t, std::int64_t>{2, 1};
  if (compact == "even") return std::pair<std::int64_t, std::int64_t>{2, 0};
  const std::size_t n = compact.find('n');
  if (n == std::string::npos) {
    const std::optional<std::int64_t> b = parse_small_integer(compact);
    if (!b) return std::nullopt;
    return std::pair<std::int64_t, std::int64_t>{0, *b};
  }
  const std::string_view a_text = std::string_view(compact).substr(0, n);
  std::int64_t a = 0;
  if (a_text.empty() || a_text == "+") {
    a = 1;
  } else if (a_text == "-") {
    a = -1;
  } else if (const std::optional<std::int64_t> parsed = parse_small_integer(a_text)) {
    a = *parsed;
  } else {
    return std::nullopt;
  }
  const std::string_view b_text = std::string_view(compact).substr(n + 1);
  if (b_text.empty()) return std::pair<std::int64_t, std::int64_t>{a, 0};
  if (b_text.front() != '+' && b_text.front() != '-') return std::nullopt;  // "2n1" is not An+B
  const std::optional<std::int64_t> b = parse_small_integer(b_text);
  if (!b) return std::nullopt;
  return std::pair<std::int64_t, std::int64_t>{a, *b};
}

}  // namespace curvescan::svg::css
