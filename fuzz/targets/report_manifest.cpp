// Fuzz target report_manifest: the manifest of a `curvescan diff --report` directory
// (raster/diff/report_manifest.cpp, kReportManifestName), read by update_report_manifest, which then
// removes the stale files it lists. The input is the manifest's whole text; the directory is a fixed
// one made afresh for each input in a scratch directory of this process: report files the manifest may
// name (one with a space and a percent sign in its path), a user's file, a symbolic link to a directory
// outside the report and one to a file there, and that outside file.
//
// The manifest is the one input of curvescan that decides which files get removed, so this target checks
// what must hold whatever it says, and traps otherwise: nothing outside the report directory is removed
// or changed (through "..", absolute paths, percent-encoded steps or the links), the files this run
// writes stay, the report directory stays, no manifest makes the update fail, and the new manifest lists
// exactly what this run wrote. Which stale files a well-formed manifest removes is the unit tests' part
// (tests/unit/diff/report_manifest_test.cpp): here any listed file with its recorded size and hash may go.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "curvescan/diff/image_diff.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kOutsideBytes = "not the report's";

void write_file(const fs::path& path, std::string_view bytes) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// Where the scratch directory goes: TMPDIR when it is set, else the memory file system /dev/shm where
/// there is one, else the system's temporary directory. Each execution creates and removes a dozen files
/// and links; on a disk file system the process waits for the device (the profile is kernel time and
/// sleeps in ext4 and the virtio disk; that root was mounted with `discard`): 3000 executions from the
/// seeds took 102 to 113 s (wall) there under ASan + UBSan on a loaded machine, against 5 to 6 s in
/// /dev/shm, with the same coverage (docs/fuzzing.md). What the target checks (paths, links, bytes) does
/// not depend on the file system.
fs::path scratch_parent() {
  if (std::getenv("TMPDIR") == nullptr) {
    std::error_code ec;
    if (fs::is_directory("/dev/shm", ec) && access("/dev/shm", W_OK | X_OK) == 0) return "/dev/shm";
  }
  return fs::temp_directory_path();
}

/// The scratch directory of this process (its id in the name: the replay test and a fuzzer may run at
/// once), removed when the process exits, and before it traps (a trap skips the destructors).
class Scratch {
 public:
  Scratch() : root_(scratch_parent() / ("curvescan-fuzz-report-manifest-" + std::to_string(getpid()))) {
    remove();
    write_file(outside_file(), kOutsideBytes);
  }
  ~Scratch() { remove(); }
  Scratch(const Scratch&) = delete;
  Scratch& operator=(const Scratch&) = delete;

  /// A check failed: the scratch directory goes, then the process traps for the fuzzer to see. The input
  /// alone reproduces it, since every run makes the directory afresh.
  [[noreturn]] void trap() const {
    remove();
    __builtin_trap();
  }

  fs::path report() const { return root_ / "report"; }
  fs::path outside_file() const { return root_ / "outside" / "keep.png"; }

 private:
  void remove() const {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }

  fs::path root_;
};

}  // namespace

int fuzz_report_manifest(const std::uint8_t* data, std::size_t size) {
  static const Scratch scratch;
  const fs::path report = scratch.report();
  std::error_code ec;
  fs::remove_all(report, ec);  // a link is removed, not followed
  // The report of the previous run (the seeds list these with their sizes and FNV-1a hashes).
  write_file(report / "index.html", "page");
  write_file(report / "images/a.png/diff.png", "diff a");
  write_file(report / "images/b.png/diff.png", "diff b");
  write_file(report / "images/b.png/actual.png", "actual b");
  write_file(report / "images/deep/c d%.png/diff.png", "diff c");
  write_file(report / "notes.txt", "a user's notes");
  fs::create_directory_symlink(scratch.outside_file().parent_path(), report / "link", ec);
  fs::create_symlink(scratch.outside_file(), report / "images/outside.png", ec);
  write_file(report / kReportManifestName, std::string_view(reinterpret_cast<const char*>(data), size));

  // This run wrote the page and a's image again.
  const std::vector<std::string> written = {"index.html", "images/a.png/diff.png"};
  const Result<ReportPruning> pruning = update_report_manifest(report, written);
  if (!pruning) scratch.trap();  // whatever the manifest holds, the update succeeds
  if (read_file(scratch.outside_file()) != kOutsideBytes) scratch.trap();  // reached outside
  if (!fs::is_directory(report) || read_file(report / "index.html") != "page" ||
      read_file(report / "images/a.png/diff.png") != "diff a") {
    scratch.trap();  // removed what this run wrote, or the directory itself
  }
  // The links are never regular files: kept, whatever the manifest says of them or through them.
  if (!fs::is_symlink(report / "link") || !fs::is_symlink(report / "images/outside.png")) scratch.trap();
  // "<size> <FNV-1a 64 of the bytes> <path>" of the two written files, sorted by path.
  const std::string expected = std::string("curvescan report files 1\n") +
                               "6 ee36949ee1b49cdd images/a.png/diff.png\n" +
                               "4 038b2a0deba58916 index.html\n";
  if (read_file(report / kReportManifestName) != expected) scratch.trap();
  return 0;
}

}  // namespace curvescan::fuzz
