// ClipMask: writing a rasterized clip path into the mask, and the intersection of nested clips.
#include "curvescan/raster/mask.h"

#include <algorithm>

namespace curvescan {

void ClipMask::write_spans(std::span<const Span> spans) noexcept {
  for (const Span& span : spans) {
    if (span.coverage == 0 || span.len <= 0) continue;
    std::fill_n(values_.begin() + static_cast<std::ptrdiff_t>(index(span.x, span.y)), span.len,
                span.coverage);
    const IntRect run{span.x, span.y, span.x + span.len, span.y + 1};
    bounds_ = bounds_.empty() ? run
                              : IntRect{std::min(bounds_.x0, run.x0), std::min(bounds_.y0, run.y0),
                                        std::max(bounds_.x1, run.x1), std::max(bounds_.y1, run.y1)};
  }
}

ClipMask ClipMask::from_values(int width, int height, std::vector<std::uint8_t> values) {
  ClipMask mask(width, height);
  if (values.size() != mask.values_.size()) return mask;
  mask.values_ = std::move(values);
  int x0 = width, y0 = height, x1 = 0, y1 = 0;
  for (int y = 0; y < height; ++y) {
    const std::uint8_t* row_values = mask.row(y);
    for (int x = 0; x < width; ++x) {
      if (row_values[x] == 0) continue;
      x0 = std::min(x0, x);
      x1 = std::max(x1, x + 1);
      y0 = std::min(y0, y);
      y1 = y + 1;
    }
  }
  mask.bounds_ = x0 < x1 ? IntRect{x0, y0, x1, y1} : IntRect{};
  return mask;
}

void ClipMask::intersect(const ClipMask& other) noexcept {
  const IntRect both{std::max(bounds_.x0, other.bounds_.x0), std::max(bounds_.y0, other.bounds_.y0),
                     std::min(bounds_.x1, other.bounds_.x1), std::min(bounds_.y1, other.bounds_.y1)};
  // Outside `both` one factor is 0, so the product is 0 there: clear what this mask had outside.
  for (int y = bounds_.y0; y < bounds_.y1; ++y) {
    std::uint8_t* row_values = values_.data() + index(0, y);
    const bool row_inside = y >= both.y0 && y < both.y1 && !both.empty();
    for (int x = bounds_.x0; x < bounds_.x1; ++x) {
      if (row_inside && x >= both.x0 && x < both.x1) {
        row_values[x] = multiply_coverage(row_values[x], other.at(x, y));
      } else {
        row_values[x] = 0;
      }
    }
  }
  bounds_ = both.empty() ? IntRect{} : both;
}

}  // namespace curvescan
