// OffsetSpanSink: spans in canvas coordinates, painted into an image that starts elsewhere (a layer,
// layer.h). Shifts every span by (-origin_x, -origin_y) and forwards it, in batches.
#pragma once

#include <algorithm>
#include <array>
#include <span>

#include "curvescan/raster/rasterizer.h"

namespace curvescan::detail {

/// Shifts spans by (−origin_x, −origin_y) before painting them: the solid compositor writes at span
/// coordinates, and a layer's image starts at its origin in the canvas.
class OffsetSpanSink final : public SpanSink {
 public:
  OffsetSpanSink(SpanSink& painter, int origin_x, int origin_y) noexcept
      : painter_(painter), origin_x_(origin_x), origin_y_(origin_y) {}

  void blend(std::span<const Span> spans) override {
    for (std::size_t start = 0; start < spans.size(); start += buffer_.size()) {
      const std::size_t count = std::min(buffer_.size(), spans.size() - start);
      for (std::size_t i = 0; i < count; ++i) {
        const Span& s = spans[start + i];
        buffer_[i] = {s.x - origin_x_, s.y - origin_y_, s.len, s.coverage};
      }
      painter_.blend(std::span<const Span>(buffer_.data(), count));
    }
  }

 private:
  SpanSink& painter_;
  int origin_x_, origin_y_;
  std::array<Span, 256> buffer_{};
};

}  // namespace curvescan::detail
