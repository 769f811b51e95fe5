#include "limit_options.h"
#include "option_range.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <system_error>

namespace curvescan::cli {

void add_input_size_option(CLI::App& command, std::int64_t& max_input_mib) {
  command
      .add_option("--max-input-size", max_input_mib,
                  "largest input file in MiB, 1 to " + std::to_string(kLargestInputMiB))
      ->type_name("MiB")
      ->check(number_in_range(std::int64_t{1}, kLargestInputMiB))
      ->capture_default_str();
}

void add_render_limit_options(CLI::App& command, RenderLimitOptions& limits, bool with_dashes) {
  command
      .add_option("--max-segments", limits.max_segments,
                  "most line segments the drawing may flatten to, over the whole render, 1 to " +
                      std::to_string(kLargestSegmentBudget))
      ->type_name("N")
      ->check(number_in_range(std::int64_t{1}, kLargestSegmentBudget))
      ->capture_default_str();
  command
      .add_option("--max-memory", limits.max_memory_mib,
                  "memory budget of the render in MiB (canvas, layers, clip masks, edges), 1 to " +
                      std::to_string(kLargestMemoryMiB))
      ->type_name("MiB")
      ->check(number_in_range(std::int64_t{1}, kLargestMemoryMiB))
      ->capture_default_str();
  if (with_dashes) {
    command
        .add_option("--max-dashes", limits.max_dashes,
                    "most dashes one stroke may make, 1 to " + std::to_string(kMaxDashSegments))
        ->type_name("N")
        ->check(number_in_range(std::int64_t{1}, kMaxDashSegments))
        ->capture_default_str();
  }
}

std::size_t input_size_bytes(std::int64_t max_input_mib) noexcept {
  return static_cast<std::size_t>(max_input_mib) << 20;
}

Error input_too_large(const std::string& name, std::size_t max_bytes) {
  return Error{ErrorKind::kLimitExceeded, "input '" + name + "' is larger than the input size limit of " +
                                              std::to_string(max_bytes >> 20) +
                                              " MiB (raise --max-input-size)"};
}

Status check_input_file(const std::string& path, std::int64_t max_input_mib) {
  std::error_code error;
  if (std::filesystem::is_directory(path, error)) {
    return Error{ErrorKind::kIoError, "cannot read '" + path + "': it is a directory"};
  }
  if (!std::filesystem::is_regular_file(path, error)) return Status::ok();
  const std::uintmax_t size = std::filesystem::file_size(path, error);
  if (!error && size > input_size_bytes(max_input_mib)) return input_too_large(path, input_size_bytes(max_input_mib));
  return Status::ok();
}

std::int64_t diff_max_pixels(std::int64_t max_memory_mib, unsigned workers) noexcept {
  const std::int64_t bytes = max_memory_mib << 20;
  return std::min(kMaxImagePixels, bytes / (kDiffBytesPerPixel * std::max<std::int64_t>(1, workers)));
}

std::string diff_memory_hint(std::int64_t max_memory_mib, unsigned workers) {
  return "the memory limit of " + std::to_string(max_memory_mib) + " MiB" +
         (workers > 1 ? " over " + std::to_string(workers) + " worker threads" : std::string()) + " allows " +
         std::to_string(diff_max_pixels(max_memory_mib, workers)) +
         " pixels an image (raise --max-memory" + (workers > 1 ? ", or lower --jobs)" : ")");
}

}  // namespace curvescan::cli
