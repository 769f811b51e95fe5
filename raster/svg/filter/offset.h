// feOffset (Filter Effects 1, section 9.17): the input moved by (dx, dy). The offset is rounded to whole
// filter pixels (as Chrome and resvg do), so the result is an exact copy rather than a resampled one; at
// device resolution the rounding moves an edge by at most half a pixel.
#pragma once

#include <algorithm>
#include <cmath>

#include "filter_image.h"

namespace curvescan::svg::detail::filter {

/// An offset of `pixels` (any double) in whole pixels: the nearest, and a half rounded down -- what
/// sampling the input at each output pixel's centre with nearest-pixel lookup gives (the centre x + 0.5
/// reads x + 0.5 - d, on a pixel's edge for a half, taken as the pixel to its right, so 7.5 moves by 7), as
/// Skia's offset filter and resvg place it. Clamped to +-1e9 (beyond the image every pixel reads
/// transparent anyway); NaN gives 0.
[[nodiscard]] inline long long whole_pixel_offset(double pixels) noexcept {
  if (!(pixels == pixels)) return 0;
  return static_cast<long long>(std::ceil(std::clamp(pixels, -1e9, 1e9) - 0.5));
}

/// out(x, y) = in(x - dx, y - dy) inside `subregion` (transparent where that falls outside `in`). `out` may
/// be `in` itself: every pixel is read before it is overwritten.
void offset(const FilterImage& in, PixelRect subregion, long long dx, long long dy,
            FilterImage& out) noexcept;

}  // namespace curvescan::svg::detail::filter
