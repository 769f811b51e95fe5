// Stroking: a Path and a StrokeStyle -> the Path of the stroke's outline, filled nonzero.
//
// The algorithm and its proof of correctness are in geometry/stroker_outline.cpp; in short (after Nehab,
// "Converting stroked primitives to filled primitives", SIGGRAPH 2020):
//  - every curve is flattened in user space (curves flatten.h) into a polyline within tolerance/2, the
//    pieces next to a segment end cut short enough that their chords follow the true end tangent;
//  - the outline is the sum of convex pieces all wound the same way: one quadrilateral per polyline
//    segment, a wedge per join, a cap per end. Filled nonzero, a sum of same-sign pieces is exactly their
//    union, whatever their overlaps (curvescan's rasterizer resolves overlapping pieces exactly), so
//    inner joins, cusps, loops and thick strokes on tight curves are "strongly correct" in Nehab's sense;
//  - joins inside a curve are round (the polyline's swept area is a union of capsules, within tolerance of
//    the curve's); the user's join only applies where two path segments meet.
// Dashing (dash_path below) happens on the flattened polyline, before the outline.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/path.h"
#include "curvescan/status.h"

namespace curvescan {

// StrokeStyle: how a path is stroked — the SVG 2 / Cairo stroke properties in one value.
//
// Units are user units (the path's own coordinates, before the transform), as in SVG 2 §13.5 "Stroke
// properties" and cairo_set_line_width: a stroke is computed in user space and then transformed, so a
// non-uniform scale turns a round pen into an elliptical one.
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

// Dashing: a Path -> the Path of its dashes (SVG 2 §13.5.6 'stroke-dasharray' / 'stroke-dashoffset').
//
// Dashes are measured by arc length along the curves (each chord of the polyline within `tolerance` counted
// as the circle arc its two end tangents define, which is the curve's length up to fourth-order terms;
// Cairo measures the bare polyline), restarting the pattern at every subpath. An odd-length array is repeated; the
// offset is taken modulo the pattern's length (negative offsets too); a zero-length dash is a zero-length
// subpath (a dot or a square once stroked with a round or square cap). A dash that runs through a vertex
// stays one subpath, and on a closed subpath a dash running through the start joins the last dash.
// stroke_path() dashes internally (it keeps which vertices are curve-interior and the true tangents);
// dash_path() is the same dasher for callers who want the dashes themselves.
/// Checks a dash array and offset as stroke_path() does: every entry finite and >= 0, offset finite.
/// kInvalidArgument with a message naming the offending entry otherwise.
[[nodiscard]] Status validate_dash(std::span<const double> dash_array, double dash_offset);

/// True when the array dashes at all: non-empty and not all zeros (SVG 2: all zeros draws a solid line).
[[nodiscard]] bool dash_is_active(std::span<const double> dash_array) noexcept;

/// The dashes of `path` as open polylines (closed ones for a closed subpath that the pattern leaves
/// entirely on), curves flattened within `tolerance` (> 0, finite). An inactive array returns the path
/// flattened. Fails like validate_dash, and with kLimitExceeded past kMaxDashSegments (limits.h).
[[nodiscard]] Result<Path> dash_path(const Path& path, std::span<const double> dash_array, double dash_offset,
                                     double tolerance);

/// The outline of `path` stroked with `style`, as closed polygonal contours (kMove, kLine, kClose only)
/// in the same (user) units, to be filled with FillRule::kNonZero. `tolerance` (user units, finite, > 0)
/// bounds the Hausdorff distance between the outline's filled area and the exact stroke.
///
/// Zero-length subpaths follow SVG 2 §13.5.5: a round cap draws a disc, a square cap a square aligned with
/// the user x axis (Cairo does the same), a butt cap nothing. Fails with kInvalidArgument for a width,
/// miter limit, dash entry or offset out of range (see StrokeStyle), with kLimitExceeded when the dash
/// pattern would make more than kMaxDashSegments dashes (limits.h) or the outline would not be finite.
/// The outline is held to kMaxStrokeOutlinePoints points (kLimitExceeded past it).
[[nodiscard]] Result<Path> stroke_path(const Path& path, const StrokeStyle& style, double tolerance);

/// Default budget of outline points of one stroke_path() call: kDefaultMaxRenderSegments (limits.h),
/// since every outline point becomes one rasterizer edge. The outline's size grows like
/// length·sqrt(width/tolerance) (curve cuts, round joins and caps alike), so a fine tolerance under a huge
/// transform is refused instead of exhausting memory.
inline constexpr std::int64_t kMaxStrokeOutlinePoints = std::int64_t{1} << 22;

/// stroke_path() with an explicit budget of outline points (>= 0; e.g. what a render's segment budget
/// leaves): kLimitExceeded, before the outline passes it, when the stroke needs more.
[[nodiscard]] Result<Path> stroke_path(const Path& path, const StrokeStyle& style, double tolerance,
                                       std::int64_t max_outline_points);

/// stroke_path() for a caller that draws only inside `visible`, a box in the path's coordinates (e.g. a
/// canvas's drawing area mapped back to user space): dashes are made, and counted against
/// kMaxDashSegments, only where the outline can reach the box — a fine dash pattern on a path that runs far
/// off the canvas costs only its visible part. Inside `visible` the outline covers what stroke_path()
/// covers without the box (the dashes lie at the same arc lengths); outside it, dashes are missing or cut.
/// A box that is not finite culls nothing.
[[nodiscard]] Result<Path> stroke_path(const Path& path, const StrokeStyle& style, double tolerance,
                                       std::int64_t max_outline_points, const Rect& visible);

/// The user-space tolerance that keeps the device-space error of a stroke within `device_tolerance` under
/// `transform`: device_tolerance / σ_max, σ_max being the largest singular value of the linear part (the
/// most a user-space distance can be stretched). +infinity when the linear part is zero (everything maps
/// to one point), NaN when the transform or the tolerance is NaN.
[[nodiscard]] double stroke_user_tolerance(const Affine& transform, double device_tolerance) noexcept;

}  // namespace curvescan
