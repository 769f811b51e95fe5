// Reading a whole input file (or standard input for "-") with a size limit and a clear error.
// (Writing is output.h.)
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "curvescan/raster/image.h"
#include "curvescan/raster/limits.h"
#include "curvescan/status.h"

namespace curvescan::cli {

/// Reads `path` ("-" = standard input) into memory; refuses inputs larger than `max_bytes`. At most
/// `max_bytes` plus one buffer are read, whatever `path` is (a regular file, a FIFO, a device such as
/// /dev/zero), and a regular file already larger is refused from its size before reading.
Result<std::string> read_input(const std::string& path, std::size_t max_bytes);

/// Reads the PNG file `path` ("-" = standard input) as read_input does and decodes it from memory
/// (decode_png, png_io.h); every message names the file.
/// `max_pixels` bounds the decoded image (refused from its header, before the pixels are allocated);
/// `pixel_limit_hint`, when not empty and `max_pixels` is below kMaxImagePixels, is added to that error to
/// name the flag that raises the bound.
Result<Image> read_png_input(const std::string& path, std::size_t max_bytes,
                             std::int64_t max_pixels = kMaxImagePixels, const std::string& pixel_limit_hint = {});

/// Writes `text` to `path` ("-" = standard output) through a temporary file and a rename, so a failure
/// leaves no partial file and does not touch an existing one.
}  // namespace curvescan::cli
