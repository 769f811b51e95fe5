// WebP decoding for <image> (libwebp; RFC 9649): lossy and lossless images, with or without alpha, to
// premultiplied RGBA8. A still image goes through libwebp's simple decoding API; of an animated one
// libwebpdemux finds the first frame, which is decoded at its offset onto the transparent canvas (RFC 9649
// 2.7): an animated image shows its first frame, as an animated GIF does (gif_decode.h), SVG 2 "The image
// element" allowing a still image. Either way the one buffer is the returned image.
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

/// Decodes `bytes` (an animation: its first frame on its canvas); `*animated`, when given, is set to whether
/// the file is an animation. kCorruptInput for a broken file; kLimitExceeded, before pixel memory is
/// allocated, beyond `max_pixels` or kMaxImageDimension per side.
[[nodiscard]] Result<Image> decode_webp(std::span<const std::uint8_t> bytes, std::int64_t max_pixels,
                                        bool* animated = nullptr);

}  // namespace curvescan::svg::detail
