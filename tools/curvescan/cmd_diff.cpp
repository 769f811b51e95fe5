// `curvescan diff`: compare two PNG images (pair mode) or two trees of PNG images (directory mode).
//
//   curvescan diff A.png B.png [-o DIFF.png] [--json] [thresholds...]
//   curvescan diff --expected DIR --actual DIR --report OUT/ [--update] [thresholds...]
//
// The comparison itself is the library's (curvescan/diff/image_diff.h); this file parses the command
// line, prints the metrics and maps the verdict to the exit codes of exit_codes.h. docs/diff.md is the
// user's documentation.
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "curvescan/diff/image_diff.h"
#include "curvescan/raster/png_io.h"
#include "diff_directory.h"
#include "diff_json.h"
#include "exit_codes.h"
#include "finite_number.h"
#include "input_file.h"
#include "limit_options.h"
#include "output.h"

namespace curvescan::cli {
namespace {

constexpr const char* kCommand = "diff";

constexpr const char* kExitCodeHelp =
    "Exit codes: 0 the same within tolerance (directory mode: every file passed), 1 different (directory "
    "mode: a file failed, is new or is missing), 2 the two images have different sizes (pair mode), 3 an "
    "error (unreadable, corrupt or too large file, I/O failure), 64 a malformed "
    "command line (an option out of its range, a missing or extra file, options of the other mode). "
    "See docs/diff.md.";

struct DiffCommandOptions {
  std::vector<std::string> images;
  std::string diff_output;
  bool json = false;
  double threshold = 0.1;
  int channel_tolerance = -1;  // -1: not given, the perceptual metric is used
  bool ignore_aa = false;
  std::vector<std::string> ignore;
  std::int64_t max_pixels = -1;
  double max_percent = -1.0;
  std::string expected_dir, actual_dir, report_dir;
  bool update = false;
  unsigned jobs = 0;
  std::int64_t max_input_mib = kDefaultMaxInputMiB;
  std::int64_t max_memory_mib = kDefaultMaxMemoryMiB;
};

/// Parses "x,y,w,h" (integers, w and h >= 0).
Result<PixelBox> parse_region(const std::string& text) {
  PixelBox box;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%d,%d,%d,%d%c", &box.x, &box.y, &box.width, &box.height, &tail) != 4 ||
      box.width < 0 || box.height < 0) {
    return Error{ErrorKind::kInvalidArgument,
                 "--ignore '" + text + "' must be x,y,w,h: four integers, the width and height >= 0"};
  }
  return box;
}

Result<DiffOptions> diff_options(const DiffCommandOptions& o) {
  DiffOptions options;
  if (o.channel_tolerance >= 0) {
    options.metric = PixelMetric::kPerChannel;
    options.channel_tolerance = o.channel_tolerance;
  } else {
    options.yiq_threshold = o.threshold;
  }
  options.ignore_antialiasing = o.ignore_aa;
  for (const std::string& text : o.ignore) {
    Result<PixelBox> box = parse_region(text);
    if (!box) return box.error();
    options.ignore_regions.push_back(*box);
  }
  if (o.max_pixels >= 0) options.max_different_pixels = static_cast<std::uint64_t>(o.max_pixels);
  if (o.max_percent >= 0.0) options.max_different_percent = o.max_percent;
  CURVESCAN_PROPAGATE(validate_diff_options(options));
  return options;
}

std::string format(double value, int decimals) {
  if (std::isinf(value)) return "inf";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

void print_text(const ImageComparison& c, const std::string& diff_output) {
  const DiffMetrics& m = c.metrics;
  std::ostringstream out;
  if (c.verdict == DiffVerdict::kSizeMismatch) {
    out << "size mismatch: expected " << m.expected_width << " x " << m.expected_height << ", actual "
        << m.actual_width << " x " << m.actual_height << "\n";
    std::cout << out.str();
    return;
  }
  out << (c.verdict == DiffVerdict::kSame ? "same" : "different") << "\n"
      << "size                " << m.expected_width << " x " << m.expected_height << "\n"
      << "differing pixels    " << m.different_pixels << " (" << format(m.different_percent, 4) << "%)\n"
      << "anti-aliasing       " << m.antialiased_pixels << "\n"
      << "changed pixels      " << m.changed_pixels << " of " << m.compared_pixels << " compared\n"
      << "max channel |delta| " << m.max_channel_delta << "\n"
      << "mean channel |delta|"
      << " " << format(m.mean_channel_delta, 4) << "\n"
      << "RMSE                " << format(m.rmse, 4) << "\n"
      << "PSNR                " << format(m.psnr, 2) << " dB\n";
  const PixelBox& b = m.difference_bounds;
  out << "differences in      ";
  if (b.empty()) {
    out << "none\n";
  } else {
    out << "x=" << b.x << " y=" << b.y << " w=" << b.width << " h=" << b.height << "\n";
  }
  if (!diff_output.empty()) out << "diff image          " << diff_output << "\n";
  std::cout << out.str();
}

int run_pair(const DiffCommandOptions& o, const DiffOptions& options) {
  // Each image is read with the --max-input-size bound whatever it is (a file, a FIFO, a device), then
  // decoded from memory.
  const std::size_t max_bytes = input_size_bytes(o.max_input_mib);
  const std::int64_t max_pixels = diff_max_pixels(o.max_memory_mib, 1);
  const std::string hint = diff_memory_hint(o.max_memory_mib, 1);
  const Result<Image> expected = read_png_input(o.images[0], max_bytes, max_pixels, hint);
  if (!expected) return report_error(kCommand, expected.error());
  const Result<Image> actual = read_png_input(o.images[1], max_bytes, max_pixels, hint);
  if (!actual) return report_error(kCommand, actual.error());
  DiffOptions with_image = options;
  with_image.make_diff_image = !o.diff_output.empty();
  const Result<ImageComparison> comparison = compare_images(*expected, *actual, with_image);
  if (!comparison) return report_error(kCommand, comparison.error());

  const bool write_diff = !o.diff_output.empty() && !comparison->diff_image.empty();
  if (write_diff) {
    if (const Status s = write_png_output(o.diff_output, comparison->diff_image); !s)
      return report_error(kCommand, s.error());
  }
  if (o.json) {
    nlohmann::json out = comparison_json(*comparison);
    out["expected"] = o.images[0];
    out["actual"] = o.images[1];
    out["options"] = options_json(options);
    out["diff_image"] = write_diff ? nlohmann::json(o.diff_output) : nlohmann::json(nullptr);
    std::cout << out.dump(1) << "\n";
  } else {
    print_text(*comparison, write_diff ? o.diff_output : std::string());
  }
  std::cout.flush();
  switch (comparison->verdict) {
    case DiffVerdict::kSame:
      return kExitOk;
    case DiffVerdict::kDifferent:
      return kExitDifferent;
    case DiffVerdict::kSizeMismatch:
      return kExitSizeMismatch;
  }
  return kExitError;
}

int run_diff(const DiffCommandOptions& o) {
  const Result<DiffOptions> options = diff_options(o);
  if (!options) return report_error(kCommand, options.error());
  const bool directory_mode = !o.expected_dir.empty() || !o.actual_dir.empty() || !o.report_dir.empty();
  if (directory_mode) {
    if (!o.images.empty() || o.expected_dir.empty() || o.actual_dir.empty() || o.report_dir.empty()) {
      return report_usage_error(
          kCommand, "directory mode needs --expected DIR, --actual DIR and --report OUT, and no image files");
    }
    DirectoryDiffOptions directory;
    directory.expected_dir = o.expected_dir;
    directory.actual_dir = o.actual_dir;
    directory.report_dir = o.report_dir;
    directory.update = o.update;
    directory.jobs = o.jobs;
    directory.diff = *options;
    directory.max_input_mib = o.max_input_mib;
    directory.max_memory_mib = o.max_memory_mib;
    return run_directory_diff(directory);
  }
  if (o.images.size() != 2) {
    return report_usage_error(kCommand, "give two PNG files (A.png B.png), or --expected, --actual and --report");
  }
  if (o.update) return report_usage_error(kCommand, "--update only applies to directory mode");
  if (o.images[0] == "-" && o.images[1] == "-") {
    return report_usage_error(kCommand, "only one of the two images can come from standard input (-)");
  }
  return run_pair(o, *options);
}

}  // namespace

void add_diff_command(CLI::App& root, CommandResult& result) {
  auto o = std::make_shared<DiffCommandOptions>();
  CLI::App* command = root.add_subcommand(
      "diff",
      "Compare two PNG images (max/mean |delta|, RMSE, PSNR, differing pixels and their bounding box), or "
      "two directories of PNG images with an HTML/JSON/JUnit report");
  command->footer(kExitCodeHelp);
  command->add_option("images", o->images,
                      "pair mode: the expected image A.png and the actual image B.png (one may be - for "
                      "standard input)")
      ->expected(0, 2);
  command->add_option(
      "-o,--output", o->diff_output,
      "pair mode: write the diff image (A faded to grey, differences red, anti-aliasing yellow)");
  command->add_flag("--json", o->json, "pair mode: print the metrics as JSON instead of text");
  CLI::Option* threshold =
      command
          ->add_option("--threshold", o->threshold,
                       "perceptual metric: pixelmatch's YIQ threshold in [0, 1]; a pixel differs when its "
                       "squared YIQ distance exceeds 35215*T^2")
      ->check(kFiniteNumber)
          ->check(CLI::Range(0.0, 1.0))
          ->capture_default_str();
  command
      ->add_option(
          "--channel-tolerance", o->channel_tolerance,
          "use the per-channel metric instead: a pixel differs when a premultiplied channel differs by "
          "more than N levels (0..255)")
      ->check(CLI::Range(0, 255))
      ->excludes(threshold);
  command->add_flag(
      "--ignore-aa", o->ignore_aa,
      "do not count differing pixels that look like anti-aliasing in either image (pixelmatch's "
      "detector); they are drawn yellow");
  command
      ->add_option("--ignore", o->ignore, "do not compare the pixels of the rectangle x,y,w,h (repeatable)")
      // One rectangle per --ignore, so that "--ignore R A.png B.png" leaves the images positional.
      ->allow_extra_args(false)
      // A malformed rectangle is a wrong command line: a usage error (64) before any image is read.
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            const Result<PixelBox> box = parse_region(text);
            return box ? std::string() : box.error().message;
          },
          "x,y,w,h"))
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command->add_option("--max-pixels", o->max_pixels, "tolerate up to N differing pixels")
      ->check(CLI::NonNegativeNumber);
  command->add_option("--max-percent", o->max_percent, "tolerate up to P percent of differing pixels")
      ->check(kFiniteNumber)
      ->check(CLI::Range(0.0, 100.0));
  command->add_option("--expected", o->expected_dir, "directory mode: the directory of expected PNG files");
  command->add_option("--actual", o->actual_dir, "directory mode: the directory of actual PNG files");
  command->add_option("--report", o->report_dir,
                      "directory mode: the output directory (index.html, summary.json, junit.xml, images/)");
  command->add_flag("--update", o->update,
                    "directory mode: after the report, copy the actual file over the expected one for every "
                    "failed and new file (review the report first)");
  command->add_option("--jobs", o->jobs, "directory mode: worker threads (default: all hardware threads)")
      ->check(CLI::Range(1u, 1024u));
  add_input_size_option(*command, o->max_input_mib);
  command
      ->add_option("--max-memory", o->max_memory_mib,
                   "memory for the images in MiB: each comparison holds the two images and the diff image, "
                   "4 bytes a pixel each, one comparison per --jobs thread (docs/limits.md)")
      ->check(CLI::Range(std::int64_t{1}, std::int64_t{1} << 20))
      ->capture_default_str();
  command->callback([o, &result] { result.exit_code = run_diff(*o); });
}

}  // namespace curvescan::cli
