// PNG input and output through libpng, in memory and in files.
//
// encode_png makes the bytes of a PNG file (unpremultiplied RGBA8, 8 bits per channel) in memory;
// write_png writes those bytes through write_output_file (file_io.h): a regular file is replaced
// atomically, a device or pipe is written through, and a failure never leaves a partial file nor touches
// an existing one. decode_png accepts anything
// libpng can convert to 8-bit RGBA (palette, grey, 16-bit, with or without alpha, interlaced) and
// returns it premultiplied; read_png reads a file (of any kind: regular, FIFO, device) with a size bound
// and decodes it. A truncated or corrupt PNG is an Error with a message, never a crash.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "curvescan/raster/image.h"
#include "curvescan/raster/limits.h"
#include "curvescan/status.h"

namespace curvescan {

/// Largest file read_png reads by default, in bytes. The largest image it may hold (kMaxImagePixels of
/// RGBA8 = 256 MiB) stored without compression adds one filter byte per row and 5 bytes per 64 KiB
/// deflate block, well under 512 MiB; anything larger cannot be a PNG curvescan would accept.
inline constexpr std::size_t kMaxPngFileBytes = std::size_t{512} << 20;

/// The bytes of a PNG file of `image` (8-bit RGBA, not interlaced). kInvalidArgument for an empty
/// image, kLimitExceeded beyond kMaxImagePixels, kIoError when memory runs out.
[[nodiscard]] Result<std::vector<std::uint8_t>> encode_png(const Image& image);

/// Decodes the PNG file held in `bytes`. kCorruptInput for empty, non-PNG, truncated or corrupt data
/// (the message says which), kLimitExceeded when the header declares more than `max_pixels` pixels or
/// more than kMaxImageDimension per side — refused before any pixel memory is allocated. `max_pixels`
/// is at most kMaxImagePixels (a larger value is treated as kMaxImagePixels). Messages do not name a
/// file: callers prefix one.
[[nodiscard]] Result<Image> decode_png(std::span<const std::uint8_t> bytes,
                                       std::int64_t max_pixels = kMaxImagePixels);

[[nodiscard]] Status write_png(const Image& image, const std::filesystem::path& path);

/// Reads at most `max_file_bytes` + 1 bytes of `path` (a regular file, FIFO or device alike) and
/// decodes them with decode_png; messages start with "cannot read 'path'". kLimitExceeded when the file
/// is longer than `max_file_bytes`, kIoError when it cannot be opened or read.
[[nodiscard]] Result<Image> read_png(const std::filesystem::path& path,
                                     std::size_t max_file_bytes = kMaxPngFileBytes);

}  // namespace curvescan
