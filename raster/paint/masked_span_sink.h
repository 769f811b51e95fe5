// Span sinks around a clip mask (mask.h):
//  - MaskedSpanSink multiplies each span's coverage by the mask under it (MUL_UN8, pixman's IN) and
//    forwards runs of equal resulting coverage to the painting sink, so the solid and gradient
//    compositors need not know about masks;
//  - ClipMaskWriter stores a rasterized clip path into a mask.
// An IN of two coverages is what Cairo's image backend does when it composites through an A8 clip
// surface; when the clip is a path of the same antialiasing, Cairo instead intersects the polygons, which
// differs only on pixels crossed by both an edge of the clip and an edge of the shape (docs/paint.md).
#pragma once

#include <array>
#include <span>

#include "curvescan/raster/mask.h"
#include "curvescan/raster/rasterizer.h"

namespace curvescan::detail {

class MaskedSpanSink final : public SpanSink {
 public:
  MaskedSpanSink(SpanSink& painter, const ClipMask& mask) noexcept : painter_(painter), mask_(mask) {}

  void blend(std::span<const Span> spans) override {
    for (const Span& span : spans) {
      const std::uint8_t* mask_row = mask_.row(span.y);
      int x = span.x;
      const int end = span.x + span.len;
      while (x < end) {
        const std::uint8_t m = mask_row[x];
        int run_end = x + 1;
        while (run_end < end && mask_row[run_end] == m) ++run_end;
        const std::uint8_t coverage = m == 255 ? span.coverage : multiply_coverage(span.coverage, m);
        if (coverage != 0) push({x, span.y, run_end - x, coverage});
        x = run_end;
      }
    }
    flush();
  }

 private:
  void push(const Span& span) {
    if (count_ == buffer_.size()) flush();
    buffer_[count_++] = span;
  }
  void flush() {
    if (count_ == 0) return;
    painter_.blend(std::span<const Span>(buffer_.data(), count_));
    count_ = 0;
  }

  SpanSink& painter_;
  const ClipMask& mask_;
  std::array<Span, 256> buffer_{};
  std::size_t count_ = 0;
};

class ClipMaskWriter final : public SpanSink {
 public:
  explicit ClipMaskWriter(ClipMask& mask) noexcept : mask_(mask) {}
  void blend(std::span<const Span> spans) override { mask_.write_spans(spans); }

 private:
  ClipMask& mask_;
};

}  // namespace curvescan::detail
