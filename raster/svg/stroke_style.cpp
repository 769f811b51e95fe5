// The stroke style of a computed style (stroke_style.h).
#include "stroke_style.h"

namespace curvescan::svg::detail {

StrokeStyle stroke_style_of(const ComputedStyle& style) {
  StrokeStyle stroke;
  stroke.width = style.stroke_width;
  switch (style.stroke_linejoin) {
    case LineJoinValue::kMiterClip:
      stroke.join = LineJoin::kMiterClip;
      break;
    case LineJoinValue::kRound:
      stroke.join = LineJoin::kRound;
      break;
    case LineJoinValue::kBevel:
      stroke.join = LineJoin::kBevel;
      break;
    default:  // miter, and SVG 2's arcs, which falls back to miter where unsupported
      stroke.join = LineJoin::kMiter;
  }
  stroke.cap = style.stroke_linecap == LineCapValue::kRound    ? LineCap::kRound
               : style.stroke_linecap == LineCapValue::kSquare ? LineCap::kSquare
                                                               : LineCap::kButt;
  stroke.miter_limit = style.stroke_miterlimit;
  stroke.dash_array = style.stroke_dasharray;
  stroke.dash_offset = style.stroke_dashoffset;
  return stroke;
}

}  // namespace curvescan::svg::detail
