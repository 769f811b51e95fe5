// PNG input and output through libpng.
//
// write_png writes unpremultiplied RGBA8 to a temporary file beside `path` and renames it over `path`, so
// a failure never leaves a partial file and never touches an existing one. read_png accepts anything
// libpng can convert to 8-bit RGBA (palette, grey, 16-bit, with or without alpha, interlaced) and
// returns it premultiplied; a truncated or corrupt file is an Error with a message, never a crash.
#pragma once

#include <filesystem>

#include "curvescan/raster/image.h"
#include "curvescan/status.h"

namespace curvescan {

[[nodiscard]] Status write_png(const Image& image, const std::filesystem::path& path);
[[nodiscard]] Result<Image> read_png(const std::filesystem::path& path);

}  // namespace curvescan
