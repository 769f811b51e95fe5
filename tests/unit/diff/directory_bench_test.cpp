// The directory-mode throughput measurement of docs/diff.md: 1,000 pairs of 512 x 512 images, one in ten
// different, diffed by the curvescan binary with all hardware threads and with one.
//
// Hidden from the default run (the [.] tag: it takes a minute to write 2,000 PNG files). Run it with
//   build/tests/test_diff "[.bench]"
// and CURVESCAN_DIFF_BENCH_PAIRS=N for another count. It prints the wall time of each run and checks the
// counts of the report, so it also stands as a large end-to-end test.
#include <catch2/catch.hpp>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>

#include "curvescan/raster/png_io.h"
#include "diff_test_support.h"

using namespace curvescan;
using namespace curvescan::test;

TEST_CASE("directory mode on 1,000 pairs of 512 x 512 images", "[.bench][diff]") {
  const char* requested = std::getenv("CURVESCAN_DIFF_BENCH_PAIRS");
  const int pairs = requested != nullptr ? std::max(1, std::atoi(requested)) : 1000;
  constexpr int kSize = 512;
  constexpr int kDifferentEvery = 10;
  ScratchDirectory dir("bench");
  for (int i = 0; i < pairs; ++i) {
    // A busy pattern (so the PNGs are not trivially small) that varies per file.
    Image expected(kSize, kSize);
    for (int y = 0; y < kSize; ++y) {
      for (int x = 0; x < kSize; ++x) {
        expected.at(x, y) =
            Rgba8{static_cast<std::uint8_t>((x * 7 + i) & 255), static_cast<std::uint8_t>((y * 3) & 255),
                  static_cast<std::uint8_t>(((x ^ y) + i) & 255), 255};
      }
    }
    Image actual = expected;
    if (i % kDifferentEvery == 0)
      paint(actual, kSize / 3, kSize / 4, kSize / 2, kSize / 2, Rgba8{0, 0, 0, 255});
    const std::string name = "scene" + std::to_string(i) + ".png";
    std::filesystem::create_directories(dir / "expected");
    std::filesystem::create_directories(dir / "actual");
    REQUIRE(write_png(expected, dir / "expected" / name).is_ok());
    REQUIRE(write_png(actual, dir / "actual" / name).is_ok());
  }
  const int failing = (pairs + kDifferentEvery - 1) / kDifferentEvery;
  for (const char* jobs : {"", " --jobs 1"}) {
    const std::filesystem::path report = dir / (std::string("report") + (jobs[0] != 0 ? "-1" : "-all"));
    const auto start = std::chrono::steady_clock::now();
    const CommandOutput out = run_diff("--expected " + shell_quote((dir / "expected").string()) +
                                           " --actual " + shell_quote((dir / "actual").string()) +
                                           " --report " + shell_quote(report.string()) + jobs,
                                       dir.path());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << "curvescan diff" << jobs << ": " << pairs << " pairs of " << kSize << "x" << kSize << " in "
              << seconds << " s wall\n"
              << out.out;
    CHECK(out.exit_code == 1);
    const nlohmann::json summary = nlohmann::json::parse(read_text(report / "summary.json"));
    CHECK(summary["counts"]["failed"] == failing);
    CHECK(summary["counts"]["passed"] == pairs - failing);
  }
}
