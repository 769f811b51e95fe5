// Reading a whole input file (or standard input for "-") with a size limit and a clear error.
// (Writing is output.h.)
#pragma once

#include <cstddef>
#include <string>

#include "curvescan/status.h"

namespace curvescan::cli {

/// Reads `path` ("-" = standard input) into memory; refuses inputs larger than `max_bytes`.
Result<std::string> read_input(const std::string& path, std::size_t max_bytes);

}  // namespace curvescan::cli
