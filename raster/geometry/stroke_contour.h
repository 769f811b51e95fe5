// Private to the stroker and dasher: a path flattened for stroking.
//
// A FlatContour keeps what a plain polyline loses and a stroke needs: which vertices sit between two
// path segments (corners: the user's join applies there) and the true tangent of the curve at every
// vertex (a cap, a dash end or a miter must follow the curve's normal, not a chord's; the outline sweeps
// the true normal segment from vertex to vertex). See stroker_flatten.cpp and stroker_outline.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "curvescan/curves/point.h"
#include "curvescan/raster/path.h"
#include "curvescan/status.h"
#include "stroke_curve_piece.h"
#include "vector_length.h"

namespace curvescan::detail {

struct FlatVertex {
  Point point;
  /// Unit tangent of the path arriving at / leaving `point`: exact at segment ends and at the cut points of
  /// a curve, interpolated between them inside a piece of narrow tangent cone (stroker_flatten.cpp); the
  /// two differ only at corners. The zero vector means "the chord's direction" (not produced by
  /// flatten_for_stroke, kept as a safe fallback).
  Vec2 tangent_in;
  Vec2 tangent_out;
  /// A vertex between two path segments: the user's join. Otherwise a round join (where the tangents differ).
  bool corner = false;
  /// The curve piece (FlatContour::piece) the chord from this vertex to the next was flattened from; -1 for a
  /// line, or when the contour keeps no pieces (StrokeCurveCuts::keep_pieces, and dashes never do).
  std::int32_t piece = -1;
};

/// One subpath: consecutive vertices distinct; a closed contour does not repeat its first vertex.
/// A single vertex is a zero-length subpath, capped along `degenerate_direction`.
struct FlatContour {
  std::vector<FlatVertex> vertices;
  bool closed = false;
  Vec2 degenerate_direction{1.0, 0.0};  // SVG 2: a zero-length subpath points along the user x axis
  /// With StrokeCurveCuts::keep_pieces: the control points of every curve piece the contour was flattened
  /// from, piece k being piece_control[piece_ends[k - 1] .. piece_ends[k]) (the dasher's exact dash ends).
  std::vector<HomogeneousPoint> piece_control;
  std::vector<std::size_t> piece_ends;

  [[nodiscard]] std::span<const HomogeneousPoint> piece(std::int32_t k) const noexcept {
    const auto index = static_cast<std::size_t>(k);
    const std::size_t begin = index == 0 ? 0 : piece_ends[index - 1];
    return std::span<const HomogeneousPoint>(piece_control).subspan(begin, piece_ends[index] - begin);
  }
};

/// How flatten_for_stroke cuts curves before flattening them (see stroker_flatten.cpp for why).
struct StrokeCurveCuts {
  /// The true tangents at the two ends of every polyline chord differ by at most this angle (radians);
  /// >= pi/2 disables the cuts (dash_path: the tangents are not used).
  double max_turn = std::numbers::pi;
  /// A piece whose control polygon is no longer than this is not cut further (its tangents may turn by
  /// more than max_turn: a cusp; the outline gives such a chord the sectors its normal sweeps). > 0.
  double min_piece_length = 1.0;
  /// Most vertices all contours may have together (the caller's outline budget): past it
  /// flatten_for_stroke stops with kLimitExceeded instead of growing without bound.
  std::size_t max_vertices = SIZE_MAX;
  /// Keep each piece's control points in the contour and its index in the vertices (FlatVertex::piece):
  /// the dasher then cuts dash ends on the curve with its exact tangent (stroke_curve_piece.h).
  bool keep_pieces = false;
  /// A control point closer than this to a curve's end point does not set the direction at that end (the
  /// cap, the join with the neighbouring segment): the next control point does, then the chord, as if the
  /// two coincided (SVG 2 §9.5.2 "Path directionality" for coincident points). The curve's own derivative
  /// there points at the nearby control point, a direction the curve keeps only over a length of that
  /// order: a line drawn as a curve would get its caps across it. 0 keeps only exact coincidence.
  double coincident_length = 0.0;
};

/// Flattens every contour of `path` within `curve_tolerance` (user units, > 0), cutting curves as `cuts`
/// says, with the true tangent at every vertex. Appends to `out`; kLimitExceeded if the flattener fails
/// on non-finite arithmetic or the vertices would pass cuts.max_vertices.
[[nodiscard]] Status flatten_for_stroke(const Path& path, double curve_tolerance, const StrokeCurveCuts& cuts,
                                        std::vector<FlatContour>& out);

/// Most pieces one curve is cut into by max_turn (past it the remaining pieces are flattened as they are:
/// the outline then covers their chords with swept sectors or discs, within the round-join stroke but not
/// the exact one).
/// The pieces a curve needs grow like its total turn / sqrt(2·tolerance/h): a circle of radius 5 stroked
/// 11 wide at tolerance 2.5e-8 (scale 10^7, 0.25 px) needs 16500 per quarter. The former 2^12 was reached
/// there and every chord past it got a disc of 2π/sqrt(8·tolerance/4/h) vertices (6.2M outline elements,
/// fuzz/regressions/raster_stroke/round_join_circle_under_scale_1e7_oom); 2^22 (kMaxFlattenSegments)
/// is beyond any outline budget (StrokeCurveCuts::max_vertices), which bounds the work instead.
inline constexpr int kMaxTurnPieces = 1 << 22;

/// The unit tangent at fraction `f` in [0, 1] of a chord whose ends have unit tangents `a` and `b`
/// (normalized linear interpolation; `a` or `b` whichever is nearer when they are opposite).
[[nodiscard]] inline Vec2 interpolate_tangent(Vec2 a, Vec2 b, double f) noexcept {
  const Vec2 mix = a * (1.0 - f) + b * f;
  const double length = vector_length(mix);
  if (!(length > 1e-9)) return f < 0.5 ? a : b;
  return mix / length;
}

/// Polyline length of a contour (closing chord included when closed).
[[nodiscard]] double contour_length(const FlatContour& contour) noexcept;

}  // namespace curvescan::detail
