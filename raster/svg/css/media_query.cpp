// Media queries (media_query.h). Section numbers refer to Media Queries Level 4.
#include "media_query.h"

#include <array>
#include <cmath>
#include <optional>
#include <string_view>
#include <utility>

#include "syntax.h"

namespace curvescan::svg::css {

// Kleene's three-valued logic of section 3.2: unknown is false at the top of a query.
enum class Truth { kFalse, kTrue, kUnknown };

namespace {

Truth negate(Truth value) {
  if (value == Truth::kUnknown) return value;
  return value == Truth::kTrue ? Truth::kFalse : Truth::kTrue;
}

// A feature's value in a query (section 4.2 "Media Feature Types").
struct Value {
  enum class Kind { kNumber, kLength, kResolution, kRatio, kIdent };
  Kind kind = Kind::kNumber;
  double number = 0.0;  ///< kNumber, kLength (px), kResolution (dppx), kRatio (width / height)
  std::string ident;    ///< kIdent, lower-cased
};

// "feature op value".
struct Comparison {
  enum class Op { kLess, kLessEqual, kEqual, kGreaterEqual, kGreater };
  Op op = Op::kEqual;
  Value value;
};

Comparison::Op flipped(Comparison::Op op) {
  switch (op) {
    case Comparison::Op::kLess:
      return Comparison::Op::kGreater;
    case Comparison::Op::kLessEqual:
      return Comparison::Op::kGreaterEqual;
    case Comparison::Op::kGreaterEqual:
      return Comparison::Op::kLessEqual;
    case Comparison::Op::kGreater:
      return Comparison::Op::kLess;
    case Comparison::Op::kEqual:
      break;
  }
  return Comparison::Op::kEqual;
}

// px per unit of an absolute or font-relative length (CSS Values 4, 6.1 and 6.2; media_query.h for the
// font-relative ones).
std::optional<double> px_per_unit(const std::string& unit) {
  static constexpr std::array<std::pair<std::string_view, double>, 11> kUnits{{{"px", 1.0},
                                                                               {"in", 96.0},
                                                                               {"cm", 96.0 / 2.54},
                                                                               {"mm", 96.0 / 25.4},
                                                                               {"q", 96.0 / 101.6},
                                                                               {"pt", 96.0 / 72.0},
                                                                               {"pc", 16.0},
                                                                               {"em", 16.0},
                                                                               {"rem", 16.0},
                                                                               {"ex", 8.0},
                                                                               {"ch", 8.0}}};
  for (const auto& [name, factor] : kUnits) {
    if (name == unit) return factor;
  }
  return std::nullopt;
}

}  // namespace

struct MediaFeatureTest {
  std::string name;  ///< lower-cased, without min- / max-
  bool boolean = false;
  std::vector<Comparison> comparisons;  ///< all must hold
};

struct MediaCondition {
  enum class Kind { kFeature, kNot, kAnd, kOr, kUnknown };
  Kind kind = Kind::kUnknown;
  std::vector<MediaCondition> children;
  MediaFeatureTest feature;
};

struct MediaQueryList::Query {
  bool malformed = false;  ///< "not all"
  bool negated = false;
  bool type_matches = true;
  std::optional<MediaCondition> condition;
};

namespace {

// The features of media_query.h: which exist, whether they take ranges (min-/max-), and their value.
enum class FeatureType { kUnknown, kRange, kDiscrete };

FeatureType feature_type(std::string_view name) {
  static constexpr std::array<std::string_view, 7> kRange{
      "width", "height", "aspect-ratio", "resolution", "color", "color-index", "monochrome"};
  static constexpr std::array<std::string_view, 20> kDiscrete{"orientation",
                                                              "prefers-color-scheme",
                                                              "prefers-reduced-motion",
                                                              "prefers-contrast",
                                                              "prefers-reduced-transparency",
                                                              "prefers-reduced-data",
                                                              "forced-colors",
                                                              "inverted-colors",
                                                              "hover",
                                                              "any-hover",
                                                              "pointer",
                                                              "any-pointer",
                                                              "grid",
                                                              "scan",
                                                              "update",
                                                              "scripting",
                                                              "overflow-block",
                                                              "overflow-inline",
                                                              "color-gamut",
                                                              "dynamic-range"};
  for (const std::string_view known : kRange) {
    if (known == name) return FeatureType::kRange;
  }
  for (const std::string_view known : kDiscrete) {
    if (known == name) return FeatureType::kDiscrete;
  }
  if (name == "display-mode") return FeatureType::kDiscrete;
  return FeatureType::kUnknown;
}

// The medium's value of a known feature; nullopt when it is unknown (the size before it is known).
std::optional<Value> medium_value(std::string_view name, const MediaFeatures& medium) {
  const auto number = [](Value::Kind kind, double x) { return Value{kind, x, {}}; };
  const auto ident = [](std::string text) { return Value{Value::Kind::kIdent, 0.0, std::move(text)}; };
  if (name == "width" || name == "height" || name == "aspect-ratio" || name == "orientation") {
    if (!medium.size_known) return std::nullopt;
    if (name == "width") return number(Value::Kind::kLength, medium.width);
    if (name == "height") return number(Value::Kind::kLength, medium.height);
    if (name == "orientation") return ident(medium.height >= medium.width ? "portrait" : "landscape");
    if (!(medium.height > 0.0)) return std::nullopt;
    return number(Value::Kind::kRatio, medium.width / medium.height);
  }
  if (name == "resolution") return number(Value::Kind::kResolution, medium.dpi / 96.0);
  if (name == "color") return number(Value::Kind::kNumber, 8.0);
  if (name == "color-index" || name == "monochrome" || name == "grid")
    return number(Value::Kind::kNumber, 0.0);
  if (name == "prefers-color-scheme") return ident("light");
  if (name == "prefers-reduced-motion" || name == "prefers-contrast" ||
      name == "prefers-reduced-transparency" || name == "prefers-reduced-data")
    return ident("no-preference");
  if (name == "scan") return ident("progressive");
  if (name == "color-gamut") return ident("srgb");
  if (name == "dynamic-range") return ident("standard");
  if (name == "display-mode") return ident("browser");
  return ident("none");  // forced-colors, inverted-colors, hover, pointer, update, scripting, overflow-*
}

Truth compare(double medium, Comparison::Op op, double query) {
  switch (op) {
    case Comparison::Op::kLess:
      return medium < query ? Truth::kTrue : Truth::kFalse;
    case Comparison::Op::kLessEqual:
      return medium <= query ? Truth::kTrue : Truth::kFalse;
    case Comparison::Op::kEqual:
      return medium == query ? Truth::kTrue : Truth::kFalse;
    case Comparison::Op::kGreaterEqual:
      return medium >= query ? Truth::kTrue : Truth::kFalse;
    case Comparison::Op::kGreater:
      return medium > query ? Truth::kTrue : Truth::kFalse;
  }
  return Truth::kUnknown;
}

Truth evaluate_feature(const MediaFeatureTest& test, const MediaFeatures& medium) {
  const std::optional<Value> value = medium_value(test.name, medium);
  if (!value) return Truth::kUnknown;
  if (test.boolean) {  // section 2.4.3 "Evaluating Media Features in a Boolean Context"
    if (value->kind == Value::Kind::kIdent)
      return value->ident == "none" || value->ident == "no-preference" ? Truth::kFalse : Truth::kTrue;
    return value->number != 0.0 ? Truth::kTrue : Truth::kFalse;
  }
  for (const Comparison& comparison : test.comparisons) {
    const Value& query = comparison.value;
    Truth result = Truth::kUnknown;
    if (value->kind == Value::Kind::kIdent) {
      if (query.kind == Value::Kind::kIdent && comparison.op == Comparison::Op::kEqual)
        result = query.ident == value->ident ? Truth::kTrue : Truth::kFalse;
    } else if (query.kind == value->kind ||
               (query.kind == Value::Kind::kNumber && value->kind == Value::Kind::kRatio) ||
               (query.kind == Value::Kind::kNumber && query.number == 0.0 &&
                value->kind == Value::Kind::kLength)) {
      // A lone number is a ratio of number / 1 (section 4.2.3); 0 is a length without its unit.
      result = compare(value->number, comparison.op, query.number);
    }
    if (result != Truth::kTrue) return result;  // a value of the wrong type is unknown
  }
  return Truth::kTrue;
}

Truth evaluate(const MediaCondition& condition, const MediaFeatures& medium) {
  switch (condition.kind) {
    case MediaCondition::Kind::kFeature:
      return evaluate_feature(condition.feature, medium);
    case MediaCondition::Kind::kNot:
      return negate(evaluate(condition.children.front(), medium));
    case MediaCondition::Kind::kAnd: {
      Truth result = Truth::kTrue;
      for (const MediaCondition& child : condition.children) {
        const Truth value = evaluate(child, medium);
        if (value == Truth::kFalse) return Truth::kFalse;
        if (value == Truth::kUnknown) result = Truth::kUnknown;
      }
      return result;
    }
    case MediaCondition::Kind::kOr: {
      Truth result = Truth::kFalse;
      for (const MediaCondition& child : condition.children) {
        const Truth value = evaluate(child, medium);
        if (value == Truth::kTrue) return Truth::kTrue;
        if (value == Truth::kUnknown) result = Truth::kUnknown;
      }
      return result;
    }
    case MediaCondition::Kind::kUnknown:
      break;
  }
  return Truth::kUnknown;
}

// Reads one query's tokens, whitespace skipped.
class QueryParser {
 public:
  QueryParser(const TokenList& list, std::size_t begin, std::size_t end, std::set<std::string>& unsupported)
      : list_(list), at_(begin), end_(end), unsupported_(unsupported) {}

  // Section 3, <media-query>; nullopt when malformed.
  std::optional<MediaQueryList::Query> query() {
    MediaQueryList::Query query;
    skip_whitespace();
    if (at_ >= end_) return std::nullopt;  // an empty query in a list is malformed
    if (peek_ident("not") && next_is_paren()) {
      std::optional<MediaCondition> condition = parse_condition(true, 0);
      if (!condition || !at_end()) return std::nullopt;
      query.condition = std::move(condition);
      return query;
    }
    if (is(TokenType::kIdent)) {
      std::string type = ascii_lower(list_.tokens[at_].value);
      if (type == "not" || type == "only") {
        query.negated = type == "not";
        ++at_;
        skip_whitespace();
        if (!is(TokenType::kIdent)) return std::nullopt;
        type = ascii_lower(list_.tokens[at_].value);
      }
      if (type == "not" || type == "and" || type == "or" || type == "only" || type == "layer")
        return std::nullopt;
      ++at_;
      query.type_matches = type == "all" || type == "screen";  // section 2.3; the others match nothing
      skip_whitespace();
      if (at_end()) return query;
      if (!peek_ident("and")) return std::nullopt;
      ++at_;
      std::optional<MediaCondition> condition = parse_condition(false, 0);
      if (!condition || !at_end()) return std::nullopt;
      query.condition = std::move(condition);
      return query;
    }
    std::optional<MediaCondition> condition = parse_condition(true, 0);
    if (!condition || !at_end()) return std::nullopt;
    query.condition = std::move(condition);
    return query;
  }

 private:
  bool is(TokenType type) const { return at_ < end_ && list_.tokens[at_].type == type; }
  void skip_whitespace() {
    while (is(TokenType::kWhitespace)) ++at_;
  }
  bool at_end() {
    skip_whitespace();
    return at_ >= end_;
  }
  bool peek_ident(std::string_view word) {
    skip_whitespace();
    return is(TokenType::kIdent) && ascii_lower(list_.tokens[at_].value) == word;
  }
  bool next_is_paren() {
    std::size_t i = at_ + 1;
    while (i < end_ && list_.tokens[i].type == TokenType::kWhitespace) ++i;
    return i < end_ &&
           (list_.tokens[i].type == TokenType::kOpenParen || list_.tokens[i].type == TokenType::kFunction);
  }

  // <media-condition> (allow_or) or <media-condition-without-or>.
  std::optional<MediaCondition> parse_condition(bool allow_or, int depth) {
    if (depth > kMaxMediaConditionDepth) return std::nullopt;
    skip_whitespace();
    if (peek_ident("not")) {
      ++at_;
      std::optional<MediaCondition> operand = in_parens(depth);
      if (!operand) return std::nullopt;
      MediaCondition condition;
      condition.kind = MediaCondition::Kind::kNot;
      condition.children.push_back(std::move(*operand));
      return condition;
    }
    std::optional<MediaCondition> first = in_parens(depth);
    if (!first) return std::nullopt;
    MediaCondition combined;
    combined.children.push_back(std::move(*first));
    for (;;) {
      skip_whitespace();
      const bool is_and = peek_ident("and"), is_or = peek_ident("or");
      if (!is_and && !is_or) break;
      const MediaCondition::Kind kind = is_and ? MediaCondition::Kind::kAnd : MediaCondition::Kind::kOr;
      if ((is_or && !allow_or) || (combined.children.size() > 1 && combined.kind != kind))
        return std::nullopt;
      combined.kind = kind;
      ++at_;
      std::optional<MediaCondition> next = in_parens(depth);
      if (!next) return std::nullopt;
      combined.children.push_back(std::move(*next));
    }
    if (combined.children.size() == 1) return std::move(combined.children.front());
    return combined;
  }

  // <media-in-parens>: ( <media-condition> ) | ( <media-feature> ) | <general-enclosed>.
  std::optional<MediaCondition> in_parens(int depth) {
    skip_whitespace();
    if (is(TokenType::kFunction)) {  // general-enclosed: unknown
      at_ = skip_component_value(list_, at_, end_);
      return MediaCondition{};
    }
    if (!is(TokenType::kOpenParen)) return std::nullopt;
    const std::size_t open = at_;
    const std::size_t after = skip_component_value(list_, open, end_);
    const std::size_t close = after - 1;  // the ')' (or the last token when the block is unclosed)
    const std::size_t inner_end = list_.tokens[close].type == TokenType::kCloseParen ? close : after;
    at_ = after;
    QueryParser inner(list_, open + 1, inner_end, unsupported_);
    if (std::optional<MediaCondition> condition = inner.parse_condition(true, depth + 1);
        condition && inner.at_end())
      return condition;
    QueryParser feature(list_, open + 1, inner_end, unsupported_);
    if (std::optional<MediaFeatureTest> test = feature.parse_feature()) {
      MediaCondition condition;
      condition.kind = MediaCondition::Kind::kFeature;
      condition.feature = std::move(*test);
      return condition;
    }
    return MediaCondition{};  // general-enclosed: unknown
  }

  std::optional<Value> value() {
    skip_whitespace();
    if (at_ >= end_) return std::nullopt;
    const Token& token = list_.tokens[at_];
    Value result;
    if (token.type == TokenType::kIdent) {
      result.kind = Value::Kind::kIdent;
      result.ident = ascii_lower(token.value);
      ++at_;
      return result;
    }
    if (token.type == TokenType::kDimension) {
      const std::string unit = ascii_lower(token.value);
      ++at_;
      if (const std::optional<double> factor = px_per_unit(unit)) {
        result.kind = Value::Kind::kLength;
        result.number = token.number * *factor;
        return result;
      }
      result.kind = Value::Kind::kResolution;
      if (unit == "dppx" || unit == "x") {
        result.number = token.number;
      } else if (unit == "dpi") {
        result.number = token.number / 96.0;
      } else if (unit == "dpcm") {
        result.number = token.number * 2.54 / 96.0;
      } else {
        return std::nullopt;
      }
      return result;
    }
    if (token.type != TokenType::kNumber) return std::nullopt;
    ++at_;
    result.number = token.number;
    // A ratio: <number> / <number> (section 4.2.3).
    const std::size_t saved = at_;
    skip_whitespace();
    if (is(TokenType::kDelim) && list_.tokens[at_].value == "/") {
      ++at_;
      skip_whitespace();
      if (!is(TokenType::kNumber)) return std::nullopt;
      const double denominator = list_.tokens[at_].number;
      ++at_;
      result.kind = Value::Kind::kRatio;
      // 0/0 is degenerate: infinite here, compared as such (section 4.2.3 makes it +inf too).
      result.number = denominator == 0.0 ? HUGE_VAL : result.number / denominator;
      return result;
    }
    at_ = saved;
    return result;
  }

  // '<', '<=', '>', '>=' or '='.
  std::optional<Comparison::Op> comparison() {
    skip_whitespace();
    if (!is(TokenType::kDelim)) return std::nullopt;
    const std::string& first = list_.tokens[at_].value;
    if (first == "=") {
      ++at_;
      return Comparison::Op::kEqual;
    }
    if (first != "<" && first != ">") return std::nullopt;
    ++at_;
    const bool equal = is(TokenType::kDelim) && list_.tokens[at_].value == "=";  // no space inside "<="
    if (equal) ++at_;
    if (first == "<") return equal ? Comparison::Op::kLessEqual : Comparison::Op::kLess;
    return equal ? Comparison::Op::kGreaterEqual : Comparison::Op::kGreater;
  }

  // Notes an unknown feature name; false for it.
  bool known(const std::string& name) {
    if (feature_type(name) != FeatureType::kUnknown) return true;
    unsupported_.insert(name);
    return false;
  }

  // <media-feature> (section 2.4), the whole of this parser's range; nullopt when it is none.
  std::optional<MediaFeatureTest> parse_feature() {
    skip_whitespace();
    MediaFeatureTest test;
    if (is(TokenType::kIdent)) {
      std::string name = ascii_lower(list_.tokens[at_].value);
      const std::size_t saved = at_;
      ++at_;
      if (at_end()) {  // (name): boolean context
        if (!known(name)) return std::nullopt;
        test.name = std::move(name);
        test.boolean = true;
        return test;
      }
      if (is(TokenType::kColon)) {  // (name: value), min- and max- for range features
        ++at_;
        std::optional<Value> query = value();
        if (!query || !at_end()) return std::nullopt;
        Comparison::Op op = Comparison::Op::kEqual;
        if (name.rfind("min-", 0) == 0 || name.rfind("max-", 0) == 0) {
          op = name[1] == 'i' ? Comparison::Op::kGreaterEqual : Comparison::Op::kLessEqual;
          name = name.substr(4);
          if (feature_type(name) == FeatureType::kDiscrete) return std::nullopt;
        }
        if (!known(name)) return std::nullopt;
        test.name = std::move(name);
        test.comparisons.push_back({op, std::move(*query)});
        return test;
      }
      at_ = saved;
    }
    // Ranges (section 2.4.4): name op value | value op name | value op name op value.
    if (is(TokenType::kIdent)) {
      std::string name = ascii_lower(list_.tokens[at_].value);
      ++at_;
      const std::optional<Comparison::Op> op = comparison();
      std::optional<Value> query = op ? value() : std::nullopt;
      if (!op || !query || !at_end()) return std::nullopt;
      if (!known(name) || feature_type(name) != FeatureType::kRange) return std::nullopt;
      test.name = std::move(name);
      test.comparisons.push_back({*op, std::move(*query)});
      return test;
    }
    std::optional<Value> low = value();
    const std::optional<Comparison::Op> first = low ? comparison() : std::nullopt;
    skip_whitespace();
    if (!first || !is(TokenType::kIdent)) return std::nullopt;
    std::string name = ascii_lower(list_.tokens[at_].value);
    ++at_;
    const Comparison::Op first_op = first.value_or(Comparison::Op::kEqual);
    test.comparisons.push_back({flipped(first_op), std::move(*low)});
    if (!at_end()) {
      const std::optional<Comparison::Op> second = comparison();
      std::optional<Value> high = second ? value() : std::nullopt;
      if (!second || !high || !at_end()) return std::nullopt;
      // Both bounds point the same way: a < name < b or a > name > b.
      const Comparison::Op second_op = second.value_or(Comparison::Op::kEqual);
      const bool less = first_op == Comparison::Op::kLess || first_op == Comparison::Op::kLessEqual;
      const bool less_too = second_op == Comparison::Op::kLess || second_op == Comparison::Op::kLessEqual;
      if (first_op == Comparison::Op::kEqual || second_op == Comparison::Op::kEqual || less != less_too)
        return std::nullopt;
      test.comparisons.push_back({second_op, std::move(*high)});
    }
    if (!known(name) || feature_type(name) != FeatureType::kRange) return std::nullopt;
    test.name = std::move(name);
    return test;
  }

  const TokenList& list_;
  std::size_t at_;
  std::size_t end_;
  std::set<std::string>& unsupported_;
};

}  // namespace

MediaQueryList::MediaQueryList() = default;
MediaQueryList::MediaQueryList(const MediaQueryList&) = default;
MediaQueryList::MediaQueryList(MediaQueryList&&) noexcept = default;
MediaQueryList& MediaQueryList::operator=(const MediaQueryList&) = default;
MediaQueryList& MediaQueryList::operator=(MediaQueryList&&) noexcept = default;
MediaQueryList::~MediaQueryList() = default;

MediaQueryList MediaQueryList::parse(const TokenList& list, std::size_t begin, std::size_t end,
                                     std::set<std::string>& unsupported) {
  MediaQueryList result;
  std::size_t first = begin;
  while (first < end && list.tokens[first].type == TokenType::kWhitespace) ++first;
  if (first >= end) return result;  // an empty list matches everything (section 3)
  // Each comma-separated query on its own: a malformed one is "not all" (section 3.2).
  std::size_t start = begin;
  for (std::size_t i = begin;;) {
    if (i >= end || list.tokens[i].type == TokenType::kComma) {
      QueryParser parser(list, start, i, unsupported);
      std::optional<Query> query = parser.query();
      if (!query) {
        query.emplace();
        query->malformed = true;
      }
      result.queries_.push_back(std::move(*query));
      if (i >= end) break;
      start = ++i;
      continue;
    }
    i = skip_component_value(list, i, end);
  }
  return result;
}

bool MediaQueryList::matches(const MediaFeatures& medium) const {
  if (queries_.empty()) return true;
  for (const Query& query : queries_) {
    if (query.malformed) continue;
    Truth result = query.type_matches ? Truth::kTrue : Truth::kFalse;
    if (result == Truth::kTrue && query.condition) result = evaluate(*query.condition, medium);
    // "not" negates the whole query; an unknown stays unknown, which is false (section 3.2).
    if (query.negated) result = negate(result);
    if (result == Truth::kTrue) return true;
  }
  return false;
}

}  // namespace curvescan::svg::css
