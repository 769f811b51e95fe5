// feTile (Filter Effects 1, section 9.20): the input's subregion taken as a tile and repeated over the
// primitive's subregion, aligned so that one copy sits where the input's subregion is.
#pragma once

#include "filter_image.h"

namespace curvescan::svg::detail::filter {

/// Repeats `in` inside `tile` over `subregion` of `out`. An empty tile leaves `out` transparent.
void tile(const FilterImage& in, PixelRect tile, PixelRect subregion, FilterImage& out) noexcept;

}  // namespace curvescan::svg::detail::filter
