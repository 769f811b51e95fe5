// The pixels every filter primitive reads and writes (Filter Effects 1, section 9): an image in the filter's
// pixel space, premultiplied RGBA with float channels in [0, 1], rows top to bottom.
//
// Float rather than 8-bit: primitives chain (a blur feeds a colour matrix feeds a composite), and rounding
// after each step would compound; the arithmetic of feComposite, the lighting and the linearRGB <-> sRGB
// conversions is written in real numbers by the specification. The renderer converts to 8-bit once, at the
// end of the chain. A FilterImage only ever holds the filter region, which the renderer bounds by the same
// pixel limit as the canvas (filter_region.h), so 16 bytes a pixel stays within --max-memory.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace curvescan::svg::detail::filter {

/// A rectangle of whole pixels, half-open: x0 <= x < x1, y0 <= y < y1. Primitive subregions are PixelRects
/// of the filter image; nothing outside a primitive's subregion is written (it stays transparent black).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;

  [[nodiscard]] constexpr int width() const noexcept { return x1 > x0 ? x1 - x0 : 0; }
  [[nodiscard]] constexpr int height() const noexcept { return y1 > y0 ? y1 - y0 : 0; }
  [[nodiscard]] constexpr bool empty() const noexcept { return x1 <= x0 || y1 <= y0; }
  [[nodiscard]] constexpr bool contains(int x, int y) const noexcept {
    return x >= x0 && x < x1 && y >= y0 && y < y1;
  }
  /// The part of this rectangle inside `other`.
  [[nodiscard]] constexpr PixelRect intersect(const PixelRect& other) const noexcept {
    return {std::max(x0, other.x0), std::max(y0, other.y0), std::min(x1, other.x1), std::min(y1, other.y1)};
  }
  constexpr bool operator==(const PixelRect&) const noexcept = default;
};

/// Premultiplied RGBA, 4 floats a pixel, in [0, 1] with colour <= alpha.
struct FilterImage {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;  ///< 4 * width * height floats, pixel (x, y) at 4 * (y * width + x)

  FilterImage() = default;
  /// A transparent black image of width x height pixels (both >= 0; the caller has bounded their product).
  FilterImage(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0.0f) {}

  [[nodiscard]] PixelRect bounds() const noexcept { return {0, 0, width, height}; }
  [[nodiscard]] float* pixel(int x, int y) noexcept {
    return rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x);
  }
  [[nodiscard]] const float* pixel(int x, int y) const noexcept {
    return rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x);
  }
};

}  // namespace curvescan::svg::detail::filter
