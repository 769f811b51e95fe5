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
#pragma once

#include <span>

#include "curvescan/raster/path.h"
#include "curvescan/status.h"

namespace curvescan {

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

}  // namespace curvescan
