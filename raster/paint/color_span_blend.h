// blend_color_span: source-over of a run of premultiplied colours, one per pixel, through one coverage —
// the blending half of the gradient and pattern compositors, which first shade a span's colours into a
// buffer and then blend the buffer.
//
// The arithmetic is paint.h's composite_source_over for every pixel, bit for bit: s' = MUL_UN8(s, coverage),
// d' = s' + MUL_UN8(d, 255 − s'.a) with a saturating add, MUL_UN8 rounded as pixman does. With SSE2 four
// pixels go at once in 16-bit lanes (as in blend_solid_span, composite.cpp), each pixel's 255 − s'.a
// broadcast across its four lanes by a word shuffle. Four pixels whose s' are all opaque are stored as they
// are, four whose s' are all zero leave the destination alone: both are what the formula gives.
#pragma once

#include <cstdint>

#include "curvescan/raster/image.h"

namespace curvescan::detail {

/// row[i] = composite_source_over(row[i], colors[i], coverage) for i in [0, len), exactly.
void blend_color_span(Rgba8* row, const Rgba8* colors, int len, std::uint8_t coverage) noexcept;

}  // namespace curvescan::detail
