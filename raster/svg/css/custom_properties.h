// Custom properties (CSS Custom Properties for Cascading Variables Module Level 1, section 2): the
// `--name: <any tokens>` declarations of style sheets and style attributes, cascaded like any property and
// inherited by every descendant.
//
// An element's custom properties are its parent's, overridden by the ones it declares (the winning
// declaration of each name, as the cascade orders them). Their computed values have var() substituted
// (section 2, "Computed value: specified value with variables substituted"), so inherited values never
// hold var() again. The steps of compute_custom_properties for one element:
//   1. the CSS-wide keywords: `initial` is the guaranteed-invalid value (no value, section 2.2);
//      `inherit`, `unset` and `revert` keep the parent's value (custom properties are inherited);
//   2. the dependency graph of the declared values that hold var() (section 2.3, fallbacks included):
//      every property in a cycle is invalid at computed-value time, which for a custom property is the
//      guaranteed-invalid value (as browsers and the Web Platform Tests have it);
//   3. the others are substituted in dependency order; one that fails (a reference without a value and
//      without a fallback, a value too long) is the guaranteed-invalid value too.
// The dependency graph is walked with Tarjan's strongly connected components algorithm (R. Tarjan, "Depth-
// first search and linear graph algorithms", SIAM J. Comput. 1972), iteratively: the length of a chain of
// references is the input's to choose.
//
// A set is immutable and shared: an element that declares no custom property shares its parent's.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "var_substitution.h"

namespace curvescan::svg::css {

/// Custom properties with a value in one element's set (1024); declarations of more names are dropped with
/// a warning. Bounds the cost of the copy an element that declares one makes of its parent's set.
inline constexpr std::size_t kMaxCustomProperties = 1024;

/// The computed custom properties of one element: the names with a value, sorted.
class CustomProperties {
 public:
  struct Entry {
    std::string name;
    std::string value;
  };

  /// The value of `name`, or null (the guaranteed-invalid value).
  [[nodiscard]] const std::string* find(std::string_view name) const noexcept;
  [[nodiscard]] std::size_t size() const noexcept { return entries_.size(); }
  [[nodiscard]] bool empty() const noexcept { return entries_.empty(); }

 private:
  friend class CustomPropertiesBuilder;
  std::vector<std::shared_ptr<const Entry>> entries_;  // by name; shared between the sets of a subtree
};

/// A declaration of a custom property, as the cascade orders them (lowest precedence first).
struct CustomDeclaration {
  std::string_view name;
  std::string_view value;
};

/// The custom properties of an element whose parent's are `parent` (null: none) and that declares
/// `declarations`. Problems (cycles, failed substitutions, the limit) are appended to `warnings`, one line
/// each. Returns `parent` itself when the declarations change nothing.
[[nodiscard]] std::shared_ptr<const CustomProperties> compute_custom_properties(
    const std::shared_ptr<const CustomProperties>& parent, const std::vector<CustomDeclaration>& declarations,
    SubstitutionBudget& budget, std::vector<std::string>& warnings);

}  // namespace curvescan::svg::css
