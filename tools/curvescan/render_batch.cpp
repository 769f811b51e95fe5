// Batch rendering on a thread pool (render_batch.h).
#include "render_batch.h"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <new>
#include <nlohmann/json.hpp>
#include <optional>
#include <thread>

#include "background_writer.h"
#include "command_line_text.h"
#include "curvescan/raster/png_io.h"
#include "exit_codes.h"
#include "input_file.h"
#include "output.h"

namespace curvescan::cli {
namespace {

constexpr const char* kCommand = "render";
using Clock = std::chrono::steady_clock;

/// The names listed in the file `path` (parse_name_list).
Result<std::vector<std::string>> read_name_list(const std::string& path) {
  // 64 MiB of names is some million files: more than any directory a batch is run on.
  const Result<std::string> text = read_input(path, std::size_t{64} << 20);
  if (!text) return text.error();
  return parse_name_list(*text);
}

/// DIR/NAME.png for the input `path`.
std::string output_name(const std::string& output_dir, const std::string& path) {
  std::filesystem::path name = std::filesystem::path(path).filename();
  std::string extension = name.extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension == ".svg" || extension == ".svgz") name.replace_extension();
  return (std::filesystem::path(output_dir) / name).string() + ".png";
}

struct FileOutcome {
  bool ok = false;
  std::string error;
  double milliseconds = 0.0;
  std::vector<std::string> warnings;
};

/// The progress line on a terminal: count, rate and time left, redrawn at most ten times a second.
class Progress {
 public:
  Progress(std::size_t total, bool shown) : total_(total), shown_(shown), start_(Clock::now()) {}

  /// Prints `line` on stderr above the progress line.
  void print(const std::string& line) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (shown_) std::fputs("\r\033[K", stderr);
    std::fputs(printable(line).c_str(), stderr);
    std::fputc('\n', stderr);
    draw_locked(true);
  }

  void finished_one() {
    std::lock_guard<std::mutex> lock(mutex_);
    ++done_;
    draw_locked(done_ == total_);
  }

  void end() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (shown_ && drawn_) std::fputc('\n', stderr);
  }

 private:
  void draw_locked(bool force) {
    if (!shown_) return;
    const Clock::time_point now = Clock::now();
    if (!force && drawn_ && now - last_draw_ < std::chrono::milliseconds(100)) return;
    last_draw_ = now;
    drawn_ = true;
    const double seconds = std::chrono::duration<double>(now - start_).count();
    const double rate = seconds > 0.0 ? static_cast<double>(done_) / seconds : 0.0;
    const double left = rate > 0.0 ? static_cast<double>(total_ - done_) / rate : 0.0;
    std::fprintf(stderr, "\r\033[Krendered %zu/%zu  %.1f files/s  %.0f s left", done_, total_, rate, left);
    std::fflush(stderr);
  }

  std::mutex mutex_;
  std::size_t total_;
  std::size_t done_ = 0;
  bool shown_;
  bool drawn_ = false;
  Clock::time_point start_;
  Clock::time_point last_draw_;
};

std::string manifest_text(const std::vector<std::string>& inputs, const std::vector<std::string>& outputs,
                          const std::vector<FileOutcome>& outcomes) {
  std::string text;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    nlohmann::json line{{"input", inputs[i]},
                        {"output", outputs[i]},
                        {"status", outcomes[i].ok ? "ok" : "error"},
                        {"ms", outcomes[i].milliseconds},
                        {"warnings", outcomes[i].warnings}};
    if (!outcomes[i].ok) line["error"] = outcomes[i].error;
    // Replacement, not an exception, for a name that is not UTF-8.
    text += line.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
    text += '\n';
  }
  return text;
}

}  // namespace

int run_render_batch(const BatchOptions& options, const RenderSettings& settings) {
  std::vector<std::string> inputs = options.inputs;
  if (!options.files_from.empty()) {
    const Result<std::vector<std::string>> listed = read_name_list(options.files_from);
    if (!listed) return report_error(kCommand, listed.error());
    inputs.insert(inputs.end(), listed->begin(), listed->end());
  }
  if (inputs.empty()) return report_usage_error(kCommand, "no input files (give FILE... or --files-from)");
  std::vector<std::string> outputs;
  std::map<std::string, std::string> claimed;  // output -> the input that writes it
  for (const std::string& input : inputs) {
    if (input == "-") return report_usage_error(kCommand, "standard input (-) cannot be part of a batch");
    outputs.push_back(output_name(options.output_dir, input));
    const auto [it, inserted] = claimed.emplace(outputs.back(), input);
    if (!inserted) {
      return report_usage_error(kCommand, "'" + input + "' and '" + it->second + "' would both write '" +
                                              outputs.back() + "'");
    }
  }
  std::error_code error;
  std::filesystem::create_directories(options.output_dir, error);
  if (error || !std::filesystem::is_directory(options.output_dir)) {
    return report_error(kCommand, "cannot use '" + options.output_dir + "' as the output directory" +
                                      (error ? ": " + error.message() : std::string(": not a directory")));
  }

  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const unsigned jobs = static_cast<unsigned>(
      std::min<std::size_t>(options.jobs != 0 ? options.jobs : cores, inputs.size()));
  std::vector<FileOutcome> outcomes(inputs.size());
  Progress progress(inputs.size(), !options.quiet && isatty(STDERR_FILENO));
  std::atomic<std::size_t> next{0};
  // Writer threads wait for the disk, not the CPU: more of them than render threads keeps several fsyncs
  // in flight. At most 64 MiB of encoded PNGs wait for them.
  std::optional<BackgroundWriter> writer(std::in_place, 4u, std::size_t{64} << 20);
  const auto worker = [&] {
    for (std::size_t i = next.fetch_add(1); i < inputs.size(); i = next.fetch_add(1)) {
      const Clock::time_point start = Clock::now();
      RenderedFile rendered;
      try {
        rendered = render_svg_file(inputs[i], settings);
      } catch (const std::bad_alloc&) {  // one file out of memory must not end the others
        rendered.image = Error{ErrorKind::kLimitExceeded, inputs[i] + ": out of memory"};
      }
      FileOutcome& outcome = outcomes[i];
      outcome.warnings = rendered.warnings;
      if (!options.quiet) {
        for (const std::string& warning : rendered.warnings)
          progress.print("curvescan render: warning: " + inputs[i] + ": " + warning);
        if (options.verbose) {
          for (const std::string& note : rendered.notes)
            progress.print("curvescan render: warning: " + inputs[i] + ": " + note);
        }
      }
      // The outcome is complete once the file is written (on a writer thread) or has failed here.
      const auto finish = [&outcome, &progress, start](const Status& status) {
        outcome.ok = static_cast<bool>(status);
        if (!status) outcome.error = status.error().message;
        outcome.milliseconds = std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        if (!outcome.ok) progress.print("curvescan render: error: " + outcome.error);
        progress.finished_one();
      };
      if (!rendered.image) {
        finish(rendered.image.error());
        continue;
      }
      Result<std::vector<std::uint8_t>> png = encode_png(*rendered.image);
      if (!png) {
        finish(Error{png.error().kind, "cannot write '" + outputs[i] + "': " + png.error().message});
        continue;
      }
      writer->write(outputs[i], std::move(png).value(), finish);
    }
  };
  std::vector<std::thread> pool;
  for (unsigned j = 1; j < jobs; ++j) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();
  writer.reset();  // every queued file written
  progress.end();

  std::size_t failed = 0;
  for (const FileOutcome& outcome : outcomes) failed += outcome.ok ? 0 : 1;
  if (!options.manifest.empty()) {
    const Status written = write_output(options.manifest, manifest_text(inputs, outputs, outcomes));
    if (!written) return report_error(kCommand, written.error());
  }
  if (failed != 0) {
    std::fprintf(stderr, "curvescan render: %zu of %zu files failed\n", failed, inputs.size());
    return kExitError;
  }
  return kExitOk;
}

}  // namespace curvescan::cli
