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

#include "command_line_text.h"
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
#include "output_is_input.h"

namespace curvescan::cli {
namespace {

constexpr const char* kCommand = "diff";

constexpr const char* kExitCodeHelp =
    "Exit codes: 0 the same within tolerance (directory mode: every file passed), 1 different (directory "
    "mode: a file failed, is new or is missing), 2 the two images have different sizes (pair mode), 3 an "
    "error (unreadable, corrupt or too large file, I/O failure), 64 a malformed "
    "command line (an option out of its range, a missing or extra file, options of the other mode, an output "
    "that is also an input), 128+N stopped by signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP). See "
    "docs/diff.md.";

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
  int region_gap = DiffOptions{}.region_gap;
  std::size_t max_regions = DiffOptions{}.max_regions;
  std::string expected_dir, actual_dir, report_dir;
  bool update = false;
  unsigned jobs = 0;
  std::int64_t max_input_mib = kDefaultMaxInputMiB;
  std::int64_t max_memory_mib = kDefaultMaxMemoryMiB;
};

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
    Result<PixelBox> box = parse_ignore_region(text);
    if (!box) return box.error();
    options.ignore_regions.push_back(*box);
  }
  if (o.max_pixels >= 0) options.max_different_pixels = static_cast<std::uint64_t>(o.max_pixels);
  if (o.max_percent >= 0.0) options.max_different_percent = o.max_percent;
  options.region_gap = o.region_gap;
  options.max_regions = o.max_regions;
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
  out << "regions             " << m.region_count;
  if (c.regions.size() < m.region_count) out << " (the largest " << c.regions.size() << " listed)";
  out << "\n";
  for (std::size_t i = 0; i < c.regions.size(); ++i) {
    const DifferenceRegion& r = c.regions[i];
    out << "  region " << (i + 1) << "  x=" << r.box.x << " y=" << r.box.y << " w=" << r.box.width
        << " h=" << r.box.height << "  " << r.pixels << " pixels, max channel |delta| " << r.max_channel_delta
        << "\n";
  }
  if (!diff_output.empty()) out << "diff image          " << diff_output << "\n";
  std::cout << out.str();
}

/// A read error with what the user can do about it (the message already names the file).
Error with_advice(Error error) {
  switch (error.kind) {
    case ErrorKind::kIoError:
      error.message += "; check the path and the permissions";
      break;
    case ErrorKind::kCorruptInput:
    case ErrorKind::kUnsupported:
      error.message += "; give a PNG image (curvescan render turns an SVG into one)";
      break;
    case ErrorKind::kInvalidArgument:
    case ErrorKind::kLimitExceeded:  // its message names the option to raise
      break;
  }
  return error;
}

int run_pair(const DiffCommandOptions& o, const DiffOptions& options) {
  // Each image is read with the --max-input-size bound whatever it is (a file, a FIFO, a device), then
  // decoded from memory.
  const std::size_t max_bytes = input_size_bytes(o.max_input_mib);
  const std::int64_t max_pixels = diff_max_pixels(o.max_memory_mib, 1);
  const std::string hint = diff_memory_hint(o.max_memory_mib, 1);
  const Result<Image> expected = read_png_input(o.images[0], max_bytes, max_pixels, hint);
  if (!expected) return report_error(kCommand, with_advice(expected.error()));
  const Result<Image> actual = read_png_input(o.images[1], max_bytes, max_pixels, hint);
  if (!actual) return report_error(kCommand, with_advice(actual.error()));
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
  if (const auto input = input_named_by_output(o.diff_output, o.images))
    return report_usage_error(kCommand, output_is_input_message(o.diff_output, *input));
  return run_pair(o, *options);
}

}  // namespace

void add_diff_command(CLI::App& root, CommandResult& result) {
  auto o = std::make_shared<DiffCommandOptions>();
  CLI::App* command = root.add_subcommand(
      "diff",
      "Compare two PNG images (pair mode), or two directories of PNG images with an HTML, JSON and JUnit "
      "report (directory mode). docs/diff.md explains the metrics and the report.\n"
      "Two forms:\n"
      "  curvescan diff EXPECTED.png ACTUAL.png [-o DIFF.png] [--json] [options]\n"
      "  curvescan diff --expected DIR --actual DIR --report DIR [--update] [--jobs N] [options]\n"
      "Examples:\n"
      "  curvescan diff expected.png actual.png -o diff.png\n"
      "  curvescan diff old.png new.png --threshold 0.05 --ignore 0,0,200,40 --json\n"
      "  curvescan diff --expected golden/ --actual out/ --report report/ --ignore-aa --max-percent 0.1\n"
      "    (then open report/index.html in a browser)");
  command->footer(kExitCodeHelp);
  // Each option says its unit, range and default in words; the validators' own descriptions (CLI11
  // prints them as type names such as "INT:INT in [0 - 255]") are silenced.
  const auto quiet = [](const CLI::Validator& validator) { return validator.description(""); };
  command
      ->add_option("images", o->images,
                   "pair mode: the expected (reference) image and the actual image, PNG files; either one "
                   "may be - to read standard input")
      ->type_name("EXPECTED.png ACTUAL.png")
      ->expected(0, 2);
  command
      ->add_option("-o,--output", o->diff_output,
                   "pair mode: write the diff image to this PNG file: the expected image faded to grey, "
                   "differing pixels red, anti-aliasing yellow, ignored rectangles blue. Default: none")
      ->type_name("DIFF.png");
  command->add_flag("--json", o->json,
                    "pair mode: print the metrics and the difference regions as JSON instead of text");
  CLI::Option* threshold =
      command
          ->add_option("--threshold", o->threshold,
                       "how different two colours must look for a pixel to differ, from 0 (any visible "
                       "change) to 1 (nothing differs), on pixelmatch's perceptual scale; 0.1 lets about 26 "
                       "grey levels through. Default 0.1")
          ->type_name("T")
          ->check(quiet(kFiniteNumber))
          ->check(quiet(CLI::Range(0.0, 1.0)));
  command
      ->add_option("--channel-tolerance", o->channel_tolerance,
                   "compare channel by channel instead: a pixel differs when its red, green, blue or alpha "
                   "differs by more than N levels (0 to 255; 0 = exact). Default: not used, --threshold "
                   "decides")
      ->type_name("N")
      ->check(quiet(CLI::Range(0, 255)))
      ->excludes(threshold);
  command->add_flag("--ignore-aa", o->ignore_aa,
                    "do not count differing pixels that look like anti-aliasing in either image "
                    "(pixelmatch's detector); they are drawn yellow. Default: counted");
  command
      ->add_option("--ignore", o->ignore,
                   "do not compare the rectangle of W x H pixels whose top-left pixel is (X, Y), in pixels "
                   "of the images; repeat the option for several rectangles. Default: none")
      ->type_name("X,Y,W,H")
      // One rectangle per --ignore, so that "--ignore R A.png B.png" leaves the images positional.
      ->allow_extra_args(false)
      // A malformed rectangle is a wrong command line: a usage error (64) before any image is read.
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            const Result<PixelBox> box = parse_ignore_region(text);
            return box ? std::string() : box.error().message;
          },
          ""))
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  command
      ->add_option("--max-pixels", o->max_pixels,
                   "pass when at most N pixels differ. Default: no differing pixel is allowed (unless "
                   "--max-percent is given)")
      ->type_name("N")
      ->check(quiet(CLI::NonNegativeNumber));
  command
      ->add_option("--max-percent", o->max_percent,
                   "pass when at most P percent (0 to 100) of all pixels differ; with --max-pixels both "
                   "must hold. Default: not used")
      ->type_name("P")
      ->check(quiet(kFiniteNumber))
      ->check(quiet(CLI::Range(0.0, 100.0)));
  command
      ->add_option("--region-gap", o->region_gap,
                   "differing pixels at most N pixels apart form one region, boxed in the report and "
                   "listed in the JSON (0 to 64 pixels; 0 = only touching pixels). Default 3")
      ->type_name("N")
      ->check(quiet(CLI::Range(0, 64)));
  command
      ->add_option("--max-regions", o->max_regions,
                   "list and box at most the N largest regions of an image (0 to 10000); the count of all "
                   "regions is always given. Default 50")
      ->type_name("N")
      ->check(quiet(CLI::Range(0, 10000)));
  command->add_option("--expected", o->expected_dir, "directory mode: the directory of expected PNG files")
      ->type_name("DIR");
  command
      ->add_option("--actual", o->actual_dir,
                   "directory mode: the directory of actual PNG files, paired with the expected ones by "
                   "their path relative to the directory")
      ->type_name("DIR");
  command
      ->add_option("--report", o->report_dir,
                   "directory mode: the directory to write index.html, summary.json, junit.xml and images/ "
                   "into (created if needed); files an earlier report wrote there and this one does not are "
                   "removed, nothing else is")
      ->type_name("DIR");
  command->add_flag("--update", o->update,
                    "directory mode: after the report, copy the actual file over the expected one for every "
                    "failed and new file (review the report first)");
  command
      ->add_option("--jobs", o->jobs,
                   "directory mode: worker threads, 1 to 1024. Default: all hardware threads")
      ->type_name("N")
      ->check(quiet(CLI::Range(1u, 1024u)));
  command
      ->add_option("--max-input-size", o->max_input_mib,
                   "largest PNG file read, in MiB (1 to 4096); a larger one is an error (docs/limits.md). "
                   "Default " + std::to_string(kDefaultMaxInputMiB))
      ->type_name("MiB")
      ->check(quiet(CLI::Range(std::int64_t{1}, std::int64_t{1} << 12)));
  command
      ->add_option("--max-memory", o->max_memory_mib,
                   "memory for the images in MiB (1 to 1048576): a comparison holds three images of 4 bytes "
                   "a pixel and 2 bytes a pixel to find the regions, one comparison per --jobs thread; a "
                   "larger image is refused (docs/limits.md). Default " +
                       std::to_string(kDefaultMaxMemoryMiB))
      ->type_name("MiB")
      ->check(quiet(CLI::Range(std::int64_t{1}, std::int64_t{1} << 20)));
  command->callback([o, &result] { result.exit_code = run_diff(*o); });
}

}  // namespace curvescan::cli
