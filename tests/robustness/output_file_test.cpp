// write_output_file (file_io.h) on every kind of thing an output path can name: nothing, a regular
// file, a symbolic link (good and dangling), a directory, a FIFO, a character device, and a full file
// system. The library's contract is checked directly here; output_command_test.cpp checks that every
// command goes through it.
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <sys/mount.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <future>
#include <string>

#include "curvescan/raster/file_io.h"
#include "run_command.h"

namespace curvescan::test {
namespace {

namespace fs = std::filesystem;

TEST_CASE("a new file is written whole, with nothing left beside it", "[robustness][output]") {
  const auto dir = scratch_directory("output-new");
  const std::string bytes(100'000, 'x');
  REQUIRE(write_output_file(dir / "out.bin", bytes));
  CHECK(read_text(dir / "out.bin") == bytes);
  CHECK(directory_listing(dir) == std::set<std::string>{"out.bin"});
}

TEST_CASE("an existing file is replaced and keeps its permission bits", "[robustness][output]") {
  const auto dir = scratch_directory("output-replace");
  write_text(dir / "out.bin", "old");
  fs::permissions(dir / "out.bin", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  REQUIRE(write_output_file(dir / "out.bin", std::string("new contents")));
  CHECK(read_text(dir / "out.bin") == "new contents");
  CHECK(fs::status(dir / "out.bin").permissions() ==
        (fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read));
  CHECK(directory_listing(dir) == std::set<std::string>{"out.bin"});
}

TEST_CASE("a symbolic link is followed: its target is written and the link stays", "[robustness][output]") {
  const auto dir = scratch_directory("output-link");
  fs::create_directory(dir / "real");
  write_text(dir / "real" / "target.bin", "old");
  fs::create_symlink("real/target.bin", dir / "link.bin");
  REQUIRE(write_output_file(dir / "link.bin", std::string("through the link")));
  CHECK(fs::is_symlink(dir / "link.bin"));
  CHECK(fs::read_symlink(dir / "link.bin") == "real/target.bin");
  CHECK(read_text(dir / "real" / "target.bin") == "through the link");
  CHECK(directory_listing(dir / "real") == std::set<std::string>{"target.bin"});
}

TEST_CASE("a dangling symbolic link is refused and nothing is created", "[robustness][output]") {
  const auto dir = scratch_directory("output-dangling");
  fs::create_symlink(dir / "nowhere.bin", dir / "link.bin");
  const Status written = write_output_file(dir / "link.bin", std::string("data"));
  REQUIRE_FALSE(written);
  CHECK_THAT(written.error().message, Catch::Contains("symbolic link to a file that does not exist"));
  CHECK(fs::is_symlink(dir / "link.bin"));
  CHECK(directory_listing(dir) == std::set<std::string>{"link.bin"});
}

TEST_CASE("a directory is refused", "[robustness][output]") {
  const auto dir = scratch_directory("output-directory");
  const Status written = write_output_file(dir, std::string("data"));
  REQUIRE_FALSE(written);
  CHECK_THAT(written.error().message, Catch::Contains("is a directory"));
  CHECK(directory_listing(dir).empty());
}

TEST_CASE("a FIFO is written through, not replaced", "[robustness][output]") {
  const auto dir = scratch_directory("output-fifo");
  const fs::path fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  const std::string bytes(1 << 20, 'p');  // more than a pipe's buffer: the writer must wait for the reader
  std::future<std::string> read = std::async(std::launch::async, [&] { return read_text(fifo); });
  REQUIRE(write_output_file(fifo, bytes));
  CHECK(read.get() == bytes);
  CHECK(fs::is_fifo(fifo));
  CHECK(directory_listing(dir) == std::set<std::string>{"pipe"});
}

TEST_CASE("/dev/null is written through and stays a device", "[robustness][output]") {
  REQUIRE(write_output_file("/dev/null", std::string(4096, 'n')));
  CHECK(fs::is_character_file("/dev/null"));
}

TEST_CASE("/dev/full reports the full disk", "[robustness][output]") {
  if (!fs::is_character_file("/dev/full")) {
    WARN("skipped: this system has no /dev/full");
    return;
  }
  const Status written = write_output_file("/dev/full", std::string(4096, 'f'));
  REQUIRE_FALSE(written);
  CHECK_THAT(written.error().message, Catch::Contains("No space left on device"));
  CHECK(fs::is_character_file("/dev/full"));
}

TEST_CASE("a full file system leaves the existing file as it was and no temporary", "[robustness][output]") {
  const auto dir = scratch_directory("output-full-tmpfs");
  // 64 KiB of tmpfs holds the old file but not the new 1 MiB one.
  if (::mount("tmpfs", dir.c_str(), "tmpfs", 0, "size=64k") != 0) {
    WARN("skipped: cannot mount a small tmpfs here (needs root and mount permission)");
    return;
  }
  // Unmounted however the test ends, before the directory is removed.
  struct Unmount {
    const char* where;
    ~Unmount() { ::umount(where); }
  } unmount{dir.c_str()};
  write_text(dir / "out.bin", "the old file");
  const Status written = write_output_file(dir / "out.bin", std::string(1 << 20, 'z'));
  REQUIRE_FALSE(written);
  CHECK_THAT(written.error().message, Catch::Contains("No space left on device"));
  CHECK(read_text(dir / "out.bin") == "the old file");
  CHECK(directory_listing(dir) == std::set<std::string>{"out.bin"});
}

TEST_CASE("a missing directory is one clear error", "[robustness][output]") {
  const auto dir = scratch_directory("output-missing-dir");
  const Status written = write_output_file(dir / "no" / "out.bin", std::string("data"));
  REQUIRE_FALSE(written);
  CHECK_THAT(written.error().message, Catch::Contains("No such file or directory"));
}

}  // namespace
}  // namespace curvescan::test
