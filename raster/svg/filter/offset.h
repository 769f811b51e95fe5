// feOffset (Filter Effects 1, section 9.17): the input moved by (dx, dy). The offset is rounded to whole
// filter pixels (as Chrome and resvg do), so the result is an exact copy rather than a resampled one; at
// device resolution the rounding moves an edge by at most half a pixel.
#pragma once

#include "filter_image.h"

namespace curvescan::svg::detail::filter {

/// out(x, y) = in(x - dx, y - dy) inside `subregion` (transparent where that falls outside `in`).
void offset(const FilterImage& in, PixelRect subregion, long long dx, long long dy,
            FilterImage& out) noexcept;

}  // namespace curvescan::svg::detail::filter
