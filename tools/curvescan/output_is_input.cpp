#include "output_is_input.h"

#include <sys/stat.h>

namespace curvescan::cli {

std::optional<std::string> input_named_by_output(const std::string& output,
                                                 const std::vector<std::string>& inputs) {
  if (output.empty() || output == "-") return std::nullopt;
  struct stat out {};
  // stat follows symbolic links, as the writer does (it writes a link's target): a link to an input is
  // that input.
  // Only a regular file is replaced; a device or FIFO named twice (/dev/null) is written through.
  if (::stat(output.c_str(), &out) != 0 || !S_ISREG(out.st_mode)) return std::nullopt;
  for (const std::string& input : inputs) {
    if (input.empty() || input == "-") continue;
    struct stat in {};
    if (::stat(input.c_str(), &in) == 0 && in.st_dev == out.st_dev && in.st_ino == out.st_ino) return input;
  }
  return std::nullopt;
}

std::string output_is_input_message(const std::string& output, const std::string& input) {
  const std::string same = output == input
                               ? "the output '" + output + "' is also an input"
                               : "the output '" + output + "' is the same file as the input '" + input + "'";
  return same + "; writing it would replace the input: name another output file";
}

}  // namespace curvescan::cli
