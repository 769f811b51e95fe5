// Image sizes from file headers (image_dimensions.h).
#include "image_dimensions.h"

#include <array>
#include <cstring>

#include "gif_decode.h"
#include "jpeg_decode.h"
#include "webp_decode.h"

namespace curvescan::svg::detail {
namespace {

std::int64_t big_endian_32(const std::uint8_t* p) noexcept {
  return (std::int64_t{p[0]} << 24) | (std::int64_t{p[1]} << 16) | (std::int64_t{p[2]} << 8) | p[3];
}

// Signature (8 bytes), then the IHDR chunk: length (4), type "IHDR" (4), width (4), height (4).
std::optional<ImageDimensions> png_dimensions(std::span<const std::uint8_t> bytes) noexcept {
  static constexpr std::array<std::uint8_t, 8> kSignature{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() < 24 || std::memcmp(bytes.data(), kSignature.data(), kSignature.size()) != 0 ||
      std::memcmp(bytes.data() + 12, "IHDR", 4) != 0)
    return std::nullopt;
  return ImageDimensions{big_endian_32(bytes.data() + 16), big_endian_32(bytes.data() + 20)};
}

}  // namespace

std::optional<ImageDimensions> declared_dimensions(std::span<const std::uint8_t> bytes, ImageFormat format) {
  if (format == ImageFormat::kPng) return png_dimensions(bytes);
  if (format == ImageFormat::kJpeg) {
    const std::optional<std::pair<std::int64_t, std::int64_t>> size = jpeg_dimensions(bytes);
    if (size) return ImageDimensions{size->first, size->second};
  }
  if (format == ImageFormat::kGif) {
    if (const auto size = gif_dimensions(bytes)) return ImageDimensions{size->first, size->second};
  }
  if (format == ImageFormat::kWebp) {
    if (const auto size = webp_dimensions(bytes)) return ImageDimensions{size->first, size->second};
  }
  return std::nullopt;
}

}  // namespace curvescan::svg::detail
