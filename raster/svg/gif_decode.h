// GIF decoding for <image> (giflib; GIF89a specification, W3C/CompuServe 1990): the first image of the
// file, composited onto its logical screen, which starts transparent. Indices in the colour table of the
// image (or the global one) become opaque colours; the transparent index of the Graphic Control Extension
// before the image stays transparent. An animated GIF shows its first frame, as a still image in SVG (SVG 2
// "The image element": animated raster images may show their first frame only).
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <utility>

#include "curvescan/raster/image.h"
#include "curvescan/status.h"

namespace curvescan::svg::detail {

/// Whether `bytes` begin with a GIF signature, "GIF87a" or "GIF89a".
[[nodiscard]] bool is_gif(std::span<const std::uint8_t> bytes) noexcept;

/// The logical screen's width and height, from the 13-byte header (nothing decoded), or nullopt when the
/// header is too short.
[[nodiscard]] std::optional<std::pair<std::int64_t, std::int64_t>> gif_dimensions(
    std::span<const std::uint8_t> bytes) noexcept;

/// Decodes the first image of `bytes` onto the logical screen; `*animated`, when given, is set to whether
/// another image follows it (the records after the first image are read up to the next image descriptor,
/// none of its data). kCorruptInput with giflib's message for a broken file or one without an image;
/// kLimitExceeded, before pixel memory is allocated, beyond `max_pixels` or kMaxImageDimension per side.
[[nodiscard]] Result<Image> decode_gif(std::span<const std::uint8_t> bytes, std::int64_t max_pixels,
                                       bool* animated = nullptr);

}  // namespace curvescan::svg::detail
