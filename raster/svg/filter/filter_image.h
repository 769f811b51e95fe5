// The pixels every filter primitive reads and writes (Filter Effects 1, section 9): an image in the filter's
// pixel space, premultiplied RGBA with float channels in [0, 1], rows top to bottom.
//
// Float rather than 8-bit: primitives chain (a blur feeds a colour matrix feeds a composite), and rounding
// after each step would compound; the arithmetic of feComposite, the lighting and the linearRGB <-> sRGB
// conversions is written in real numbers by the specification. The renderer converts to 8-bit once, at the
// end of the chain. A FilterImage only ever holds the filter region, which the renderer bounds by the same
// pixel limit as the canvas (filter_region.h), so 16 bytes a pixel stays within --max-memory.
//
// The channels live in memory that starts zero (curvescan/raster/zeroed_memory.h), and `extent` says where
// the ink can be, so that the filter graph computes each primitive only there (filter_graph.h).
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "curvescan/raster/zeroed_memory.h"

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
  /// The smallest rectangle holding both (an empty one adds nothing).
  [[nodiscard]] constexpr PixelRect unite(const PixelRect& other) const noexcept {
    if (empty()) return other;
    if (other.empty()) return *this;
    return {std::min(x0, other.x0), std::min(y0, other.y0), std::max(x1, other.x1), std::max(y1, other.y1)};
  }
  /// Grown by `dx` columns left and right and `dy` rows above and below (>= 0; huge values saturate).
  [[nodiscard]] constexpr PixelRect grown(long long dx, long long dy) const noexcept {
    if (empty()) return *this;
    return {saturate(x0 - dx), saturate(y0 - dy), saturate(x1 + dx), saturate(y1 + dy)};
  }
  /// Moved by (dx, dy) pixels (huge values saturate).
  [[nodiscard]] constexpr PixelRect moved(long long dx, long long dy) const noexcept {
    if (empty()) return *this;
    return {saturate(x0 + dx), saturate(y0 + dy), saturate(x1 + dx), saturate(y1 + dy)};
  }
  constexpr bool operator==(const PixelRect&) const noexcept = default;

 private:
  // Coordinates stay within +-2^30, far outside any image and far from overflow.
  static constexpr int saturate(long long v) noexcept {
    constexpr long long kLimit = 1LL << 30;
    return static_cast<int>(std::clamp(v, -kLimit, kLimit));
  }
};

/// The channels of a filter image, or a plane of one channel: zero when made.
using FilterPixels = std::vector<float, ZeroedAllocator<float>>;

/// Premultiplied RGBA, 4 floats a pixel, in [0, 1] with colour <= alpha.
struct FilterImage {
  int width = 0;
  int height = 0;
  FilterPixels rgba;  ///< 4 * width * height floats, pixel (x, y) at 4 * (y * width + x)
  /// Every pixel outside this rectangle is transparent black (inside, some may be too). Whoever writes
  /// pixels directly leaves it at the whole image; the filter graph narrows it to the ink it computes.
  PixelRect extent;

  FilterImage() = default;
  /// A transparent black image of width x height pixels (both >= 0; the caller has bounded their product).
  FilterImage(int w, int h)
      : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4), extent{0, 0, w, h} {}

  [[nodiscard]] PixelRect bounds() const noexcept { return {0, 0, width, height}; }
  [[nodiscard]] float* pixel(int x, int y) noexcept {
    return rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x);
  }
  [[nodiscard]] const float* pixel(int x, int y) const noexcept {
    return rgba.data() + 4 * (static_cast<std::size_t>(y) * width + x);
  }
};

// Zeroes every pixel of `image` outside `keep` (only inside its extent: the rest is zero already) and
// narrows the extent to `keep`.
inline void clear_outside(FilterImage& image, PixelRect keep) {
  const PixelRect dirty = image.extent.intersect(image.bounds());
  for (int y = dirty.y0; y < dirty.y1; ++y) {
    if (y < keep.y0 || y >= keep.y1 || keep.empty()) {
      std::fill(image.pixel(dirty.x0, y), image.pixel(dirty.x1, y), 0.0f);
      continue;
    }
    if (dirty.x0 < keep.x0)
      std::fill(image.pixel(dirty.x0, y), image.pixel(std::min(keep.x0, dirty.x1), y), 0.0f);
    if (dirty.x1 > keep.x1)
      std::fill(image.pixel(std::max(keep.x1, dirty.x0), y), image.pixel(dirty.x1, y), 0.0f);
  }
  image.extent = dirty.intersect(keep);
}

}  // namespace curvescan::svg::detail::filter
