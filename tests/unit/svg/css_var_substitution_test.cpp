// var() substitution and the custom properties of one element (svg/css/var_substitution.h,
// svg/css/custom_properties.h), against CSS Custom Properties for Cascading Variables Module Level 1.
#include <catch2/catch.hpp>
#include <map>
#include <string>
#include <vector>

#include "svg/css/custom_properties.h"
#include "svg/css/var_substitution.h"

using namespace curvescan::svg::css;

namespace {

// A lookup over a fixed map.
CustomPropertyLookup lookup_in(const std::map<std::string, std::string, std::less<>>& values) {
  return [&values](std::string_view name) -> const std::string* {
    const auto found = values.find(name);
    return found == values.end() ? nullptr : &found->second;
  };
}

Substitution substitute(std::string_view value,
                        const std::map<std::string, std::string, std::less<>>& values) {
  SubstitutionBudget budget;
  return substitute_var(value, lookup_in(values), budget);
}

std::shared_ptr<const CustomProperties> compute(const std::shared_ptr<const CustomProperties>& parent,
                                                const std::vector<CustomDeclaration>& declarations,
                                                std::vector<std::string>* warnings = nullptr) {
  SubstitutionBudget budget;
  std::vector<std::string> ignored;
  return compute_custom_properties(parent, declarations, budget, warnings ? *warnings : ignored);
}

std::string value_of(const std::shared_ptr<const CustomProperties>& set, std::string_view name) {
  const std::string* value = set ? set->find(name) : nullptr;
  return value ? *value : "<guaranteed-invalid>";
}

}  // namespace

TEST_CASE("var(): a reference, a fallback, a nested fallback, in any function and any case (section 3)") {
  const std::map<std::string, std::string, std::less<>> values{
      {"--c", "#00f"}, {"--r", "255"}, {"--Big", "x"}};
  CHECK(substitute("var(--c)", values).value == "#00f");
  CHECK(substitute("VAR( --c )", values).value == "#00f");  // function names are ASCII case-insensitive
  CHECK(substitute("var(--missing, red)", values).value == "red");
  CHECK(substitute("var(--missing, var(--c))", values).value == "#00f");
  CHECK(substitute("var(--missing, var(--also-missing, lime))", values).value == "lime");
  CHECK(substitute("rgb(var(--r), 0, 0)", values).value == "rgb(255, 0, 0)");
  CHECK(substitute("url(#g) var(--c)", values).value == "url(#g) #00f");
  CHECK(substitute("var(--c, this fallback is not used)", values).value == "#00f");
  // Names are case-sensitive (section 2): --big is not --Big.
  CHECK(substitute("var(--Big)", values).value == "x");
  CHECK(substitute("var(--big, y)", values).value == "y");
  // An empty fallback is a valid one: the value becomes empty (which a property's grammar then refuses).
  CHECK(substitute("var(--missing,)", values).value == "");
}

TEST_CASE("var(): a missing value without fallback, and malformed var(), fail") {
  const std::map<std::string, std::string, std::less<>> values{{"--c", "#00f"}};
  const Substitution missing = substitute("var(--missing)", values);
  CHECK_FALSE(missing.value);
  CHECK(missing.failure == SubstitutionFailure::kNoValue);
  CHECK(missing.missing == "--missing");
  CHECK(describe(missing) == "var(--missing) has no value and no fallback");
  // A missing value inside a fallback fails the whole value.
  CHECK_FALSE(substitute("var(--missing, var(--other))", values).value);
  for (const char* malformed : {"var()", "var(c)", "var(--c --d)", "var(--)", "var(1)", "var(--c;)"}) {
    INFO(malformed);
    CHECK(substitute(malformed, values).failure == SubstitutionFailure::kMalformed);
  }
}

TEST_CASE("var(): the substitution is on tokens -- a value never joins the token next to it") {
  const std::map<std::string, std::string, std::less<>> values{{"--n", "10"}, {"--u", "px"}};
  // 10 followed by px is the number 10 and the identifier px: a space keeps them two tokens, and the
  // length grammar then refuses them, as browsers do.
  CHECK(substitute("var(--n)px", values).value == "10 px");
  CHECK(substitute("var(--n)var(--u)", values).value == "10 px");
  CHECK(substitute("var(--n) var(--u)", values).value == "10 px");
  // Punctuation does not join: no space is added.
  CHECK(substitute("(var(--n))", values).value == "(10)");
}

TEST_CASE("var(): fallbacks nested past the bound are refused, not recursed into") {
  std::string value = "red";
  for (int i = 0; i < kMaxVarNesting + 8; ++i) value = "var(--x, " + value + ")";
  CHECK(substitute(value, {}).failure == SubstitutionFailure::kMalformed);
  std::string shallow = "red";
  for (int i = 0; i < kMaxVarNesting; ++i) shallow = "var(--x, " + shallow + ")";
  CHECK(substitute(shallow, {}).value == "red");
}

TEST_CASE("var(): values past the length bound and substitutions past the document budget fail") {
  const std::map<std::string, std::string, std::less<>> values{
      {"--big", std::string(kMaxSubstitutedValueBytes / 2 + 1, 'a')}};
  CHECK(substitute("var(--big)", values).value);
  CHECK(substitute("var(--big) var(--big)", values).failure == SubstitutionFailure::kTooLong);
  SubstitutionBudget budget{10};
  const std::map<std::string, std::string, std::less<>> small{{"--s", "123456"}};
  CHECK(substitute_var("var(--s)", lookup_in(small), budget).value == "123456");
  CHECK(budget.remaining == 4);
  CHECK(substitute_var("var(--s)", lookup_in(small), budget).failure == SubstitutionFailure::kBudget);
}

TEST_CASE("var(): the references of a value, fallbacks included (the edges of section 2.3)") {
  CHECK(var_references("var(--a) var(--b, var(--c)) rgb(var(--a))") ==
        std::vector<std::string>{"--a", "--b", "--c", "--a"});
  CHECK(var_references("red").empty());
  CHECK(is_custom_property_name("--x"));
  CHECK_FALSE(is_custom_property_name("--"));
  CHECK_FALSE(is_custom_property_name("-x"));
  CHECK(contains_var("fill: Var(--x)"));
  CHECK_FALSE(contains_var("variant(x)"));
}

TEST_CASE("custom properties: inherited, overridden, the CSS-wide keywords (sections 2 and 2.2)") {
  const auto root = compute(nullptr, {{"--a", "red"}, {"--b", "1px"}, {"--a", "blue"}});  // the last wins
  CHECK(value_of(root, "--a") == "blue");
  CHECK(value_of(root, "--b") == "1px");
  // A child inherits everything; `initial` is the guaranteed-invalid value; `inherit`/`unset` keep the
  // parent's; an empty value is valid (and not the guaranteed-invalid value).
  const auto child =
      compute(root, {{"--a", "initial"}, {"--b", "UNSET"}, {"--c", ""}, {"--d", "var(--b) solid"}});
  CHECK(value_of(child, "--a") == "<guaranteed-invalid>");
  CHECK(value_of(child, "--b") == "1px");
  CHECK(value_of(child, "--c") == "");
  CHECK(value_of(child, "--d") == "1px solid");
  CHECK(value_of(root, "--a") == "blue");  // the parent's set is unchanged
  // An element that declares nothing new shares its parent's set.
  CHECK(compute(root, {}) != nullptr);
}

TEST_CASE("custom properties: references resolve in dependency order, not declaration order") {
  const auto set = compute(nullptr, {{"--a", "var(--b) var(--b)"}, {"--b", "var(--c)"}, {"--c", "x"}});
  CHECK(value_of(set, "--a") == "x x");
  CHECK(value_of(set, "--b") == "x");
  // A reference to the element's own value of a name, not the parent's, where the element declares it.
  const auto parent = compute(nullptr, {{"--c", "parent"}});
  const auto child = compute(parent, {{"--a", "var(--c)"}, {"--c", "child"}});
  CHECK(value_of(child, "--a") == "child");
}

TEST_CASE("custom properties: a cycle makes every property in it guaranteed-invalid (section 2.3)") {
  std::vector<std::string> warnings;
  // The Web Platform Tests' case (variables-substitute-guaranteed-invalid): the parent's values do not
  // come back through a cycle or through a reference to one.
  const auto parent = compute(nullptr, {{"--var3", "inherited"}, {"--var4", "inherited"}});
  const auto set = compute(parent,
                           {{"--var1", "var(--var2)"},
                            {"--var2", "var(--var1)"},
                            {"--var3", "var(--var1)"},
                            {"--var4", "var(--noexist)"},
                            {"--ok", "var(--var1, fine)"}},
                           &warnings);
  CHECK(value_of(set, "--var1") == "<guaranteed-invalid>");
  CHECK(value_of(set, "--var2") == "<guaranteed-invalid>");
  CHECK(value_of(set, "--var3") == "<guaranteed-invalid>");
  CHECK(value_of(set, "--var4") == "<guaranteed-invalid>");
  CHECK(value_of(set, "--ok") == "fine");  // outside the cycle: its fallback applies
  CHECK(warnings.size() == 4);
  // A property in a cycle only through a fallback is in the cycle all the same (edges include
  // fallbacks), and so is one that a depth-first walk reaches through a finished node: r -> a, r -> b,
  // a -> r, b -> a makes one component of three.
  const auto self = compute(nullptr, {{"--s", "var(--t, var(--s, x))"}, {"--t", "y"}});
  CHECK(value_of(self, "--s") == "<guaranteed-invalid>");
  const auto cross =
      compute(nullptr, {{"--r", "var(--a) var(--b)"}, {"--a", "var(--r)"}, {"--b", "var(--a, z)"}});
  CHECK(value_of(cross, "--r") == "<guaranteed-invalid>");
  CHECK(value_of(cross, "--a") == "<guaranteed-invalid>");
  CHECK(value_of(cross, "--b") == "<guaranteed-invalid>");
}

TEST_CASE("custom properties: a chain of 100 000 references is resolved without recursion") {
  std::vector<std::string> names, values;
  constexpr int kLength = 100000;
  for (int i = 0; i < kLength; ++i) {
    names.push_back("--p" + std::to_string(i));
    values.push_back(i + 1 < kLength ? "var(--p" + std::to_string(i + 1) + ")" : "end");
  }
  std::vector<CustomDeclaration> declarations;
  for (int i = 0; i < kLength; ++i) declarations.push_back({names[i], values[i]});
  std::vector<std::string> warnings;
  const auto set = compute(nullptr, declarations, &warnings);
  // The set holds at most kMaxCustomProperties names: the first resolved, from the chain's end, each with
  // the chain's last value; the rest are dropped with one warning.
  REQUIRE(set);
  CHECK(set->size() == kMaxCustomProperties);
  CHECK(value_of(set, "--p" + std::to_string(kLength - kMaxCustomProperties)) == "end");
  CHECK(value_of(set, "--p0") == "<guaranteed-invalid>");
  CHECK(warnings.size() == 1);
}

TEST_CASE("custom properties: billion laughs through variables is refused with a warning") {
  // --l0: lol; --l1: var(--l0) var(--l0); ... 30 levels would be 2^30 x 4 bytes. Each value is capped at
  // kMaxSubstitutedValueBytes, so the levels past the cap are guaranteed-invalid, and the work is bounded.
  std::vector<std::string> names, values;
  for (int i = 0; i <= 30; ++i) {
    names.push_back("--l" + std::to_string(i));
    values.push_back(i == 0 ? "lol"
                            : "var(--l" + std::to_string(i - 1) + ") var(--l" + std::to_string(i - 1) + ")");
  }
  std::vector<CustomDeclaration> declarations;
  for (std::size_t i = 0; i < names.size(); ++i) declarations.push_back({names[i], values[i]});
  std::vector<std::string> warnings;
  const auto set = compute(nullptr, declarations, &warnings);
  CHECK(value_of(set, "--l1") == "lol lol");
  // --ln is 2^(n+2) - 1 bytes long: --l18 is 1 MiB less one byte, --l19 2 MiB less one.
  CHECK(set->find("--l18") != nullptr);
  CHECK(set->find("--l18")->size() == kMaxSubstitutedValueBytes - 1);
  CHECK(set->find("--l19") == nullptr);
  CHECK(set->find("--l30") == nullptr);
  REQUIRE(!warnings.empty());
  CHECK(warnings.front().find("longer than 1048576 bytes") != std::string::npos);
}
