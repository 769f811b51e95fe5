// The markers of a Path node (render_path.h), placed (docs/svg.md, "How a document is drawn"): for each
// vertex of the path that gets a marker (marker.h: marker-start on the first, marker-mid on the others,
// marker-end on the last), the <marker> read once per render and where its content goes -- the vertex
// frame (position and orientation) and, inside it, the content's own mapping and overflow clip -- so that
// drawing a marker reads no `marker-*` property, no <marker> attribute and places nothing.
//
// The content itself is still drawn from the <marker>'s children by the drawing walk.
#pragma once

#include <numbers>
#include <optional>
#include <vector>

#include "context_paint.h"
#include "curvescan/curves/affine.h"
#include "curvescan/curves/point.h"
#include "curvescan/curves/rect.h"
#include "marker.h"

namespace curvescan::svg::detail {

/// Whether an element takes markers (SVG 2 11.6, "markable elements": <path>, <line>, <polyline>,
/// <polygon>, and in SVG 2 every basic shape) and how its vertices are found (marker_vertices).
enum class Markable {
  kNo,          ///< curve elements and text runs
  kBasicShape,  ///< every piece of the shape's outline ends a vertex
  kPathData,    ///< <path>: the conic pieces of one elliptical arc are one segment
};

/// One marker at one vertex.
struct PlacedMarker {
  const ResolvedMarker* marker = nullptr;  ///< read once per render (resolved_references.h); not null
  Point position;                          ///< the vertex, in the path's user units
  /// The marker's orientation in degrees: orient's fixed angle, or the vertex direction (turned by 180
  /// for orient="auto-start-reverse" at the path's start).
  double angle = 0.0;
  /// From the content to the vertex frame: the stroke-width scale (markerUnits="strokeWidth"), the
  /// viewBox mapping and the refX/refY shift (MarkerSetup::content_to_frame).
  Affine content_to_frame;
  /// The overflow clip in the vertex frame (MarkerSetup::clip); nullopt when overflow shows everything.
  /// Never without area: a marker clipped to nothing is not placed.
  std::optional<Rect> clip;

  /// The vertex frame seen from the device: `ctm` (the path's user space to the device), then the
  /// vertex's position and orientation.
  [[nodiscard]] Affine frame_under(const Affine& ctm) const {
    return ctm * Affine::translate(position.x, position.y) * Affine::rotate(angle * std::numbers::pi / 180.0);
  }
};

/// A Path node's markers, when it has any.
struct PathMarkers {
  /// In the order they are drawn: the path's vertices in order; on a path of one vertex, its start marker
  /// before its end marker.
  std::vector<PlacedMarker> placed;
  /// What context-fill and context-stroke mean in the markers' content (SVG 2 13.4.1): the marked
  /// element's paints, in its user space and with its box.
  ContextPaint context;
};

}  // namespace curvescan::svg::detail
