// var() substitution (var_substitution.h). Section numbers refer to CSS Custom Properties for Cascading
// Variables Module Level 1.
#include "var_substitution.h"

#include "syntax.h"
#include "tokenizer.h"

namespace curvescan::svg::css {
namespace {

// Characters that can continue an identifier, a number or a dimension: a substituted value that starts
// or ends with one must not touch another such character across the var() boundary, or the two tokens
// would read as one (section 3: the substitution is on tokens, not text).
bool joins(char c) noexcept {
  const auto u = static_cast<unsigned char>(c);
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
         c == '.' || c == '%' || c == '\\' || c == '#' || c == '+' || u >= 0x80;
}

bool is_whitespace(const TokenList& list, std::size_t i) {
  return list.tokens[i].type == TokenType::kWhitespace;
}

// One var() parsed: the name, and the fallback's token range when there is a comma.
struct VarFunction {
  std::string name;
  bool has_fallback = false;
  std::size_t fallback_begin = 0, fallback_end = 0;
};

// The var() whose arguments are tokens [begin, end) (between "var(" and ")"), or nullopt when they are
// not `<custom-property-name> [, <declaration-value>?]?` (section 3).
std::optional<VarFunction> parse_var(const TokenList& list, std::size_t begin, std::size_t end) {
  std::size_t i = begin;
  while (i < end && is_whitespace(list, i)) ++i;
  if (i == end || list.tokens[i].type != TokenType::kIdent || !is_custom_property_name(list.tokens[i].value))
    return std::nullopt;
  VarFunction function;
  function.name = list.tokens[i++].value;
  while (i < end && is_whitespace(list, i)) ++i;
  if (i == end) return function;
  if (list.tokens[i].type != TokenType::kComma) return std::nullopt;
  ++i;
  // The fallback, trimmed of whitespace (the value of a declaration is, CSS Syntax 3 5.4.6).
  std::size_t last = end;
  while (i < last && is_whitespace(list, i)) ++i;
  while (last > i && is_whitespace(list, last - 1)) --last;
  function.has_fallback = true;
  function.fallback_begin = i;
  function.fallback_end = last;
  return function;
}

class Substituter {
 public:
  Substituter(const TokenList& list, const CustomPropertyLookup& lookup, SubstitutionBudget& budget)
      : list_(list), lookup_(lookup), budget_(budget) {}

  // Appends tokens [begin, end) to `out`, var() functions substituted; false on failure (failure_ says
  // why). Fallbacks recurse, at most kMaxVarNesting deep.
  bool substitute(std::size_t begin, std::size_t end, int depth, std::string& out) {
    if (depth > kMaxVarNesting) return fail(SubstitutionFailure::kMalformed);
    std::size_t run = begin;  // the start of the tokens copied as they are
    for (std::size_t i = begin; i < end;) {
      const Token& token = list_.tokens[i];
      if (token.type != TokenType::kFunction || !ascii_equal_ignoring_case(token.value, "var")) {
        ++i;
        continue;
      }
      if (!append(out, serialize_tokens(list_, run, i), false)) return false;
      const std::size_t after = skip_component_value(list_, i, end);
      // An unclosed var() at the end of the value is closed by the end (CSS Syntax 3 5.4.9).
      const std::size_t close =
          list_.tokens[after - 1].type == TokenType::kCloseParen && after - 1 > i ? after - 1 : after;
      const std::optional<VarFunction> function = parse_var(list_, i + 1, close);
      if (!function) return fail(SubstitutionFailure::kMalformed);
      if (const std::string* value = lookup_(function->name)) {
        if (!append(out, *value, true)) return false;
      } else if (function->has_fallback) {
        std::string fallback;
        if (!substitute(function->fallback_begin, function->fallback_end, depth + 1, fallback)) return false;
        if (!append(out, fallback, true)) return false;
      } else {
        missing_ = function->name;
        return fail(SubstitutionFailure::kNoValue);
      }
      i = after;
      run = after;
    }
    return append(out, serialize_tokens(list_, run, end), false);
  }

  SubstitutionFailure failure() const { return failure_; }
  const std::string& missing() const { return missing_; }

 private:
  bool fail(SubstitutionFailure failure) {
    failure_ = failure;
    return false;
  }

  // Appends `piece`, keeping it apart from the text before with a space where the two would join into one
  // token. Every boundary between pieces is a var() boundary. Substituted pieces are charged to the budget.
  bool append(std::string& out, std::string_view piece, bool substituted) {
    if (piece.empty()) return true;
    const bool space = !out.empty() && joins(out.back()) && joins(piece.front());
    const std::size_t size = piece.size() + (space ? 1 : 0);
    if (out.size() + size > kMaxSubstitutedValueBytes) return fail(SubstitutionFailure::kTooLong);
    if (substituted) {
      if (size > budget_.remaining) return fail(SubstitutionFailure::kBudget);
      budget_.remaining -= size;
    }
    if (space) out += ' ';
    out += piece;
    return true;
  }

  const TokenList& list_;
  const CustomPropertyLookup& lookup_;
  SubstitutionBudget& budget_;
  SubstitutionFailure failure_ = SubstitutionFailure::kNone;
  std::string missing_;
};

}  // namespace

bool is_custom_property_name(std::string_view name) noexcept {
  return name.size() > 2 && name[0] == '-' && name[1] == '-';
}

bool contains_var(std::string_view value) noexcept {
  for (std::size_t i = 0; i + 4 <= value.size(); ++i) {
    if (value[i + 3] == '(' && ascii_equal_ignoring_case(value.substr(i, 3), "var")) return true;
  }
  return false;
}

Substitution substitute_var(std::string_view value, const CustomPropertyLookup& lookup,
                            SubstitutionBudget& budget) {
  // The value's tokens: it came from a declaration, whose tokens the style sheet's limits bounded already.
  const TokenList list = tokenize(value);
  Substituter substituter(list, lookup, budget);
  Substitution result;
  std::string out;
  if (substituter.substitute(0, list.tokens.size(), 0, out)) {
    result.value = std::move(out);
  } else {
    result.failure = substituter.failure();
    result.missing = substituter.missing();
  }
  return result;
}

std::vector<std::string> var_references(std::string_view value) {
  std::vector<std::string> names;
  if (!contains_var(value)) return names;
  const TokenList list = tokenize(value);
  // Every var( followed by a custom property name, at any depth: fallbacks and other functions are read
  // token by token, so no recursion is needed.
  for (std::size_t i = 0; i + 1 < list.tokens.size(); ++i) {
    const Token& token = list.tokens[i];
    if (token.type != TokenType::kFunction || !ascii_equal_ignoring_case(token.value, "var")) continue;
    std::size_t k = i + 1;
    while (k < list.tokens.size() && is_whitespace(list, k)) ++k;
    if (k < list.tokens.size() && list.tokens[k].type == TokenType::kIdent &&
        is_custom_property_name(list.tokens[k].value))
      names.push_back(list.tokens[k].value);
  }
  return names;
}

std::string describe(const Substitution& failed) {
  switch (failed.failure) {
    case SubstitutionFailure::kNone:
      return "substituted";
    case SubstitutionFailure::kMalformed:
      return "a malformed var() (var(--name) or var(--name, fallback), fallbacks nested at most " +
             std::to_string(kMaxVarNesting) + " deep)";
    case SubstitutionFailure::kNoValue:
      return "var(" + failed.missing + ") has no value and no fallback";
    case SubstitutionFailure::kTooLong:
      return "the value after var() substitution is longer than " +
             std::to_string(kMaxSubstitutedValueBytes) + " bytes";
    case SubstitutionFailure::kBudget:
      return "var() substitutions in this document produced more than " +
             std::to_string(kMaxDocumentSubstitutionBytes) + " bytes; no more are made";
  }
  return {};
}

}  // namespace curvescan::svg::css
