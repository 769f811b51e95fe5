// StrokeStyle: how a path is stroked — the SVG 2 / Cairo stroke properties in one value.
//
// Units are user units (the path's own coordinates, before the transform), as in SVG 2 §13.5 "Stroke
// properties" and cairo_set_line_width: a stroke is computed in user space and then transformed, so a
// non-uniform scale turns a round pen into an elliptical one.
#pragma once

#include <vector>

namespace curvescan {

/// Shape drawn at the corners between two path segments (SVG 2 'stroke-linejoin').
enum class LineJoin {
  kMiter,      ///< sharp corner; falls back to kBevel when the miter ratio exceeds the miter limit
  kMiterClip,  ///< SVG 2 miter-clip: like kMiter, but an over-long miter is cut at miter_limit·width/2
               ///< from the vertex instead of falling back to a bevel
  kRound,      ///< circular arc of radius width/2 around the vertex
  kBevel,      ///< straight line between the two offset corners
};

/// Shape drawn at the ends of open subpaths and dashes (SVG 2 'stroke-linecap').
enum class LineCap {
  kButt,    ///< the stroke ends flush at the end point
  kRound,   ///< half disc of radius width/2 beyond the end point
  kSquare,  ///< half square of side width beyond the end point
};

struct StrokeStyle {
  /// Full stroke width in user units, finite and >= 0. Zero draws nothing (SVG 2: "a value of zero
  /// causes no stroke to be painted").
  double width = 1.0;
  LineJoin join = LineJoin::kMiter;
  LineCap cap = LineCap::kButt;
  /// SVG 'stroke-miterlimit': a miter join is drawn when miter length / width = 1 / sin(φ/2) <= limit,
  /// φ being the angle between the two segments at the corner. Finite and >= 1 (SVG 2: values below 1
  /// are invalid). Default 4 as in SVG and Cairo; Cairo's default is 10.
  double miter_limit = 4.0;
  /// SVG 'stroke-dasharray' in user units: alternating dash and gap lengths, an odd-length list being
  /// repeated once to make it even. Empty = solid. All zeros = solid (SVG 2). Negative or non-finite
  /// entries are invalid: SVG ignores such a declaration (solid stroke), curvescan's API reports it as
  /// an error so that a reader can choose (svg readers map it to an empty array).
  std::vector<double> dash_array;
  /// SVG 'stroke-dashoffset': distance into the pattern at the start of each subpath; negative values
  /// are taken modulo the pattern's length. Finite.
  double dash_offset = 0.0;
};

}  // namespace curvescan
