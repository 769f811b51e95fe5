// Replays the committed fuzz inputs through the fuzz targets (fuzz/targets/), in the normal and the
// sanitizer suite alike: fuzz/corpus/<target>/ (the seed corpora: every seed must run clean) and
// fuzz/regressions/<target>/ (each file an input that once crashed, hung or exhausted memory; its name
// says what broke and fuzz/regressions/README.md which commit fixed it). fuzz/pending/ is not replayed:
// those inputs still fail and wait for their owner's fix.
//
// A target returns 0 for every input; a failure shows as a crash or a sanitizer report, with the file
// named by the SECTION (regressions) or the INFO message (corpus) in Catch2's report.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include <catch2/catch.hpp>

#include "fuzz_targets.h"

namespace {

namespace fs = std::filesystem;
using curvescan::fuzz::FuzzTarget;
using curvescan::fuzz::kFuzzTargets;

const fs::path kFuzzDir = fs::path(CURVESCAN_SOURCE_DIR) / "fuzz";

// The input files of `directory`, sorted, without the README that documents them.
std::vector<fs::path> input_files(const fs::path& directory) {
  std::vector<fs::path> files;
  if (!fs::is_directory(directory)) return files;
  for (const fs::directory_entry& entry : fs::directory_iterator(directory)) {
    if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::uint8_t> file_bytes(const fs::path& path) {
  std::ifstream stream(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(stream), std::istreambuf_iterator<char>()};
}

int replay(const FuzzTarget& target, const fs::path& file) {
  const std::vector<std::uint8_t> bytes = file_bytes(file);
  // data() of an empty vector may be null; libFuzzer passes a valid pointer even for the empty input.
  const std::uint8_t empty = 0;
  return target.function(bytes.empty() ? &empty : bytes.data(), bytes.size());
}

}  // namespace

TEST_CASE("the table of fuzz functions names the targets the build lists", "[fuzz_replay]") {
  // fuzz/CMakeLists.txt holds the one list of targets (it builds them and fuzz/run.sh reads it); the
  // table of functions in fuzz_targets.h must follow it, in the same order, or a target goes unreplayed.
  std::ifstream list(CURVESCAN_FUZZ_TARGET_LIST);
  REQUIRE(list);
  std::vector<std::string> listed;
  for (std::string name; std::getline(list, name);) {
    if (!name.empty()) listed.push_back(name);
  }
  std::vector<std::string> tabled;
  for (const FuzzTarget& target : kFuzzTargets) tabled.emplace_back(target.name);
  CHECK(tabled == listed);
}

TEST_CASE("every fuzz target has a seed corpus", "[fuzz_replay]") {
  for (const FuzzTarget& target : kFuzzTargets) {
    INFO("fuzz/corpus/" << target.name);
    CHECK(input_files(kFuzzDir / "corpus" / std::string(target.name)).size() >= 3);
  }
}

TEST_CASE("the seed corpora replay clean", "[fuzz_replay]") {
  for (const FuzzTarget& target : kFuzzTargets) {
    for (const fs::path& file : input_files(kFuzzDir / "corpus" / std::string(target.name))) {
      INFO("fuzz target " << target.name << ", corpus file " << file.filename().string());
      CHECK(replay(target, file) == 0);
    }
  }
}

TEST_CASE("the fuzz regressions replay clean", "[fuzz_replay][regression]") {
  for (const FuzzTarget& target : kFuzzTargets) {
    for (const fs::path& file : input_files(kFuzzDir / "regressions" / std::string(target.name))) {
      DYNAMIC_SECTION("fuzz/regressions/" << target.name << "/" << file.filename().string()) {
        CHECK(replay(target, file) == 0);
      }
    }
  }
}
