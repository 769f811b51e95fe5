// JPEG decoding for <image> (libjpeg-turbo's libjpeg API): baseline and progressive JPEG, greyscale, RGB
// and CMYK/YCCK (Adobe's inverted CMYK, as Photoshop writes it) to opaque RGBA8.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <utility>

#include "curvescan/raster/image.h"
#include "curvescan/status.h"

namespace curvescan::svg::detail {

/// Decodes `bytes`. kCorruptInput with libjpeg's message for a broken file; kLimitExceeded, before any
/// pixel memory is allocated, beyond `max_pixels` or kMaxImageDimension per side.
[[nodiscard]] Result<Image> decode_jpeg(std::span<const std::uint8_t> bytes, std::int64_t max_pixels);

/// The width and height decode_jpeg would give `bytes` (its frame header, read by libjpeg, nothing
/// decoded), or nullopt when the header cannot be read.
[[nodiscard]] std::optional<std::pair<std::int64_t, std::int64_t>> jpeg_dimensions(
    std::span<const std::uint8_t> bytes);

}  // namespace curvescan::svg::detail
