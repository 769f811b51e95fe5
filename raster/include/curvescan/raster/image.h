// Image: an RGBA8 raster, premultiplied alpha, rows top to bottom.
//
// Byte order in memory is R, G, B, A for every pixel (not Cairo's native-endian ARGB32 word; see
// to_cairo_argb32()/from_cairo_argb32() in cairo_interop.h of the tests and tools). Colour channels are
// premultiplied by alpha: a pixel (r, g, b, a) always has r, g, b <= a.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "curvescan/raster/zeroed_memory.h"

namespace curvescan {

/// One premultiplied RGBA8 pixel.
struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 0;
  bool operator==(const Rgba8&) const = default;
};

/// An image's pixels, row-major: a std::vector whose size stays width · height.
/// Zeroed memory (zeroed_memory.h): a new image costs no pass over its pixels, and a canvas's rows are
/// cleared by the bands that first draw them. Rgba8{} is all zero bytes.
using PixelVector = std::vector<Rgba8, ZeroedAllocator<Rgba8>>;

class Image {
 public:
  Image() = default;
  /// A transparent width x height image. Callers check sizes against their limits first
  /// (the canvas size limit is documented in limits.h).
  Image(int width, int height)
      : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {}

  [[nodiscard]] int width() const noexcept { return width_; }
  [[nodiscard]] int height() const noexcept { return height_; }
  [[nodiscard]] bool empty() const noexcept { return pixels_.empty(); }
  [[nodiscard]] Rgba8& at(int x, int y) noexcept { return pixels_[index(x, y)]; }
  [[nodiscard]] const Rgba8& at(int x, int y) const noexcept { return pixels_[index(x, y)]; }
  [[nodiscard]] Rgba8* row(int y) noexcept { return pixels_.data() + index(0, y); }
  [[nodiscard]] const Rgba8* row(int y) const noexcept { return pixels_.data() + index(0, y); }
  [[nodiscard]] PixelVector& pixels() noexcept { return pixels_; }
  [[nodiscard]] const PixelVector& pixels() const noexcept { return pixels_; }

  bool operator==(const Image&) const = default;

 private:
  [[nodiscard]] std::size_t index(int x, int y) const noexcept {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  }
  int width_ = 0;
  int height_ = 0;
  PixelVector pixels_;
};

/// The memory the pixels of a width x height Image take, as the render budget counts it (limits.h): a
/// large block is rounded up to whole huge pages, which are resident once written (zeroed_memory.h).
/// Sizes too large for any budget give 2^60 rather than overflowing.
[[nodiscard]] inline std::int64_t image_memory_bytes(std::int64_t width, std::int64_t height) noexcept {
  constexpr std::int64_t kBeyondAnyBudget = std::int64_t{1} << 60;
  if (width <= 0 || height <= 0) return 0;
  if (width > kBeyondAnyBudget / static_cast<std::int64_t>(sizeof(Rgba8)) / height) return kBeyondAnyBudget;
  return static_cast<std::int64_t>(
      zeroed_block_bytes(static_cast<std::size_t>(width * height) * sizeof(Rgba8)));
}

}  // namespace curvescan
