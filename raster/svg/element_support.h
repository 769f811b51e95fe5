// What this reader does with each element of the SVG namespace: render it, read it only through a
// reference (non-rendering elements, SVG 1.1 section 1.6), or report it as unsupported -- never drop it
// silently (docs/svg.md lists the supported set).
#pragma once

#include <string_view>

namespace curvescan::svg::detail {

enum class ElementSupport {
  kRendered,      ///< drawn where it appears in the tree (shapes, groups, text, use, ...)
  kNonRendering,  ///< drawn only when referenced (defs, gradients, clipPath, mask, ...) or metadata
  kUnsupported,   ///< an SVG element this reader does not implement: a warning, once per kind
  kUnknown,       ///< not an SVG element name: not drawn, nor its content (SVG 2), with a warning
};

[[nodiscard]] ElementSupport element_support(std::string_view local_name) noexcept;

}  // namespace curvescan::svg::detail
