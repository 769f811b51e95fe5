// The transform property in CSS syntax (CSS Transforms 1, section 13 "The Transform Functions"), as style
// sheets write it: `transform: translate(10px, 5px) rotate(45deg)`.
//
// SVG's own syntax (transform.h: unitless numbers, optional commas, rotate(a cx cy)) is tried first by
// the caller; this parser reads what that one refuses: lengths with absolute units (px, in, cm, mm, Q,
// pt, pc; 0 without a unit), angles in deg, grad, rad and turn (0 without a unit), commas between the
// arguments, and the functions matrix(), translate(), translateX(), translateY(), scale(), scaleX(),
// scaleY(), rotate() (also rotateZ()), skew(), skewX() and skewY(), separated by whitespace. Relative
// lengths (em, %) and the 3D functions are refused with a message naming them: the declaration is then
// invalid and the cascade falls back (cascade.h).
#pragma once

#include <string_view>

#include "curvescan/curves/affine.h"
#include "curvescan/status.h"

namespace curvescan::svg::detail {

/// The transform of a CSS <transform-list>, or an error naming what is not understood. `none` is the
/// identity.
[[nodiscard]] Result<Affine> parse_css_transform(std::string_view text);

}  // namespace curvescan::svg::detail
