// The pixel size an image file declares in its header, read before anything is decoded, so that the
// memory its pixels will take can be checked against the render's budget first: a file of a few hundred
// bytes may declare 30000 x 30000 pixels (an "image bomb", 3.4 GiB of RGBA8).
#pragma once

#include <cstdint>
#include <optional>
#include <span>

#include "image_source.h"

namespace curvescan::svg::detail {

struct ImageDimensions {
  std::int64_t width = 0;
  std::int64_t height = 0;
};

/// PNG: the width and height of the IHDR chunk, which the PNG specification (ISO/IEC 15948, 5.6) puts
/// first, right after the 8-byte signature. JPEG: the frame header as libjpeg reads it (jpeg_decode.h).
/// nullopt for other formats and for a header too short or malformed to say (the decoder then reports
/// what is wrong).
[[nodiscard]] std::optional<ImageDimensions> declared_dimensions(std::span<const std::uint8_t> bytes,
                                                                 ImageFormat format);

}  // namespace curvescan::svg::detail
