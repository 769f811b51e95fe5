// Private to the stroker and dasher: a path flattened for stroking.
//
// A FlatContour keeps what a plain polyline loses and a stroke needs: which vertices sit between two
// path segments (corners: the user's join applies there) and which lie inside a curve (smooth: the
// join is round, so the polyline sweeps a union of capsules), and the true end tangents of every
// segment (a cap or a miter must follow the curve's tangent, not the chord's). See stroker_outline.cpp.
#pragma once

#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/raster/path.h"
#include "curvescan/status.h"

namespace curvescan::detail {

struct FlatVertex {
  Point point;
  /// Unit tangent of the path arriving at / leaving `point` where it is known exactly (segment ends);
  /// the zero vector means "the chord's direction" (curve-interior vertices, dash ends inside a chord).
  Vec2 tangent_in;
  Vec2 tangent_out;
  /// A vertex between two path segments: the user's join. Otherwise a round join.
  bool corner = false;
};

/// One subpath: consecutive vertices distinct; a closed contour does not repeat its first vertex.
/// A single vertex is a zero-length subpath, capped along `degenerate_direction`.
struct FlatContour {
  std::vector<FlatVertex> vertices;
  bool closed = false;
  Vec2 degenerate_direction{1.0, 0.0};  // SVG 2: a zero-length subpath points along the user x axis
};

/// Where and how finely flatten_for_stroke refines curve ends (see stroker_flatten.cpp for why).
struct StrokeEndRefinement {
  double angle = 0.0;   ///< chords within `region` of a refined end lean at most this much (radians)
  double region = 0.0;  ///< control-polygon length of a refined end region; 0 disables refinement
  bool caps = false;    ///< refine the ends of open contours (butt and square caps need it)
  bool corners = false; ///< refine both sides of corners where the tangent turns (miter, bevel joins)
  bool whole = false;   ///< refine whole curves (dashing with butt or square caps: a dash may end anywhere)
};

/// Flattens every contour of `path` within `curve_tolerance` (user units, > 0), refining curve ends as
/// `refinement` says. Appends to `out`; kLimitExceeded if the flattener fails on non-finite arithmetic.
[[nodiscard]] Status flatten_for_stroke(const Path& path, double curve_tolerance,
                                        const StrokeEndRefinement& refinement, std::vector<FlatContour>& out);

/// Most halvings when locating an end region; most pieces one end region is cut into (past it the
/// remaining pieces are flattened as they are, and the end may be off by more than the tolerance).
inline constexpr int kMaxEndHalvings = 40;
inline constexpr int kMaxEndPieces = 1 << 10;

/// Polyline length of a contour (closing chord included when closed).
[[nodiscard]] double contour_length(const FlatContour& contour) noexcept;

}  // namespace curvescan::detail
