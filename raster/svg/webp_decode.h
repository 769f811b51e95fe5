// WebP decoding for <image> (libwebp's simple decoding API; RFC 9649): still lossy and lossless images,
// with or without alpha, to premultiplied RGBA8. An animated WebP is refused with a message (libwebp's
// simple API decodes no animation, and its demux library is not used).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <utility>

#include "curvescan/raster/image.h"
#include "curvescan/status.h"

namespace curvescan::svg::detail {

/// Whether `bytes` begin with a WebP container: "RIFF", a 4-byte size, "WEBP" (RFC 9649 2.5).
[[nodiscard]] bool is_webp(std::span<const std::uint8_t> bytes) noexcept;

/// The width and height libwebp reads from the headers (nothing decoded), or nullopt.
[[nodiscard]] std::optional<std::pair<std::int64_t, std::int64_t>> webp_dimensions(
    std::span<const std::uint8_t> bytes) noexcept;

/// Decodes `bytes`. kCorruptInput for a broken or animated file; kLimitExceeded, before pixel memory is
/// allocated, beyond `max_pixels` or kMaxImageDimension per side.
[[nodiscard]] Result<Image> decode_webp(std::span<const std::uint8_t> bytes, std::int64_t max_pixels);

}  // namespace curvescan::svg::detail
