// The render tree's Path node (docs/svg.md, "How a document is drawn"): a shape as the drawing needs it
// and nothing more -- its geometry in user units and its fill and stroke resolved (shape_paint.h), so
// that drawing it reads no attribute and no computed style (a pattern's tile is still drawn by the walk
// from the pattern's content, at the resolution the drawing sets). The basic shapes, <path>, the curve
// elements and the runs of a <text> are drawn through it, and a shape's markers are placed in it
// (placed_marker.h; their content is still drawn from the <marker>'s children).
#pragma once

#include <memory>
#include <optional>

#include "curvescan/raster/path.h"
#include "curvescan/raster/stroke.h"
#include "painting_properties.h"
#include "placed_marker.h"
#include "shape_paint.h"

namespace curvescan::svg::detail {

struct PathNode {
  Path path;  ///< in the element's user units
  FillRule fill_rule = FillRule::kNonZero;
  /// nullopt: nothing to paint (`none`, a paint server that paints nothing without a fallback, or the
  /// element is not visible).
  std::optional<ShapePaint> fill;
  /// nullopt as for the fill, and also when stroke-width is not positive.
  std::optional<ShapePaint> stroke;
  StrokeStyle stroke_style;                    ///< stroke_style.h
  bool non_scaling_stroke = false;             ///< vector-effect: non-scaling-stroke (built in device space)
  Antialias antialias = Antialias::kExact;     ///< kNone for shape-rendering crispEdges / optimizeSpeed
  PaintOrder paint_order = kNormalPaintOrder;  ///< SVG 2 13.10, markers among the layers
  /// marker-start, -mid and -end placed on the path's vertices (placed_marker.h); none on a curve element
  /// or a text run, nor inside the content of the marker itself: null then. Held apart so that a node
  /// without markers, nearly every one, stays small to make, move and destroy.
  std::unique_ptr<const PathMarkers> markers;
};

}  // namespace curvescan::svg::detail
