// Directory mode of `curvescan diff`: pair two trees of PNG files by relative path, compare every pair on
// a pool of threads, and write the HTML report, a JSON summary and JUnit XML (docs/diff.md, "Directory
// mode").
#pragma once

#include <cstdint>
#include <filesystem>

#include "curvescan/diff/image_diff.h"

namespace curvescan::cli {

struct DirectoryDiffOptions {
  std::filesystem::path expected_dir;
  std::filesystem::path actual_dir;
  std::filesystem::path report_dir;
  /// After the report: copy the actual file over the expected one for every failed and new entry.
  bool update = false;
  /// Worker threads; 0 = std::thread::hardware_concurrency().
  unsigned jobs = 0;
  /// Print one line per file that did not pass (at most this many; the report lists them all).
  std::size_t max_listed = 50;
  DiffOptions diff;
  /// Largest PNG file read, in MiB (--max-input-size); a larger one is an error entry.
  std::int64_t max_input_mib = 64;
  /// Memory for the images in MiB (--max-memory), shared by the worker threads (diff_max_pixels).
  std::int64_t max_memory_mib = 1024;
  /// The worker threads actually run; set by run_directory_diff from `jobs`.
  unsigned workers = 1;
};

/// Runs the whole directory mode and returns the exit code: 0 all passed, 1 some failed/new/missing
/// (after --update only the missing ones count), 3 a file could not be read or the report not written.
int run_directory_diff(const DirectoryDiffOptions& options);

}  // namespace curvescan::cli
