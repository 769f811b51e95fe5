// Reading a whole input file (or standard input for "-") with a size limit and a clear error.
#pragma once

#include <cstddef>
#include <string>

#include "curvescan/status.h"

namespace curvescan::cli {

/// Reads `path` ("-" = standard input) into memory; refuses inputs larger than `max_bytes`.
Result<std::string> read_input(const std::string& path, std::size_t max_bytes);

/// Writes `text` to `path` ("-" = standard output) through a temporary file and a rename, so a failure
/// leaves no partial file and does not touch an existing one.
Status write_output_atomically(const std::string& path, const std::string& text);

}  // namespace curvescan::cli
