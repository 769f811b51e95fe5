// context-fill and context-stroke (SVG 2 13.4.1): the paints of a context element -- the element a marker
// is drawn for, or the <use> whose content is drawn -- as its content sees them.
#pragma once

#include <optional>

#include "computed_style.h"
#include "curvescan/curves/affine.h"
#include "curvescan/curves/rect.h"
#include "curvescan/svg/color.h"

namespace curvescan::svg::detail {

/// Where a context element's paint server is drawn: its user space (`ctm`, to the device) and its
/// bounding box. A gradient or pattern is drawn there, not on the box of the shape that uses the context
/// paint (SVG 2 13.4.1: "the paint server is rendered using the coordinate space and bounding box of the
/// context element").
struct PaintSpace {
  std::optional<Rect> bbox;  ///< nullopt: the element draws nothing; the paint then has no box
  Affine ctm;
};

/// A context element's fill and stroke, with a context paint of its own already replaced by its own
/// context's (never kContextFill or kContextStroke: none when there is no outer context).
struct ContextPaint {
  PaintSpec fill;
  PaintSpec stroke;
  Color color;  ///< the context element's `color`, for its currentColor
  PaintSpace fill_space, stroke_space;
};

}  // namespace curvescan::svg::detail
