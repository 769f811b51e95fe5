// PNG input and output through libpng.
//
// encode_png turns an Image into the bytes of an unpremultiplied RGBA8 PNG; write_png writes those bytes
// through write_output_file (output_file.h): a regular file is replaced atomically, a device or pipe is
// written through, and a failure never leaves a partial file nor touches an existing one. read_png accepts anything
// libpng can convert to 8-bit RGBA (palette, grey, 16-bit, with or without alpha, interlaced) and
// returns it premultiplied; a truncated or corrupt file is an Error with a message, never a crash.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "curvescan/raster/image.h"
#include "curvescan/status.h"

namespace curvescan {

[[nodiscard]] Result<std::vector<std::uint8_t>> encode_png(const Image& image);
[[nodiscard]] Status write_png(const Image& image, const std::filesystem::path& path);
[[nodiscard]] Result<Image> read_png(const std::filesystem::path& path);

}  // namespace curvescan
