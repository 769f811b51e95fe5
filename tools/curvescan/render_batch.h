// `curvescan render FILE... --output-dir DIR`: many documents in one process, on a pool of threads.
//
// Each input FILE becomes DIR/NAME.png, NAME being the file's name without its .svg/.svgz extension; two
// inputs that would write the same output are refused before anything is rendered. A failing file is
// reported (one line naming it) and does not stop the others; the exit code is 3 when any failed. On a
// terminal, a progress line shows the count, the rate and the time left (not with -q, not when stderr is
// not a terminal). --manifest writes one JSON line per input, in input order, when all are done.
#pragma once

#include <string>
#include <vector>

#include "render_file.h"

namespace curvescan::cli {

struct BatchOptions {
  std::vector<std::string> inputs;
  std::string files_from;  ///< a file of input names, one a line ("-" = standard input); empty = none
  std::string output_dir;
  std::string manifest;  ///< JSON Lines file; empty = none
  unsigned jobs = 0;     ///< 0 = the number of cores
  bool verbose = false;
  bool quiet = false;
};

/// Renders every input; returns the exit code (kExitOk, kExitError, or kExitUsage for a bad list).
[[nodiscard]] int run_render_batch(const BatchOptions& options, const RenderSettings& settings);

}  // namespace curvescan::cli
