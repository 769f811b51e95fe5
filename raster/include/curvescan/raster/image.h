// Image: an RGBA8 raster, premultiplied alpha, rows top to bottom.
//
// Byte order in memory is R, G, B, A for every pixel (not Cairo's native-endian ARGB32 word; see
// to_cairo_argb32()/from_cairo_argb32() in cairo_interop.h of the tests and tools). Colour channels are
// premultiplied by alpha: a pixel (r, g, b, a) always has r, g, b <= a.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <utility>
#include <vector>

namespace curvescan {

/// One premultiplied RGBA8 pixel.
struct Rgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 0;
  bool operator==(const Rgba8&) const = default;
};

/// The allocator of Image's pixels: zeroed memory from calloc, and value-initialising a pixel in it does
/// nothing. A large image is then fresh pages from the system (glibc's calloc maps them and skips the
/// clearing), and each page is cleared by the kernel when first written, on the thread that writes it:
/// the rows of a canvas are cleared by the bands that draw them, in parallel (Canvas::set_threads),
/// instead of all at once before drawing. Rgba8 is an aggregate, so a pixel exists in calloc's memory
/// without being constructed (C++20 [intro.object], implicit-lifetime types), and all its bytes are 0,
/// as Rgba8{} is. The vector's size is width · height for the image's life: growing it again after
/// shrinking would leave old values in the regrown pixels instead of zeros.
template <typename T>
struct ZeroedPixelAllocator {
  using value_type = T;
  ZeroedPixelAllocator() = default;
  template <typename U>
  ZeroedPixelAllocator(const ZeroedPixelAllocator<U>&) noexcept {}
  [[nodiscard]] T* allocate(std::size_t n) {
    if (void* memory = std::calloc(n, sizeof(T))) return static_cast<T*>(memory);
    throw std::bad_alloc();
  }
  void deallocate(T* p, std::size_t) noexcept { std::free(p); }
  /// Value-initialisation: the memory is already zero.
  template <typename U>
  void construct(U*) noexcept {}
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <typename U>
  bool operator==(const ZeroedPixelAllocator<U>&) const noexcept { return true; }
};

/// An image's pixels, row-major: a std::vector whose size stays width · height.
using PixelVector = std::vector<Rgba8, ZeroedPixelAllocator<Rgba8>>;

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

}  // namespace curvescan
