// An output path that names one of the command's input files: refused before any work, so that
// `curvescan curve spec.json -o spec.json` or `curvescan diff a.png b.png -o a.png` cannot replace the
// input the user meant to keep with the result (docs/limits.md, "Output files").
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace curvescan::cli {

/// The first of `inputs` that is the same file as `output` (the same device and inode, so a hard link, a
/// symbolic link or another spelling of the path counts), or nothing. "-" and paths that do not exist
/// never match, nor does an output that is not a regular file (a device or FIFO is written through, not
/// replaced).
std::optional<std::string> input_named_by_output(const std::string& output,
                                                 const std::vector<std::string>& inputs);

/// The usage message for that case: "the output 'OUT' is the input 'IN'; ...".
std::string output_is_input_message(const std::string& output, const std::string& input);

}  // namespace curvescan::cli
