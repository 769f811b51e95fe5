// Where a command's result goes: `-o PATH` or `-o -` for standard output. Every command writes through
// here, and here only through curvescan/raster/file_io.h, so all of them treat devices, FIFOs,
// symbolic links and existing files alike (README, "Output files").
#pragma once

#include <string>
#include <string_view>

#include "curvescan/raster/image.h"
#include "curvescan/status.h"

namespace curvescan::cli {

/// Writes `bytes` to `path`, or to standard output when `path` is "-".
[[nodiscard]] Status write_output(const std::string& path, std::string_view bytes);

/// Encodes `image` as PNG in memory, then writes it as write_output does. Nothing is written when the
/// encoding fails.
[[nodiscard]] Status write_png_output(const std::string& path, const Image& image);

}  // namespace curvescan::cli
