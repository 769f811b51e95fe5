// Conversions between curvescan's premultiplied RGBA8 bytes and the other pixel layouts it meets:
// Cairo/pixman's native-endian premultiplied ARGB32 word, and straight (unpremultiplied) RGBA for PNG.
#pragma once

#include <cstdint>

#include "curvescan/raster/image.h"

namespace curvescan {

/// Cairo's CAIRO_FORMAT_ARGB32 word: alpha in the top byte, premultiplied, native endian.
[[nodiscard]] constexpr std::uint32_t to_argb32(Rgba8 p) noexcept {
  return (std::uint32_t{p.a} << 24) | (std::uint32_t{p.r} << 16) | (std::uint32_t{p.g} << 8) | p.b;
}
[[nodiscard]] constexpr Rgba8 from_argb32(std::uint32_t word) noexcept {
  return {static_cast<std::uint8_t>(word >> 16), static_cast<std::uint8_t>(word >> 8),
          static_cast<std::uint8_t>(word), static_cast<std::uint8_t>(word >> 24)};
}

/// x·a/255 rounded to nearest for x, a in [0, 255], exactly: pixman's and Cairo's MUL_UN8, the one
/// product every compositing step and premultiply() share so that they round alike.
[[nodiscard]] constexpr std::uint8_t mul_un8(unsigned x, unsigned a) noexcept {
  const unsigned t = x * a + 128u;
  return static_cast<std::uint8_t>((t + (t >> 8)) >> 8);
}

/// Straight-alpha RGBA8, as PNG stores it.
struct StraightRgba8 {
  std::uint8_t r = 0, g = 0, b = 0, a = 0;
  bool operator==(const StraightRgba8&) const = default;
};

/// Premultiplies with correct rounding: c·a/255 rounded to nearest (pixman's MUL_UN8).
[[nodiscard]] Rgba8 premultiply(StraightRgba8 p) noexcept;
/// Unpremultiplies with correct rounding: c·255/a rounded to nearest, clamped to 255; a = 0 gives 0.
[[nodiscard]] StraightRgba8 unpremultiply(Rgba8 p) noexcept;

}  // namespace curvescan
