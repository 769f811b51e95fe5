// read_file_bounded (file_io.h): the one reader of whole files — bounded for any kind of file, and for
// files that must be regular, a FIFO or a device is refused without waiting.
#include <sys/stat.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "curvescan/raster/file_io.h"
#include "scratch_directory.h"

namespace curvescan {
namespace {

using test::scratch_directory;

TEST_CASE("a regular file is read whole, and refused from its size when over the bound", "[io][read]") {
  const auto dir = scratch_directory("read-test");
  const std::filesystem::path file = dir / "ten";
  std::ofstream(file, std::ios::binary) << "0123456789";
  const Result<std::vector<std::uint8_t>> whole = read_file_bounded(file, ReadBound{10, "the test limit"});
  REQUIRE(whole);
  CHECK(std::string(whole->begin(), whole->end()) == "0123456789");
  const Result<std::vector<std::uint8_t>> over = read_file_bounded(file, ReadBound{9, "the test limit"});
  REQUIRE_FALSE(over);
  CHECK(over.error().kind == ErrorKind::kLimitExceeded);
  CHECK_THAT(over.error().message, Catch::Contains("larger than 9 bytes, the test limit"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("a device is read up to the bound plus one byte, then refused", "[io][read]") {
  const Result<std::vector<std::uint8_t>> zero = read_file_bounded("/dev/zero", ReadBound{std::size_t{1} << 20, {}});
  REQUIRE_FALSE(zero);
  CHECK(zero.error().kind == ErrorKind::kLimitExceeded);
  CHECK_THAT(zero.error().message, Catch::Contains("'/dev/zero'") && Catch::Contains("1 MiB"));
  // An empty device is an empty read.
  const Result<std::vector<std::uint8_t>> null = read_file_bounded("/dev/null", ReadBound{16, {}});
  REQUIRE(null);
  CHECK(null->empty());
}

TEST_CASE("regular files only: a FIFO and a device are refused at once, a directory always", "[io][read]") {
  const auto dir = scratch_directory("read-test");
  const std::filesystem::path fifo = dir / "pipe";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  // No writer ever opens the FIFO: a blocking open would hang this test; O_NONBLOCK keeps it immediate.
  const Result<std::vector<std::uint8_t>> from_fifo =
      read_file_bounded(fifo, ReadBound{1024, {}, FileKinds::kRegularOnly});
  REQUIRE_FALSE(from_fifo);
  CHECK_THAT(from_fifo.error().message, Catch::Contains("it is a FIFO, not a regular file"));
  const Result<std::vector<std::uint8_t>> from_device =
      read_file_bounded("/dev/zero", ReadBound{1024, {}, FileKinds::kRegularOnly});
  REQUIRE_FALSE(from_device);
  CHECK_THAT(from_device.error().message, Catch::Contains("a character device, not a regular file"));
  const Result<std::vector<std::uint8_t>> from_directory = read_file_bounded(dir, ReadBound{1024, {}});
  REQUIRE_FALSE(from_directory);
  CHECK_THAT(from_directory.error().message, Catch::Contains("it is a directory"));
  const Result<std::vector<std::uint8_t>> missing = read_file_bounded(dir / "absent", ReadBound{1024, {}});
  REQUIRE_FALSE(missing);
  CHECK(missing.error().kind == ErrorKind::kIoError);
  CHECK_THAT(missing.error().message, Catch::Contains("No such file or directory"));
  std::filesystem::remove_all(dir);
}

TEST_CASE("a descriptor is read to its end within the bound", "[io][read]") {
  int pipe_ends[2];
  REQUIRE(::pipe(pipe_ends) == 0);
  REQUIRE(::write(pipe_ends[1], "abc", 3) == 3);
  ::close(pipe_ends[1]);
  const Result<std::vector<std::uint8_t>> bytes = read_descriptor_bounded(pipe_ends[0], "<pipe>", ReadBound{3, {}});
  ::close(pipe_ends[0]);
  REQUIRE(bytes);
  CHECK(std::string(bytes->begin(), bytes->end()) == "abc");
}

}  // namespace
}  // namespace curvescan
