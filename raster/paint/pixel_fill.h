// fill_pixels: a run of pixels set to one colour at memory speed, for Canvas::clear and the opaque spans of
// the solid compositor (an opaque colour at full coverage replaces the destination, so no blending).
//
// A colour whose four bytes are equal (transparent black, opaque white) is a memset; any other colour is
// written 16 bytes at a time with SSE2 stores (baseline on x86-64), as pixman's sse2_fill does. A plain
// std::fill of the four-byte struct is not vectorised by g++ 12 at -O2 (its very-cheap cost model refuses a
// loop that needs a scalar epilogue), so it stores one pixel per instruction: 4–5× slower on a 512² clear.
#pragma once

#include <cstddef>

#include "curvescan/raster/image.h"

namespace curvescan::detail {

/// first[0..count) = color.
void fill_pixels(Rgba8* first, std::size_t count, Rgba8 color) noexcept;

}  // namespace curvescan::detail
