// SolidSpanCompositor: the SpanSink that paints a solid premultiplied colour, source-over, with each span's
// coverage (paint.h composite_source_over), bit for bit.
//
// Every pixel of a span sees the same source: s' = MUL_UN8(colour, coverage) and keep = 255 - s'.a are
// span constants, so they are computed once per span and the pixels only do d' = s' + MUL_UN8(d, keep)
// (blend_solid_span in composite.cpp, four pixels at a time with SSE2, as pixman's solid OVER does, eight
// with AVX2 where the processor has it). An
// opaque colour at full coverage is a plain fill (keep = 0 keeps nothing of the destination): pixel_fill.h.
#pragma once

#include <cstdint>
#include <span>

#include "curvescan/raster/image.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/rasterizer.h"
#include "pixel_fill.h"

namespace curvescan::detail {

/// row[0..len) = composite_source_over(row[i], color, coverage) for every i, exactly (same rounding).
void blend_solid_span(Rgba8* row, int len, Rgba8 color, std::uint8_t coverage) noexcept;

/// blend_solid_span with the four-pixel SSE2 loop only, even where the processor has AVX2 (the same bytes:
/// tests hold the two to each other and to the reference).
void blend_solid_span_without_avx2(Rgba8* row, int len, Rgba8 color, std::uint8_t coverage) noexcept;

/// Every span composited with `color` as blend_solid_span does (an opaque colour at full coverage filled,
/// a transparent one skipped), in one call: the per-span work inlined into one loop.
void blend_solid_spans(Image& image, std::span<const Span> spans, Rgba8 color) noexcept;

class SolidSpanCompositor final : public SpanSink {
 public:
  SolidSpanCompositor(Image& image, Rgba8 color) noexcept : image_(image), color_(color) {}

  void blend(std::span<const Span> spans) override { blend_solid_spans(image_, spans, color_); }

 private:
  Image& image_;
  Rgba8 color_;
};

}  // namespace curvescan::detail
