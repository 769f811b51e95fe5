// `curvescan diff` end to end, the report side: difference regions in the text and JSON output, the
// statuses of the summary, the pruning of an earlier report's images, --help and the error messages.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>
#include <regex>

#include "curvescan/diff/image_diff.h"
#include "curvescan/raster/png_io.h"
#include "diff_test_support.h"

using namespace curvescan;
using namespace curvescan::test;

namespace {

namespace fs = std::filesystem;
constexpr Rgba8 kGreen{0, 160, 0, 255};
constexpr Rgba8 kBlue{0, 0, 200, 255};

std::string q(const fs::path& path) {
  return shell_quote(path.string());
}

void save(const Image& image, const fs::path& path) {
  fs::create_directories(path.parent_path());
  REQUIRE(write_png(image, path).is_ok());
}

}  // namespace

TEST_CASE("diff --json lists the difference regions with their pixels and largest delta",
          "[diff][cli][regions]") {
  ScratchDirectory dir("cli-regions");
  const Image a = filled(40, 30, kGreen);
  Image b = a;
  paint(b, 24, 8, 32, 16, kBlue);                 // 64 pixels, largest delta 200 (blue channel)
  paint(b, 2, 25, 4, 27, Rgba8{0, 100, 0, 255});  // 4 pixels, largest delta 60
  save(a, dir / "a.png");
  save(b, dir / "b.png");
  const CommandOutput out = run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --json", dir.path());
  REQUIRE(out.exit_code == 1);
  const nlohmann::json json = nlohmann::json::parse(out.out);
  CHECK(json["region_count"] == 2);
  CHECK(json["regions"] == nlohmann::json::parse(R"([
    {"x": 24, "y": 8, "width": 8, "height": 8, "pixels": 64, "max_channel_delta": 200},
    {"x": 2, "y": 25, "width": 2, "height": 2, "pixels": 4, "max_channel_delta": 60}])"));
  CHECK(json["options"]["region_gap"] == 3);
  CHECK(json["options"]["max_regions"] == 50);

  const CommandOutput capped =
      run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --max-regions 1", dir.path());
  CHECK_THAT(capped.out, Catch::Contains("regions             2 (the largest 1 listed)"));
  CHECK_THAT(capped.out, Catch::Contains("region 1  x=24 y=8 w=8 h=8  64 pixels, max channel |delta| 200"));
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --region-gap 65", dir.path()).exit_code == 64);
}

TEST_CASE("directory mode: statuses, regions in summary.json, and pruning of an earlier report's images",
          "[diff][cli][manifest]") {
  ScratchDirectory dir("cli-prune");
  const Image a = filled(20, 20, kGreen);
  Image changed = a;
  paint(changed, 5, 5, 8, 8, kBlue);
  save(a, dir / "expected/one.png");
  save(changed, dir / "actual/one.png");
  save(a, dir / "expected/two/deep.png");
  save(changed, dir / "actual/two/deep.png");
  save(a, dir / "expected/size.png");
  save(filled(21, 20, kGreen), dir / "actual/size.png");
  const std::string args = "--expected " + q(dir / "expected") + " --actual " + q(dir / "actual") +
                           " --report " + q(dir / "report");
  REQUIRE(run_diff(args, dir.path()).exit_code == 1);

  const nlohmann::json summary = nlohmann::json::parse(read_text(dir / "report/summary.json"));
  CHECK(summary["counts"]["failed"] == 3);         // the size mismatch is a failure ...
  CHECK(summary["counts"]["size_mismatch"] == 1);  // ... counted apart as well
  std::map<std::string, std::string> status;
  for (const auto& file : summary["files"]) status[file["name"]] = file["status"];
  CHECK(status == std::map<std::string, std::string>{
                      {"one.png", "failed"}, {"size.png", "size-mismatch"}, {"two/deep.png", "failed"}});
  for (const auto& file : summary["files"]) {
    if (file["name"] != "one.png") continue;
    CHECK(
        file["comparison"]["regions"] ==
        nlohmann::json::parse(R"([{"x":5,"y":5,"width":3,"height":3,"pixels":9,"max_channel_delta":200}])"));
  }
  CHECK(fs::exists(dir / "report/images/two/deep.png/diff.png"));
  CHECK(fs::exists(dir / "report" / kReportManifestName));

  // A user's file in the report directory, and one of the report's images edited by a user.
  write_text(dir / "report/images/notes.txt", "mine");
  write_text(dir / "report/images/size.png/actual.png", "edited");

  // Fix two of the three: their images are stale now and go; the user's files stay.
  save(a, dir / "actual/two/deep.png");
  save(a, dir / "actual/size.png");
  const CommandOutput second = run_diff(args, dir.path());
  CHECK(second.exit_code == 1);
  CHECK_THAT(second.out, Catch::Contains("removed 4 stale files of an earlier report"));
  CHECK_THAT(second.out, Catch::Contains("kept 1 files of an earlier report that changed since"));
  CHECK_FALSE(fs::exists(dir / "report/images/two"));
  CHECK(fs::exists(dir / "report/images/one.png/diff.png"));
  CHECK(read_text(dir / "report/images/notes.txt") == "mine");
  CHECK(read_text(dir / "report/images/size.png/actual.png") == "edited");
  CHECK_FALSE(fs::exists(dir / "report/images/size.png/expected.png"));

  // Everything passes: no image is left but the user's.
  save(a, dir / "actual/one.png");
  CHECK(run_diff(args, dir.path()).exit_code == 0);
  CHECK_FALSE(fs::exists(dir / "report/images/one.png"));
  CHECK(fs::exists(dir / "report/images/notes.txt"));
  CHECK(fs::exists(dir / "report/index.html"));
}

TEST_CASE("diff --help lists every option in words with its default, and examples", "[diff][cli][help]") {
  ScratchDirectory dir("cli-help");
  const CommandOutput help = run_shell(shell_quote(curvescan_binary()) + " diff --help", dir.path());
  REQUIRE(help.exit_code == 0);
  for (const char* option :
       {"-o, --output", "--json", "--threshold", "--channel-tolerance", "--ignore-aa", "--ignore X,Y,W,H",
        "--max-pixels", "--max-percent", "--region-gap", "--max-regions", "--expected", "--actual",
        "--report", "--update", "--jobs", "--max-input-size", "--max-memory"}) {
    CHECK_THAT(help.out, Catch::Contains(option));
  }
  // Every option with a value states its default; no parser type name (TEXT, INT, FLOAT, UINT) shows.
  for (const char* stated : {"Default 0.1", "Default 3", "Default 50", "Default 64", "Default 1024",
                             "Default: all hardware threads", "Default: none", "in MiB", "pixels"}) {
    CHECK_THAT(help.out, Catch::Contains(stated));
  }
  CHECK_FALSE(std::regex_search(help.out, std::regex("\\b(TEXT|INT|FLOAT|UINT|NONNEGATIVE|FINITE)\\b")));
  // Two or three examples, each a complete command.
  const std::regex command_line("\n  curvescan diff \\S");
  const std::ptrdiff_t examples = std::distance(
      std::sregex_iterator(help.out.begin(), help.out.end(), command_line), std::sregex_iterator());
  CHECK(examples >= 2 + 2);  // the two forms and at least two examples
  CHECK_THAT(help.out, Catch::Contains("Examples:"));
}

TEST_CASE("diff errors name the file and say what to do", "[diff][cli][errors]") {
  ScratchDirectory dir("cli-errors");
  save(filled(4, 4, kGreen), dir / "a.png");
  write_text(dir / "text.png", "this is not a PNG");
  const CommandOutput not_png = run_diff(q(dir / "a.png") + " " + q(dir / "text.png"), dir.path());
  CHECK(not_png.exit_code == 3);
  CHECK_THAT(not_png.err, Catch::Contains((dir / "text.png").string()));
  CHECK_THAT(not_png.err, Catch::Contains("give a PNG image"));
  const CommandOutput absent = run_diff(q(dir / "a.png") + " " + q(dir / "absent.png"), dir.path());
  CHECK(absent.exit_code == 3);
  CHECK_THAT(absent.err, Catch::Contains((dir / "absent.png").string()));
  CHECK_THAT(absent.err, Catch::Contains("check the path"));

  const CommandOutput no_dir = run_diff(
      "--expected " + q(dir / "nowhere") + " --actual " + q(dir / "a.png") + " --report " + q(dir / "report"),
      dir.path());
  CHECK(no_dir.exit_code == 3);
  CHECK_THAT(no_dir.err, Catch::Contains("--expected '" + (dir / "nowhere").string() + "' does not exist"));
  CHECK_THAT(no_dir.err, Catch::Contains("give the directory that holds the expected PNG files"));
  CHECK_FALSE(fs::exists(dir / "report"));  // nothing is written before the inputs are checked

  fs::create_directories(dir / "e");
  const CommandOutput file_as_dir = run_diff(
      "--expected " + q(dir / "e") + " --actual " + q(dir / "a.png") + " --report " + q(dir / "report"),
      dir.path());
  CHECK_THAT(file_as_dir.err,
             Catch::Contains("--actual '" + (dir / "a.png").string() + "' is not a directory"));
}
