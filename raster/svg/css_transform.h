// The transform property in CSS syntax (CSS Transforms 1, section 13 "The Transform Functions", and
// CSS Transforms 2, section 12 "The 3D Transform Functions"), as style sheets write it:
// `transform: translate(10px, 5px) rotate(45deg)`.
//
// SVG's own syntax (transform.h: unitless numbers, optional commas, rotate(a cx cy)) is tried first by
// the caller; this parser reads what that one refuses: lengths with absolute units (px, in, cm, mm, Q,
// pt, pc; 0 without a unit), em and ex of the element's font size (ex as 0.5 em, the value CSS Values 4
// 6.1.1 prescribes when the x-height is not measured), percentages in the translations of the reference
// box (SVG elements' transform-box is view-box: the nearest viewport), angles in deg, grad, rad and turn
// (0 without a unit), commas between the arguments, whitespace between the functions.
//
// Every function of both levels is read as a 4 x 4 matrix and the list composed in 3D; SVG draws flat
// (transform-style: flat), so the result is then flattened onto the plane z = 0 (CSS Transforms 2, 5:
// x and y of points with z = 0, the output z dropped). A list whose flattened matrix is affine (no
// perspective on x or y, as for translate3d(x, y, 0), scale3d(sx, sy, 1), rotateZ(), rotateX(),
// matrix3d() affine in x and y) gives that affine; one with perspective division by x or y is refused
// with a message naming it, and so are rem and the other relative units: the declaration is then
// invalid and the cascade falls back (cascade.h).
#pragma once

#include <string_view>

#include "curvescan/curves/affine.h"
#include "curvescan/status.h"

namespace curvescan::svg::detail {

/// What relative lengths in a transform refer to.
struct CssTransformContext {
  double font_size = 16.0;        ///< the element's font size, px (em, ex)
  double reference_width = 0.0;   ///< the reference box, px: percentages of translate's x
  double reference_height = 0.0;  ///< and of its y
};

/// The transform of a CSS <transform-list>, or an error naming what is not understood. `none` is the
/// identity.
[[nodiscard]] Result<Affine> parse_css_transform(std::string_view text,
                                                 const CssTransformContext& context = {});

}  // namespace curvescan::svg::detail
