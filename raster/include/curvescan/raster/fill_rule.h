// FillRule and Antialias: how the rasterizer turns winding numbers into coverage.
#pragma once

namespace curvescan {

/// SVG fill-rule / Cairo fill rule.
enum class FillRule {
  kNonZero,  ///< inside where the winding number is not zero
  kEvenOdd,  ///< inside where the winding number is odd
};

enum class Antialias {
  kExact,  ///< coverage = exact area of the (rule-resolved) shape inside the pixel square
  kNone,   ///< aliased: a pixel is fully covered iff its centre is inside
};

}  // namespace curvescan
