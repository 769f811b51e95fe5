// Private to the stroker and dash_path(): the dasher on flattened contours (see dasher.cpp).
#pragma once

#include <span>
#include <vector>

#include "curvescan/status.h"
#include "stroke_contour.h"

namespace curvescan::detail {

/// Appends the dashes of `contours` to `out`. `dash_array` must be valid and active (stroke.h); an
/// odd-length array is repeated. kLimitExceeded, with nothing appended, past kMaxDashSegments.
[[nodiscard]] Status dash_contours(std::span<const FlatContour> contours, std::span<const double> dash_array,
                                   double dash_offset, std::vector<FlatContour>& out);

}  // namespace curvescan::detail
