// Resolving `curvescan text --font FILE|FAMILY`: a font file when the argument names one, else a
// fontconfig family lookup that must find the family (no silent fallback on the command line).
#pragma once

#include <string>

#include "curvescan/status.h"
#include "curvescan/text/font.h"

namespace curvescan::cli {

/// Opens `file_or_family`: a path that exists is opened as a font file (Font::open: a device, FIFO or
/// socket is refused as not a font file); an argument that looks
/// like a path (contains '/' or ends in a font file extension) but does not exist is a missing file;
/// anything else is a CSS family list looked up through fontconfig at `weight` and `italic`.
[[nodiscard]] Result<Font> open_font_argument(const std::string& file_or_family, int weight, bool italic);

}  // namespace curvescan::cli
