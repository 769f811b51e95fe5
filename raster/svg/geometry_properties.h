// The geometry properties of SVG 2 (section 10.2 "Geometry properties" of the Basic Shapes chapter and
// 9.4 "The 'd' property"): x, y, width, height, cx, cy, r, rx, ry and d are CSS properties whose
// presentation attributes are the attributes of the same name, so a style sheet or the style attribute
// may set them (`rect { width: 10px }`, `path { d: path("M0 0 L10 10") }`) and wins over the attribute.
// They are read for rect, circle, ellipse, path and image (nested svg, use and foreignObject keep
// their attributes).
//
// Each value comes from the cascade (cascade.h): the highest declaration that is valid for the
// property's grammar, else the attribute when it is valid, else nothing (the initial value: 0 for x, y,
// cx, cy, r; auto for width, height, rx, ry; none for d). An invalid value is reported once per element
// and property and falls back to the next one down, as CSS drops invalid declarations.
//
// Grammars (SVG 2 10.2, 10.4, 10.5): x, y, cx, cy are <length-percentage>; r is a non-negative one;
// width, height, rx and ry are `auto` or a non-negative one. Unitless numbers are user units in a style
// sheet too, as in SVG 1.1 (4.2 "<length>": the unit identifier is optional in SVG's own properties) and
// as rsvg-convert reads them. `d` is `none` or path(<string>) in CSS, path data in the attribute.
// The CSS-wide keywords, in declarations: initial and unset give the initial value (the properties are
// not inherited); inherit takes the parent element's value of the property. In an attribute they are
// invalid (x="inherit" is an error in SVG 1.1, where x is no property).
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string>
#include <string_view>

#include "computed_style.h"
#include "curvescan/svg/length.h"

namespace curvescan::svg::detail {

/// True for the ten geometry property names above.
[[nodiscard]] bool is_geometry_property(std::string_view name) noexcept;

/// The value of a length-valued geometry property of `node`: nullopt for the initial value and for
/// `auto`. Invalid values are reported through `diagnostics` and skipped.
[[nodiscard]] std::optional<Length> geometry_length(const pugi::xml_node& node, std::string_view name,
                                                    const css::StyleSheets* sheets, Diagnostics& diagnostics);

/// The path data of `node`'s `d` property: the string of a CSS path(), else the attribute's text; empty
/// for none.
[[nodiscard]] std::string geometry_path_data(const pugi::xml_node& node, const css::StyleSheets* sheets,
                                             Diagnostics& diagnostics);

/// The text of a CSS path(<string>) function, unescaped (CSS Syntax 3 4.3.5); nullopt when `value` is
/// not one.
[[nodiscard]] std::optional<std::string> css_path_function(std::string_view value);

}  // namespace curvescan::svg::detail
