// The cascade of one element (CSS Cascade 4 section 6; SVG 2 section 6.3 "Styling" and 6.6
// "Presentation attributes"): which declaration of each property wins, applied over the parent's
// inherited values by apply_property (computed_style.h).
//
// Precedence, lowest first:
//   1. presentation attributes (they count as author rules of specificity 0 placed before every style
//      sheet, SVG 2 6.6);
//   2. normal declarations of the author style sheets (<style> elements, then the caller's sheet), by
//      specificity, then source order;
//   3. normal declarations of the style attribute (CSS Style Attributes 3: more specific than any
//      selector);
//   4. !important declarations of the style sheets, by specificity, then source order;
//   5. !important declarations of the style attribute.
// Custom properties (`--name: ...`, CSS Variables 1) are cascaded first, in the same order, and inherited
// (css/custom_properties.h). Then every other declaration is applied in that order, font-size and font
// first because em lengths of the other properties depend on them. An invalid value is ignored with a
// warning (apply_property) and leaves the value of the declaration below it in place: CSS drops invalid
// declarations at parse time (CSS Syntax 3 5.4.6, CSS Cascade 4 4.1), so the next valid one down wins.
// A value with var() is different: valid at parse time whatever it holds, it is substituted here (the
// computed-value time of CSS Variables 1, section 3; css/var_substitution.h) and the property's grammar
// parses the result; when the substitution fails or the result is invalid, the property is unset
// (section 3.1: the inherited value, or the initial one), not the declaration below. Presentation
// attributes are substituted too (SVG 2 parses them with the property's CSS grammar; Firefox, WebKit and
// Chrome substitute `fill="var(--c)"`). The property parsers refuse what their grammar does not allow;
// the CSS-wide keywords inherit, initial and unset work for every property. See docs/svg.md.
#pragma once

#include <functional>
#include <optional>
#include <pugixml.hpp>
#include <string>
#include <string_view>

#include "computed_style.h"

namespace curvescan::svg::detail {

/// The computed style of `node`: `parent` (its inherited properties) with the cascaded declarations
/// applied. `context.style_sheets` may be null (no sheets).
[[nodiscard]] ComputedStyle cascade_style(const pugi::xml_node& node, const ComputedStyle& parent,
                                          const ResolveContext& context, Diagnostics& diagnostics);

/// Whether a value is valid for a property's grammar (declared_value skips the ones that are not).
using ValueCheck = std::function<bool(std::string_view)>;

/// The value of property `name` declared for `node` by a style sheet or its style attribute (the same
/// precedence), or nullopt. For properties that are attributes outside the property table, such as
/// SVG 2's `transform` (section 8.5: the attribute is the presentation attribute of the CSS property).
/// With `valid`, the highest declaration that it accepts: an invalid one falls back to the next.
/// A value with var() is substituted with the custom properties along the document tree (not through a
/// <use>, whose content inherits from it: only cascade_style follows that); when the substitution fails
/// or `valid` refuses its result, the value is "unset" (CSS Variables 1, 3.1), and the next declaration
/// applies only when `valid` refuses "unset" too.
[[nodiscard]] std::optional<std::string> declared_value(const pugi::xml_node& node, std::string_view name,
                                                        const css::StyleSheets* sheets,
                                                        const ValueCheck& valid = {});

/// The cascaded value of property `name` on `node` (the same precedence, then the presentation
/// attribute), or nullopt when nothing valid sets it.
[[nodiscard]] std::optional<std::string> cascaded_value(const pugi::xml_node& node, std::string_view name,
                                                        const css::StyleSheets* sheets,
                                                        const ValueCheck& valid = {});

}  // namespace curvescan::svg::detail
