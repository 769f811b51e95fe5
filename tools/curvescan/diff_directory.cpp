// Directory mode of `curvescan diff` (contract in diff_directory.h).
//
// Work is split into one job per relative path. Each job reads, compares and, for a file that did not
// pass, writes its images under report_dir/images/<relative path>/ (expected.png and actual.png are byte
// copies of the inputs, diff.png is drawn by compare_images) and fills its own slot of the result vector,
// so the threads share nothing but an atomic job counter. The HTML, JSON and JUnit files are written once
// all jobs finished, in the sorted order of the relative paths, so the reports do not depend on timing.
#include "diff_directory.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <new>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "curvescan/raster/png_io.h"
#include "diff_json.h"
#include "exit_codes.h"
#include "input_file.h"
#include "limit_options.h"

namespace curvescan::cli {
namespace {

constexpr const char* kCommand = "diff";
namespace fs = std::filesystem;

bool is_png_name(const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) {
    return static_cast<char>(c >= 'A' && c <= 'Z' ? c + ('a' - 'A') : c);
  });
  return extension == ".png";
}

bool is_within(const fs::path& path, const fs::path& directory) {
  const auto [end, ignored] = std::mismatch(directory.begin(), directory.end(), path.begin(), path.end());
  return end == directory.end();
}

/// Relative paths (generic form) of the PNG files under `root`, skipping anything under `excluded` (the
/// report directory, which may lie inside the actual tree and holds PNGs of its own). `side` is
/// "expected" or "actual", for the error message.
Result<std::vector<std::string>> list_png_files(const fs::path& root, const fs::path& excluded,
                                                const std::string& side) {
  std::error_code ec;
  if (!fs::is_directory(root, ec)) {
    return Error{ErrorKind::kIoError, "--" + side + " '" + root.string() + "' " +
                                          (fs::exists(root, ec) ? "is not a directory" : "does not exist") +
                                          ": give the directory that holds the " + side + " PNG files"};
  }
  std::vector<std::string> names;
  fs::recursive_directory_iterator it(root, fs::directory_options::skip_permission_denied, ec), end;
  if (ec) return Error{ErrorKind::kIoError, "cannot list '" + root.string() + "': " + ec.message()};
  for (; it != end; it.increment(ec)) {
    if (ec) return Error{ErrorKind::kIoError, "cannot list '" + root.string() + "': " + ec.message()};
    const fs::path full = fs::weakly_canonical(it->path(), ec);
    if (!ec && !excluded.empty() && is_within(full, excluded)) {
      if (it->is_directory(ec)) it.disable_recursion_pending();
      continue;
    }
    if (!it->is_regular_file(ec) || !is_png_name(it->path())) continue;
    names.push_back(it->path().lexically_relative(root).generic_string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

struct Job {
  std::string name;
  bool has_expected = false;
  bool has_actual = false;
};

struct JobResult {
  DiffReportEntry entry;
  double seconds = 0.0;
  std::string write_failure;  ///< set when the report's images for this file could not be written
  std::vector<std::string> written;  ///< the report files written for it, relative to the report directory
};

class DirectoryDiff {
 public:
  explicit DirectoryDiff(const DirectoryDiffOptions& options)
      : options_(options),
        max_pixels_(diff_max_pixels(options.max_memory_mib, options.workers)),
        memory_hint_(diff_memory_hint(options.max_memory_mib, options.workers)) {}

  JobResult run(const Job& job) const {
    const auto start = std::chrono::steady_clock::now();
    JobResult result;
    try {
      result = compare(job);
    } catch (const std::bad_alloc&) {
      result.entry.name = job.name;
      result.entry.outcome = DiffOutcome::kError;
      result.entry.message = "out of memory while comparing this file";
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
  }

 private:
  [[nodiscard]] fs::path image_dir(const std::string& name) const {
    return options_.report_dir / "images" / name;
  }
  [[nodiscard]] static std::string image_url(const std::string& name, const char* file) {
    return relative_url(image_path(name, file));
  }
  /// The path of one of a file's report images, relative to the report directory.
  [[nodiscard]] static std::string image_path(const std::string& name, const char* file) {
    return (fs::path("images") / name / file).generic_string();
  }

  /// Copies `source` into the report as images/<name>/<file>; returns the URL or records the failure.
  std::string copy_into_report(const fs::path& source, const std::string& name, const char* file,
                               JobResult& result) const {
    std::error_code ec;
    fs::create_directories(image_dir(name), ec);
    if (!ec) fs::copy_file(source, image_dir(name) / file, fs::copy_options::overwrite_existing, ec);
    if (ec) {
      result.write_failure = "cannot copy '" + source.string() + "' into the report: " + ec.message() +
                             " (check that the report directory is writable and has space)";
      return {};
    }
    result.written.push_back(image_path(name, file));
    return image_url(name, file);
  }

  JobResult compare(const Job& job) const {
    JobResult result;
    DiffReportEntry& entry = result.entry;
    entry.name = job.name;
    const fs::path expected_path = options_.expected_dir / job.name;
    const fs::path actual_path = options_.actual_dir / job.name;
    if (!job.has_actual) {
      entry.outcome = DiffOutcome::kMissing;
      entry.message = "the expected image has no actual image";
      entry.expected_image = copy_into_report(expected_path, job.name, "expected.png", result);
      return result;
    }
    if (!job.has_expected) {
      entry.outcome = DiffOutcome::kNew;
      entry.message = "the actual image has no expected image";
      entry.actual_image = copy_into_report(actual_path, job.name, "actual.png", result);
      return result;
    }
    // Read with the --max-input-size bound (a file may be replaced or grow after it was listed).
    const std::size_t max_bytes = input_size_bytes(options_.max_input_mib);
    const Result<Image> expected = read_png_input(expected_path.string(), max_bytes, max_pixels_, memory_hint_);
    const Result<Image> actual = read_png_input(actual_path.string(), max_bytes, max_pixels_, memory_hint_);
    if (!expected || !actual) {
      entry.outcome = DiffOutcome::kError;
      entry.message = !expected ? expected.error().message : actual.error().message;
      return result;
    }
    // Most files of a regression run pass: compare without drawing first (the row fast path of
    // compare_images), and draw the diff image only for the files that fail.
    DiffOptions metrics_only = options_.diff;
    metrics_only.make_diff_image = false;
    Result<ImageComparison> compared = compare_images(*expected, *actual, metrics_only);
    if (compared && compared->verdict == DiffVerdict::kDifferent) {
      compared = compare_images(*expected, *actual, options_.diff);
    }
    if (!compared) {  // options were validated before the pool started; kept for totality
      entry.outcome = DiffOutcome::kError;
      entry.message = compared.error().message;
      return result;
    }
    Image diff_image = std::move(compared->diff_image);
    compared->diff_image = Image();
    entry.comparison = std::move(*compared);
    if (entry.comparison->verdict == DiffVerdict::kSame) {
      entry.outcome = DiffOutcome::kPassed;
      return result;
    }
    entry.outcome = DiffOutcome::kFailed;
    entry.message = describe_comparison(*entry.comparison);
    entry.expected_image = copy_into_report(expected_path, job.name, "expected.png", result);
    entry.actual_image = copy_into_report(actual_path, job.name, "actual.png", result);
    if (!diff_image.empty()) {
      const Status written = write_png(diff_image, image_dir(job.name) / "diff.png");
      if (written) {
        entry.diff_image = image_url(job.name, "diff.png");
        result.written.push_back(image_path(job.name, "diff.png"));
      } else {
        result.write_failure = written.error().message;
      }
    }
    return result;
  }

  const DirectoryDiffOptions& options_;
  const std::int64_t max_pixels_;  // of each decoded image, from --max-memory over the workers
  const std::string memory_hint_;  // names --max-memory when that bound refuses an image
};

std::vector<Job> pair_files(const std::vector<std::string>& expected,
                            const std::vector<std::string>& actual) {
  std::map<std::string, Job> by_name;
  for (const std::string& name : expected) by_name[name] = {name, true, false};
  for (const std::string& name : actual) {
    Job& job = by_name[name];
    job.name = name;
    job.has_actual = true;
  }
  std::vector<Job> jobs;
  jobs.reserve(by_name.size());
  for (auto& [name, job] : by_name) jobs.push_back(std::move(job));
  return jobs;
}

std::vector<JobResult> run_pool(const std::vector<Job>& jobs, const DirectoryDiff& diff, unsigned threads) {
  std::vector<JobResult> results(jobs.size());
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i = next.fetch_add(1); i < jobs.size(); i = next.fetch_add(1))
      results[i] = diff.run(jobs[i]);
  };
  std::vector<std::jthread> pool;
  const unsigned count = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(jobs.size())));
  for (unsigned t = 1; t < count; ++t) pool.emplace_back(worker);
  worker();  // the calling thread is one of the workers
  return results;
}

Status update_expected(const DirectoryDiffOptions& options, const std::vector<DiffReportEntry>& entries,
                       std::size_t& updated) {
  for (const DiffReportEntry& entry : entries) {
    if (entry.outcome != DiffOutcome::kFailed && entry.outcome != DiffOutcome::kNew) continue;
    const fs::path target = options.expected_dir / entry.name;
    std::error_code ec;
    fs::create_directories(target.parent_path(), ec);
    if (!ec) fs::copy_file(options.actual_dir / entry.name, target, fs::copy_options::overwrite_existing, ec);
    if (ec)
      return Error{ErrorKind::kIoError,
                   "--update: cannot copy over '" + target.string() + "': " + ec.message()};
    ++updated;
  }
  return Status::ok();
}

}  // namespace

int run_directory_diff(const DirectoryDiffOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::error_code ec;
  // The inputs are checked before the report directory is made, so that a bad --expected or --actual
  // leaves nothing behind.
  const fs::path report_canonical = fs::weakly_canonical(options.report_dir, ec);
  const Result<std::vector<std::string>> expected = list_png_files(options.expected_dir, report_canonical, "expected");
  if (!expected) return report_error(kCommand, expected.error());
  const Result<std::vector<std::string>> actual = list_png_files(options.actual_dir, report_canonical, "actual");
  if (!actual) return report_error(kCommand, actual.error());
  fs::create_directories(options.report_dir, ec);
  if (ec)
    return report_error(kCommand, "cannot create the report directory '" + options.report_dir.string() +
                                      "': " + ec.message() + " (give --report a directory you can write)");

  const std::vector<Job> jobs = pair_files(*expected, *actual);
  const unsigned threads =
      options.jobs > 0 ? options.jobs : std::max(1u, std::thread::hardware_concurrency());
  DirectoryDiffOptions with_workers = options;
  with_workers.workers = std::max(1u, std::min<unsigned>(threads, static_cast<unsigned>(jobs.size())));
  const DirectoryDiff diff(with_workers);
  std::vector<JobResult> results = run_pool(jobs, diff, threads);

  std::vector<DiffReportEntry> entries;
  std::vector<double> seconds;
  entries.reserve(results.size());
  std::size_t counts[5] = {};
  std::size_t size_mismatches = 0;
  std::vector<std::string> written = {"index.html", "summary.json", "junit.xml"};
  for (JobResult& r : results) {
    if (!r.write_failure.empty()) return report_error(kCommand, r.write_failure);
    written.insert(written.end(), r.written.begin(), r.written.end());
    if (report_status(r.entry) == "size-mismatch") ++size_mismatches;
    ++counts[static_cast<int>(r.entry.outcome)];
    seconds.push_back(r.seconds);
    entries.push_back(std::move(r.entry));
  }
  const double total_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const fs::path html = options.report_dir / "index.html";
  if (const Status s = write_html_report(
          html,
          "curvescan diff: " + options.actual_dir.string() + " against " + options.expected_dir.string(),
          entries, options.diff);
      !s) {
    return report_error(kCommand, s.error());
  }
  nlohmann::json summary;
  summary["expected_dir"] = options.expected_dir.string();
  summary["actual_dir"] = options.actual_dir.string();
  summary["options"] = options_json(options.diff);
  summary["counts"] = {{"failed", counts[static_cast<int>(DiffOutcome::kFailed)]},
                       {"new", counts[static_cast<int>(DiffOutcome::kNew)]},
                       {"missing", counts[static_cast<int>(DiffOutcome::kMissing)]},
                       {"passed", counts[static_cast<int>(DiffOutcome::kPassed)]},
                       {"error", counts[static_cast<int>(DiffOutcome::kError)]},
                       {"size_mismatch", size_mismatches}};
  summary["seconds"] = total_seconds;
  summary["threads"] = threads;
  nlohmann::json files = nlohmann::json::array();
  for (const DiffReportEntry& e : entries) {
    nlohmann::json file;
    file["name"] = e.name;
    file["outcome"] = to_string(e.outcome);
    file["status"] = report_status(e);
    file["message"] = e.message;
    file["comparison"] = e.comparison ? comparison_json(*e.comparison) : nlohmann::json(nullptr);
    file["images"] = {{"expected", e.expected_image}, {"actual", e.actual_image}, {"diff", e.diff_image}};
    files.push_back(std::move(file));
  }
  summary["files"] = std::move(files);
  if (const Status s =
          write_text_file_atomically(options.report_dir / "summary.json", summary.dump(1) + "\n");
      !s) {
    return report_error(kCommand, s.error());
  }
  if (const Status s = write_text_file_atomically(options.report_dir / "junit.xml",
                                                  junit_xml(entries, seconds, total_seconds));
      !s) {
    return report_error(kCommand, s.error());
  }

  // Last, once every file of this report is in place: remove what earlier reports left and this one did
  // not write again (images of files that pass now), and list this report's files for the next run.
  const Result<ReportPruning> pruning = update_report_manifest(options.report_dir, written);
  if (!pruning) return report_error(kCommand, pruning.error());

  std::size_t listed = 0;
  for (const DiffReportEntry& e : entries) {
    if (e.outcome == DiffOutcome::kPassed) continue;
    if (listed++ == options.max_listed) {
      std::cout << "... (the report lists every file)\n";
      break;
    }
    std::cout << to_string(e.outcome) << "\t" << e.name << ": " << e.message << "\n";
  }
  std::size_t updated = 0;
  if (options.update) {
    if (const Status s = update_expected(options, entries, updated); !s)
      return report_error(kCommand, s.error());
  }
  std::printf(
      "%zu failed, %zu new, %zu missing, %zu passed, %zu unreadable (%zu files, %.2f s, %u threads); "
      "report: %s\n",
      counts[static_cast<int>(DiffOutcome::kFailed)], counts[static_cast<int>(DiffOutcome::kNew)],
      counts[static_cast<int>(DiffOutcome::kMissing)], counts[static_cast<int>(DiffOutcome::kPassed)],
      counts[static_cast<int>(DiffOutcome::kError)], entries.size(), total_seconds, threads,
      html.string().c_str());
  if (options.update) std::printf("--update: copied %zu actual images over the expected ones\n", updated);
  if (pruning->removed_files > 0) {
    std::printf("removed %zu stale files of an earlier report from %s\n", pruning->removed_files,
                options.report_dir.string().c_str());
  }
  if (!pruning->kept_changed.empty()) {
    std::printf("kept %zu files of an earlier report that changed since it wrote them, e.g. %s\n",
                pruning->kept_changed.size(), pruning->kept_changed.front().c_str());
  }
  std::fflush(stdout);

  if (counts[static_cast<int>(DiffOutcome::kError)] > 0) return kExitError;
  const std::size_t unresolved = counts[static_cast<int>(DiffOutcome::kMissing)] +
                                 (options.update ? 0
                                                 : counts[static_cast<int>(DiffOutcome::kFailed)] +
                                                       counts[static_cast<int>(DiffOutcome::kNew)]);
  return unresolved > 0 ? kExitDifferent : kExitOk;
}

}  // namespace curvescan::cli
