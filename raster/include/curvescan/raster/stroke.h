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
// Dashing (dash.h) happens on the flattened polyline, before the outline.
#pragma once

#include <cstdint>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/path.h"
#include "curvescan/raster/stroke_style.h"
#include "curvescan/status.h"

namespace curvescan {

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

/// The user-space tolerance that keeps the device-space error of a stroke within `device_tolerance` under
/// `transform`: device_tolerance / σ_max, σ_max being the largest singular value of the linear part (the
/// most a user-space distance can be stretched). +infinity when the linear part is zero (everything maps
/// to one point), NaN when the transform or the tolerance is NaN.
[[nodiscard]] double stroke_user_tolerance(const Affine& transform, double device_tolerance) noexcept;

}  // namespace curvescan
