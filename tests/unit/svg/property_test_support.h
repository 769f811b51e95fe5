// One declaration applied through the cascade's property table, as the property tests of the text and font
// rows use it: a fixed 100 × 100 viewport at 96 dpi, no font metrics.
#pragma once

#include <string_view>

#include "svg/computed_style.h"

namespace curvescan::svg::testing {

/// Applies `name: value` to `style` with `parent` as the parent's computed style; true when it was valid
/// (the property table gave no warning).
inline bool apply_declaration(detail::ComputedStyle& style, const detail::ComputedStyle& parent,
                              std::string_view name, std::string_view value) {
  const detail::ResolveContext context{100.0, 100.0, {96.0, 96.0}, nullptr};
  detail::Diagnostics diagnostics;
  detail::apply_property(style, parent, name, value, context, diagnostics);
  return diagnostics.warnings.empty();
}

/// The same for the font variant properties alone: `variants` as the element's, `parent` as its parent's.
inline bool apply_declaration(detail::FontVariants& variants, const detail::FontVariants& parent,
                              std::string_view name, std::string_view value) {
  detail::ComputedStyle style;
  style.text.font_variants = variants;
  detail::ComputedStyle parent_style;
  parent_style.text.font_variants = parent;
  const bool valid = apply_declaration(style, parent_style, name, value);
  variants = style.text.font_variants;
  return valid;
}

}  // namespace curvescan::svg::testing
