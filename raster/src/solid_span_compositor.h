// SolidSpanCompositor: the SpanSink that paints a solid premultiplied colour, source-over, with each span's
// coverage (paint.h composite_source_over). The fast path is the common case of a shape's interior: full
// coverage and an opaque colour is a plain store, which is what composite_source_over yields there
// (s' = s, and 255 - s'.a = 0 keeps nothing of the destination).
#pragma once

#include <algorithm>
#include <span>

#include "curvescan/raster/image.h"
#include "curvescan/raster/paint.h"
#include "curvescan/raster/span.h"

namespace curvescan::detail {

class SolidSpanCompositor final : public SpanSink {
 public:
  SolidSpanCompositor(Image& image, Rgba8 color) noexcept : image_(image), color_(color) {}

  void blend(std::span<const Span> spans) override {
    for (const Span& span : spans) {
      if (span.coverage == 0 || color_.a == 0) continue;  // both leave the destination as it is
      Rgba8* row = image_.row(span.y) + span.x;
      if (span.coverage == 255 && color_.a == 255) {
        std::fill(row, row + span.len, color_);
        continue;
      }
      for (int i = 0; i < span.len; ++i) row[i] = composite_source_over(row[i], color_, span.coverage);
    }
  }

 private:
  Image& image_;
  Rgba8 color_;
};

}  // namespace curvescan::detail
