// The `style` attribute: a CSS declaration block (CSS 2.1 section 4.1.8; SVG 1.1 section 6.4).
//
//   style="fill: red; stroke-width:2px /* a comment */; opacity: .5 !important"
//
// The text is read by the CSS parser the <style> element uses (CSS Syntax Level 3, 5.3.8 "Parse a list
// of declarations"). Comments are removed, names are lower-cased (CSS property names are ASCII
// case-insensitive), values are trimmed and a trailing "!important" is dropped (the renderer's cascade
// keeps it; here the declarations are listed). A declaration without ':' or with an empty name or value
// is skipped, as CSS error handling requires (CSS Syntax 3, 5.4.6).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace curvescan::svg {

struct StyleDeclaration {
  std::string name;
  std::string value;
};

/// The declarations of a style attribute, in order (later ones win when the caller applies them in order).
[[nodiscard]] std::vector<StyleDeclaration> parse_style_attribute(std::string_view text);

}  // namespace curvescan::svg
