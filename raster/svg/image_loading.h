// The pixels of an <image> or <feImage> file: its bytes loaded (image_source.h) and inflated when they are
// gzip-compressed (svgz, SVG 2 1.2.2), then a PNG, JPEG, GIF or WebP decoded into RGBA8. Both steps stay
// within what the render's memory budget has left (limits.h): the bytes are held while they decode, and
// the size a file's header declares is checked before its pixels are allocated, so a small file declaring
// a huge image (an "image bomb") is refused without allocating it.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "curvescan/raster/image.h"
#include "curvescan/status.h"
#include "image_source.h"

namespace curvescan::svg::detail {

/// The bytes `href` refers to (image_source.h), at most `memory_left` of them and never more than the image
/// file size limit (kMaxPngFileBytes); gzip-compressed bytes are inflated within the same bound, and an
/// inflation error is the reason the image is refused.
[[nodiscard]] ImageBytes load_image_bytes(std::string_view href,
                                          const std::optional<std::filesystem::path>& resource_directory,
                                          std::int64_t memory_left);

/// `bytes` of a raster `format` decoded into pixels (4 bytes each), which must fit in `memory_left` less
/// `held` (the memory the caller keeps meanwhile, the file's bytes): kLimitExceeded, before anything is
/// decoded, when they do not, or when the image has more than `max_pixels`; the decoder's error for a
/// broken file. An animated GIF or WebP gives its first frame, and `*animated` (when given) says it was one.
[[nodiscard]] Result<Image> decode_image_within_budget(const std::vector<std::uint8_t>& bytes,
                                                       ImageFormat format, std::int64_t memory_left,
                                                       std::int64_t held, std::int64_t max_pixels,
                                                       bool* animated = nullptr);

}  // namespace curvescan::svg::detail
