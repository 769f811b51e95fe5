// The limits every subcommand shares (docs/limits.md): the flags that raise them, their defaults, and
// the checks the library does not make itself (input file size). Each limit exceeded ends as one line on
// stderr naming the limit, its value and the flag, with exit code 3 (exit_codes.h).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "curvescan/raster/limits.h"
#include "curvescan/status.h"

namespace curvescan::cli {

/// Default largest input file (SVG, JSON spec, text, font, PNG) in MiB: far above any real document
/// (the tiger is 100 KiB), small enough that reading and parsing it stays within seconds and memory.
inline constexpr std::int64_t kDefaultMaxInputMiB = 64;
/// Default memory budget of one render in MiB (limits.h, kDefaultMaxRenderMemoryBytes).
inline constexpr std::int64_t kDefaultMaxMemoryMiB = kDefaultMaxRenderMemoryBytes >> 20;
/// The rasterizer numbers the edges of one fill with 32-bit indices (rasterizer_impl.h), so a segment
/// budget is accepted up to 2^31.
inline constexpr std::int64_t kLargestSegmentBudget = std::int64_t{1} << 31;

/// The footer of the help of a command with --max-* options.
inline constexpr const char* kLimitsHelp =
    "The --max-* options bound the time and memory one input may take; docs/limits.md explains each.";

/// The largest --max-input-size (MiB) and --max-memory (MiB) accepted.
inline constexpr std::int64_t kLargestInputMiB = std::int64_t{1} << 12;
inline constexpr std::int64_t kLargestMemoryMiB = std::int64_t{1} << 20;

/// The render limits as the command line gives them (memory in MiB).
struct RenderLimitOptions {
  std::int64_t max_segments = kDefaultMaxRenderSegments;
  std::int64_t max_memory_mib = kDefaultMaxMemoryMiB;
  std::int64_t max_dashes = kMaxDashSegments;

  [[nodiscard]] RenderLimits render_limits() const noexcept {
    return RenderLimits{max_segments, max_memory_mib << 20, max_dashes};
  }
};

/// Adds --max-input-size MiB to `command`.
void add_input_size_option(CLI::App& command, std::int64_t& max_input_mib);
/// Adds --max-segments, --max-memory and (when `with_dashes`) --max-dashes to `command`.
void add_render_limit_options(CLI::App& command, RenderLimitOptions& limits, bool with_dashes);

/// diff's memory: each comparison holds the expected, the actual and the diff image, 4 bytes a pixel
/// each, and, when pixels differ, two bytes a pixel to find the difference regions; directory mode runs
/// one comparison per worker thread.
inline constexpr std::int64_t kDiffBytesPerPixel = 3 * 4 + 2;
/// The largest image (pixels) a diff decodes within `max_memory_mib` shared by `workers` comparisons.
[[nodiscard]] std::int64_t diff_max_pixels(std::int64_t max_memory_mib, unsigned workers) noexcept;
/// The hint added to a diff image refused by diff_max_pixels, naming --max-memory.
[[nodiscard]] std::string diff_memory_hint(std::int64_t max_memory_mib, unsigned workers);

/// `max_input_mib` in bytes.
[[nodiscard]] std::size_t input_size_bytes(std::int64_t max_input_mib) noexcept;

/// Before a reader opens `path`: kIoError when it is a directory, kLimitExceeded when it is a file larger
/// than `max_input_mib` (the message names the limit and --max-input-size); OK otherwise (a missing or
/// unreadable file is reported by the reader).
[[nodiscard]] Status check_input_file(const std::string& path, std::int64_t max_input_mib);

/// The message of an input larger than the limit: "input 'NAME' is larger than the input size limit of N MiB
/// (raise --max-input-size)".
[[nodiscard]] Error input_too_large(const std::string& name, std::size_t max_bytes);

}  // namespace curvescan::cli
