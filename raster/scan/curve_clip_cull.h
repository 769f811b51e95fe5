// flatten_visible: a path's curve segment to a polyline for filling inside a clip box, flattening only
// the pieces that can be seen.
//
// Essay. The rasterizer clips edges to its box and computes coverage inside it only, and a fill needs from
// the edges outside the box nothing but their winding. A curve whose convex hull misses the box can
// therefore be replaced by its chord (proof in curve_clip_cull.cpp), and a huge curve that crosses the box
// is cut by de Casteljau halving (Gallivan, *Parametric Curves*, "DeCasteljau's Algorithm") until each piece either misses the
// box (its chord) or is small next to it (flattened as usual): the flattening work follows the visible part
// of the curve, not its extent. Before, an SVG arc 8e167 tall over a 32 x 32 clip was flattened to the
// 2^22-segment cap first (fuzz/regressions/raster_stroke/ellipse_arcs_4e167_tall_flatten_timeout, 50 s).
#pragma once

#include <climits>
#include <cstddef>
#include <vector>

#include "curvescan/curves/flatten.h"
#include "curvescan/curves/point.h"
#include "curvescan/curves/rect.h"
#include "curvescan/raster/path.h"

namespace curvescan::detail {

/// A closed box holding every clip an IntRect can describe (pixel edges are ints): culling against it is
/// exact for any Rasterizer (tests use it; add_path_edges culls against the rasterizer's own clip()).
inline constexpr Rect kAnyClipBox{static_cast<double>(INT_MIN), static_cast<double>(INT_MIN),
                                  static_cast<double>(INT_MAX), static_cast<double>(INT_MAX)};

/// Deepest halving of one curve (a curve 2·DBL_MAX wide is below one unit after ~1025 halvings); past it a
/// piece that still meets the box is flattened whatever its size (the flattener's own cap bounds it).
inline constexpr int kMaxCullDepth = 1100;

/// A piece meeting the box is flattened once its bounding box is at most this many times the box's larger
/// side (plus one pixel): smaller pieces cost the flattener about what their visible part costs, larger
/// ones are halved. A curve this small from the start is flattened exactly as flatten.h does it.
inline constexpr double kFlattenExtentFactor = 4.0;

/// What flatten_visible did, for tests and budgets (counts of pieces, machine independent).
struct CullStats {
  std::size_t chorded = 0;    ///< pieces replaced by their chord (hull outside the box)
  std::size_t flattened = 0;  ///< pieces given to the flattener
  std::size_t halved = 0;     ///< de Casteljau halvings
};

/// Appends to `out` the polyline of the curve segment `element` (kQuad, kCubic, kBezier, kConic or
/// kRationalBezier; device pixels) as flatten_bezier/flatten_rational do — vertices after the first, the
/// last exactly element.end — except that pieces whose control-point hull misses `box` (closed) are single
/// chords. Inside `box` the winding number of the contour is unchanged and the polyline is within
/// `tolerance` of the curve. Outcome: the flattener's for a curve handled whole (then the polyline is
/// bit-for-bit flatten.h's); for a cut curve kOk, or kSegmentLimit when a piece was not certified (a piece
/// the flattener refused is a chord: the polyline is always complete). Work: O(kMaxCullDepth · pieces
/// meeting the box) halvings plus the flattening of the visible pieces.
/// `max_segments` (at least 1) caps the vertices appended, as flatten_bezier's cap does: each flattened
/// piece gets what is left of it, and once it is spent the last vertex becomes element.end (the rest of
/// the curve is that chord) and the outcome is kSegmentLimit; a curve that needs fewer vertices than the
/// cap is not affected. Each halving adds one piece that either appends a vertex or waits on the stack
/// (at most kMaxCullDepth + 1 of them), so the halvings are bounded by the cap too.
FlattenOutcome flatten_visible(const PathElement& element, double tolerance, const Rect& box,
                               std::vector<Point>& out, std::size_t max_segments = kMaxFlattenSegments,
                               CullStats* stats = nullptr);

}  // namespace curvescan::detail
