// The bad-input corpus runner: one table entry = one curvescan command on one bad input, with the exit
// code and a message it must give, run twice:
//   1. with no output file: after a failure, no output file (and no temporary file) may exist;
//   2. with an existing output file: after a failure, it must be left byte for byte as it was.
// After a success (exit 0, e.g. a document with a reference cycle that SVG says to skip with a warning)
// the output must exist and be a whole file of its kind (a PNG read_png accepts, or JSON).
//
// Placeholders in `arguments`: {in} the input file (written from `input`, or made as `input_kind` says),
// {out} the output path, {dir} the case's scratch directory.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <pthread.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <catch2/catch.hpp>
#include <cerrno>
#include <chrono>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "curvescan/raster/png_io.h"
#include "run_command.h"

namespace curvescan::test {

enum class InputKind {
  kFile,       ///< `input` written to {in}
  kDirectory,  ///< {in} is an empty directory
  kMissing,    ///< {in} does not exist
  kFifo,       ///< {in} is a FIFO; a writer thread feeds it `fifo_bytes` zero bytes (feed_fifo)
};

enum class OutputKind { kPng, kJson, kNone };

struct BadInputCase {
  std::string name;       ///< what the entry checks, shown on failure
  std::string arguments;  ///< the command line after "curvescan", with placeholders
  std::string input;      ///< the bytes of {in}
  int exit_code = 3;
  std::string message;  ///< ECMAScript regex that must match somewhere in stderr
  InputKind input_kind = InputKind::kFile;
  std::string input_name = "input";  ///< file name of {in} (extensions matter to `text --font`)
  OutputKind output_kind = OutputKind::kPng;
  std::string output_name = "out";  ///< file name of {out} inside the scratch directory
  /// Other files the command reads, written into the scratch directory ({dir}/name) first.
  std::vector<std::pair<std::string, std::string>> extra_files = {};
  /// kFifo: how many bytes the writer offers (more than the limit under test, so that a reader without
  /// a bound reads them all and fails with another message).
  std::size_t fifo_bytes = 0;
};

/// Writes up to `total` zero bytes into the FIFO `path` once a reader has opened it, and gives up at
/// `deadline`, so a test cannot hang: the write end is opened non-blocking (ENXIO until there is a
/// reader) and written with poll() time-boxed. At the deadline without a reader, the FIFO is opened for
/// reading and writing and closed again, which lets a reader blocked in open() go on and see EOF.
/// SIGPIPE is blocked in this thread only: a reader that stops early makes write() fail with EPIPE.
inline void feed_fifo(const std::filesystem::path& path, std::size_t total,
                      std::chrono::steady_clock::time_point deadline) {
  sigset_t pipe_signal;
  sigemptyset(&pipe_signal);
  sigaddset(&pipe_signal, SIGPIPE);
  pthread_sigmask(SIG_BLOCK, &pipe_signal, nullptr);
  int fd = -1;
  while (std::chrono::steady_clock::now() < deadline) {
    fd = ::open(path.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd >= 0 || errno != ENXIO) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (fd < 0) {
    const int unblock = ::open(path.c_str(), O_RDWR | O_NONBLOCK | O_CLOEXEC);
    if (unblock >= 0) ::close(unblock);
    return;
  }
  const std::string zeros(std::size_t{1} << 16, '\0');
  std::size_t written = 0;
  while (written < total && std::chrono::steady_clock::now() < deadline) {
    const ssize_t n = ::write(fd, zeros.data(), std::min(zeros.size(), total - written));
    if (n > 0) {
      written += static_cast<std::size_t>(n);
    } else if (n < 0 && errno == EAGAIN) {
      pollfd wait{fd, POLLOUT, 0};
      ::poll(&wait, 1, 50);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;  // EPIPE: the reader stopped
    }
  }
  ::close(fd);
}

inline std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

/// What one run of an entry did: the command's exit code and output, the scratch directory's listing
/// before and after, the output file after, and whether it was a whole file of its kind.
struct BadInputRun {
  const BadInputCase* c = nullptr;
  std::string existing_output;  // empty: the run started with no output file
  std::string arguments;
  CommandOutput result;
  std::set<std::string> before, after;
  std::string output_after;
  bool output_whole = false;
};

/// Runs one entry in a fresh scratch directory, with `existing_output` (empty: none) at {out} first.
/// No Catch2 assertions here: runs go on worker threads, checks on the test's thread (check_run).
inline BadInputRun run_bad_input_once(const BadInputCase& c, const std::string& existing_output) {
  BadInputRun run;
  run.c = &c;
  run.existing_output = existing_output;
  const auto dir = scratch_directory("bad-input");
  const std::filesystem::path input = dir / c.input_name;
  const std::filesystem::path output = dir / c.output_name;
  if (c.input_kind == InputKind::kFile) write_text(input, c.input);
  if (c.input_kind == InputKind::kDirectory) std::filesystem::create_directories(input);
  if (c.input_kind == InputKind::kFifo) ::mkfifo(input.c_str(), 0600);
  for (const auto& [name, bytes] : c.extra_files) write_text(dir / name, bytes);
  if (!existing_output.empty()) write_text(output, existing_output);
  run.arguments = replace_all(c.arguments, "{in}", shell_quote(input.string()));
  run.arguments = replace_all(run.arguments, "{out}", shell_quote(output.string()));
  run.arguments = replace_all(run.arguments, "{dir}", shell_quote(dir.string()));
  // The command's own stdout/stderr files go to a sibling directory, so that the listing sees only what
  // the command made.
  const auto capture = scratch_directory("bad-input-capture");
  run.before = directory_listing(dir);
  std::thread feeder;
  if (c.input_kind == InputKind::kFifo) {
    // 60 s: far above the second or so a bounded read of a few MiB takes on a loaded machine.
    feeder = std::thread(feed_fifo, input, c.fifo_bytes, std::chrono::steady_clock::now() + std::chrono::seconds(60));
  }
  run.result = run_curvescan(run.arguments, capture);
  if (feeder.joinable()) feeder.join();
  run.after = directory_listing(dir);
  if (std::filesystem::is_regular_file(output)) run.output_after = read_text(output);
  if (c.output_kind == OutputKind::kPng) {
    run.output_whole = read_png(output).is_ok();
  } else {
    run.output_whole = !run.output_after.empty() && run.output_after.back() == '\n';
  }
  return run;
}

/// "curvescan: error: MESSAGE\n" or "curvescan SUBCOMMAND: error: MESSAGE\n" (a lower-case word), one
/// line with a message. Written out rather than as a std::regex: libstdc++'s regex recurses once per
/// character a repetition matches, so `[^\n]+` over a long message can overflow the stack under ASan.
inline bool is_one_error_line(const std::string& err) {
  const std::string_view text(err);
  constexpr std::string_view kProgram = "curvescan", kError = ": error: ";
  if (!text.starts_with(kProgram) || !text.ends_with('\n')) return false;
  std::size_t at = kProgram.size();
  if (at < text.size() && text[at] == ' ') {
    const std::size_t word = ++at;
    while (at < text.size() && text[at] >= 'a' && text[at] <= 'z') ++at;
    if (at == word) return false;
  }
  if (text.substr(at, kError.size()) != kError) return false;
  const std::string_view message = text.substr(at + kError.size(), text.size() - at - kError.size() - 1);
  return !message.empty() && message.find('\n') == std::string_view::npos;
}

inline void check_run(const BadInputRun& run) {
  const BadInputCase& c = *run.c;
  INFO("case: " << c.name << "\ncommand: curvescan " << run.arguments << "\nexisting output: "
                << (run.existing_output.empty() ? "no" : "yes") << "\nstderr: " << run.result.err);
  CHECK(run.result.exit_code == c.exit_code);
  CHECK(std::regex_search(run.result.err, std::regex(c.message)));
  if (run.result.exit_code == 3) {
    // One line naming the subcommand ("curvescan render: error: ..."), nothing else.
    CHECK(is_one_error_line(run.result.err));
  }
  if (c.exit_code != 0) {
    CHECK(run.after == run.before);  // no output file, no temporary file left behind
    if (!run.existing_output.empty()) CHECK(run.output_after == run.existing_output);
  } else if (c.output_kind != OutputKind::kNone) {
    CHECK(run.output_whole);
  }
}

/// Runs every entry of `cases` without and with an existing output file, a few commands at a time (each
/// run has its own scratch directory), then checks them in order.
inline void run_bad_inputs(const std::vector<BadInputCase>& cases) {
  struct Job {
    const BadInputCase* c;
    std::string existing_output;
  };
  std::vector<Job> jobs;
  for (const BadInputCase& c : cases) {
    jobs.push_back({&c, ""});
    if (c.exit_code != 0) jobs.push_back({&c, "an existing output file that a failure must not touch\n"});
  }
  std::vector<BadInputRun> runs(jobs.size());
  std::atomic<std::size_t> next{0};
  const auto worker = [&] {
    for (std::size_t i = next++; i < jobs.size(); i = next++) runs[i] = run_bad_input_once(*jobs[i].c, jobs[i].existing_output);
  };
  // Four at a time: the commands mostly wait on process start-up and the file system.
  std::vector<std::thread> workers;
  for (int i = 0; i < 4; ++i) workers.emplace_back(worker);
  for (std::thread& t : workers) t.join();
  for (const BadInputRun& run : runs) check_run(run);
}

}  // namespace curvescan::test
