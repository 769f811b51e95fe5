// <marker> (SVG 1.1 section 11.6, SVG 2 "Markers"): where markers go on a path and how a marker's content
// is placed at a vertex.
//
// Vertices. Every moveto starts a vertex, every segment ends one, and a closepath ends one at the
// subpath's start. marker-start goes on the first vertex of the path, marker-end on the last, marker-mid
// on all others. A vertex's direction (orient="auto") bisects the incoming and outgoing directions; a
// subpath's first vertex has only the outgoing one and its last only the incoming one -- also when the
// subpath is closed, where SVG 1.1 11.6.2 would bisect the closing and first segments: browsers and resvg
// do not, and documents are drawn against them. In <path> data an elliptical arc is built from several
// conic pieces, whose joins are not vertices (a rational segment only comes from an arc there, so two
// pieces that are both rational and meet tangentially are taken as one arc; two separate arcs meeting
// tangentially lose their mid marker). Basic shapes keep every piece: a circle has a vertex at each
// quarter, as the path SVG 2 gives for it (10.3: four arcs).
//
// Placement. The marker's content is drawn in a frame at the vertex, rotated by the orientation and
// scaled by the stroke width (markerUnits="strokeWidth", the default): its viewport is markerWidth x
// markerHeight (default 3 x 3) with the viewBox mapped onto it, and the point (refX, refY) of the content
// at the vertex. Content outside the viewport is clipped unless overflow is visible or auto.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <vector>

#include "computed_style.h"
#include "curvescan/curves/affine.h"
#include "curvescan/curves/point.h"
#include "curvescan/curves/rect.h"
#include "curvescan/raster/path.h"

namespace curvescan::svg::detail {

/// Deepest nesting of markers drawn inside marker content.
inline constexpr int kMaxMarkerDepth = 4;

struct MarkerVertex {
  Point position;
  double angle = 0.0;  ///< degrees, the orient="auto" direction
};

/// The vertices of `path` in order, with their auto orientation (see above); `merge_arc_pieces` for paths
/// built from path data. A control point within `coincident_length` (user units, >= 0) of a segment's end
/// does not set the direction there, the next one does (SVG 2 "Path directionality" for coincident
/// points), as the stroker does for caps (StrokeCurveCuts::coincident_length): pass the stroke's
/// tolerance / 64 so that markers and caps agree. 0 skips only exactly coincident points.
[[nodiscard]] std::vector<MarkerVertex> marker_vertices(const Path& path, bool merge_arc_pieces,
                                                        double coincident_length = 0.0);

/// A <marker> with its attributes read (resolve_marker), once per marker and viewport in a render
/// (resolved_references.h): everything but the stroke width and the vertex.
struct ResolvedMarker {
  pugi::xml_node element;  ///< the <marker>, whose children the drawing walk draws
  ComputedStyle style;     ///< its computed style, from its own ancestors (its content inherits it)
  /// false: the marker draws nothing (markerWidth or markerHeight not positive, or an empty viewBox).
  bool draws = true;
  double width = 3.0, height = 3.0;  ///< markerWidth, markerHeight in user units
  Point ref;                         ///< (refX, refY) mapped by the viewBox into the viewport
  /// orient: nullopt for auto (the vertex angle), else a fixed angle in degrees.
  std::optional<double> fixed_angle;
  bool auto_start_reverse = false;  ///< orient="auto-start-reverse": the start marker points backwards
  bool stroke_width_units = true;   ///< markerUnits="strokeWidth" (the default)
  Affine view = Affine::identity();  ///< the viewBox mapping onto the viewport
  bool clips = true;                 ///< overflow hidden or scroll: the viewport clips the content
};

/// Reads `marker` whose computed style is `style`; warnings for bad values go to `diagnostics`.
[[nodiscard]] ResolvedMarker resolve_marker(const pugi::xml_node& marker, ComputedStyle style,
                                            const ResolveContext& context, Diagnostics& diagnostics);

/// A <marker> placed for a stroke width: everything but the vertex.
struct MarkerSetup {
  /// Maps the marker's content to the vertex frame (rotation and position excluded): stroke-width scale,
  /// the viewBox mapping and the refX/refY shift.
  Affine content_to_frame;
  /// The clip rectangle in the vertex frame, or nullopt when overflow shows everything.
  std::optional<Rect> clip;
};

/// `marker` for a stroke of `stroke_width`; nullopt when it draws nothing.
[[nodiscard]] std::optional<MarkerSetup> place_marker(const ResolvedMarker& marker, double stroke_width);

}  // namespace curvescan::svg::detail
