// var() substitution (CSS Custom Properties for Cascading Variables Module Level 1, section 3).
//
// A value that contains var() is valid at parse time whatever else it holds (section 3): what it means is
// known only when the element's custom properties are, at computed-value time. substitute_var then
// replaces each `var(--name)` / `var(--name, fallback)` by the custom property's value, or else by its
// fallback (whose own var() functions are substituted too), and the property's own grammar parses the
// result. A reference to a custom property without a value (the guaranteed-invalid value, section 2.2)
// and without a fallback makes the whole value invalid at computed-value time (section 3.1).
//
// The substitution is made on the token stream (section 3, "substitute a var()"): the tokens around a
// var() stay as they are, and where a substituted value would join the token before or after it into
// one ("var(--n)px" with --n: 10 is the number 10 and the identifier px, not the dimension 10px), a space
// keeps them apart.
//
// Bounds (docs/limits.md; section 2.4.1 lets an implementation treat an over-long value as invalid):
// substituted values longer than kMaxSubstitutedValueBytes are invalid, fallbacks nest at most
// kMaxVarNesting deep, and a SubstitutionBudget shared by the whole document caps the bytes all
// substitutions produce, so that "billion laughs" through variables (`--a: var(--b) var(--b)` over 30
// levels) costs at most linear time and memory.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace curvescan::svg::css {

/// A value after substitution longer than this (1 MiB) is invalid at computed-value time.
inline constexpr std::size_t kMaxSubstitutedValueBytes = std::size_t{1} << 20;
/// Bytes all var() substitutions of one document may produce (64 MiB); past that, every var() is invalid.
inline constexpr std::size_t kMaxDocumentSubstitutionBytes = std::size_t{64} << 20;
/// var() functions nested in fallbacks deeper than this make the value invalid.
inline constexpr int kMaxVarNesting = 32;

/// Whether `name` is a custom property name: "--" and at least one more code point (section 2; "--"
/// alone is reserved).
[[nodiscard]] bool is_custom_property_name(std::string_view name) noexcept;

/// Whether `value` holds a var() function (ASCII case-insensitive, as function names are). A cheap test
/// on the text, made before anything is tokenized: a value without "var(" has nothing to substitute.
[[nodiscard]] bool contains_var(std::string_view value) noexcept;

/// The bytes substitutions may still produce in one document.
struct SubstitutionBudget {
  std::size_t remaining = kMaxDocumentSubstitutionBytes;
};

/// Why a substitution failed.
enum class SubstitutionFailure {
  kNone,
  kMalformed,  ///< a var() that is not `var(<custom-property-name> [, <fallback>]?)`, or nested too deep
  kNoValue,    ///< a reference to a custom property without a value, and no fallback
  kTooLong,    ///< the result would pass kMaxSubstitutedValueBytes
  kBudget,     ///< the document's SubstitutionBudget is spent
};

struct Substitution {
  std::optional<std::string> value;  ///< the value with every var() replaced; nullopt when it failed
  SubstitutionFailure failure = SubstitutionFailure::kNone;
  std::string missing;  ///< kNoValue: the name of the custom property without a value
};

/// The value of a custom property, or null when it has none (the guaranteed-invalid value).
using CustomPropertyLookup = std::function<const std::string*(std::string_view name)>;

/// `value` with its var() functions substituted from `lookup` (see the top of this file). The bytes
/// produced are charged to `budget`.
[[nodiscard]] Substitution substitute_var(std::string_view value, const CustomPropertyLookup& lookup,
                                          SubstitutionBudget& budget);

/// The custom property names `value` references through var(), fallbacks included, in order (repeats
/// kept): the edges of the dependency graph of section 2.3.
[[nodiscard]] std::vector<std::string> var_references(std::string_view value);

/// A user-readable reason for a failure ("var(--x) has no value and no fallback").
[[nodiscard]] std::string describe(const Substitution& failed);

}  // namespace curvescan::svg::css
