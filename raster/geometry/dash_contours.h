// Private to the stroker and dash_path(): the dasher on flattened contours (see dasher.cpp).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "curvescan/curves/rect.h"
#include "curvescan/status.h"
#include "stroke_contour.h"

namespace curvescan::detail {

/// Appends the dashes of `contours` to `out`. `dash_array` must be valid and active (stroke.h); an
/// odd-length array is repeated. With a `cull` box, no dashes are made on the parts of the contours outside
/// it (see dasher.cpp), nor counted. kLimitExceeded, with nothing appended, past kMaxDashSegments.
[[nodiscard]] Status dash_contours(std::span<const FlatContour> contours, std::span<const double> dash_array,
                                   double dash_offset, std::vector<FlatContour>& out,
                                   const std::optional<Rect>& cull);

}  // namespace curvescan::detail
