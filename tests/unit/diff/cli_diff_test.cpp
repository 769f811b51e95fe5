// `curvescan diff` end to end through the built binary: every exit code, the JSON shape, directory mode's
// grouping, reports and --update.
#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "curvescan/raster/png_io.h"
#include "diff_test_support.h"

using namespace curvescan;
using namespace curvescan::test;

namespace {

constexpr Rgba8 kGrey{100, 100, 100, 255};

std::string q(const std::filesystem::path& path) {
  return shell_quote(path.string());
}

void save(const Image& image, const std::filesystem::path& path) {
  std::filesystem::create_directories(path.parent_path());
  REQUIRE(write_png(image, path).is_ok());
}

}  // namespace

TEST_CASE("the curvescan binary exists", "[diff][cli]") {
  INFO("build the curvescan target first: " << curvescan_binary());
  REQUIRE(std::filesystem::exists(curvescan_binary()));
}

TEST_CASE("pair mode exit codes: 0 same, 1 different, 2 size mismatch, 3 error, 64 usage", "[diff][cli]") {
  ScratchDirectory dir("cli-exit");
  const Image a = filled(8, 8, kGrey);
  Image b = a;
  paint(b, 2, 2, 4, 3, Rgba8{0, 0, 0, 255});  // 2 pixels
  save(a, dir / "a.png");
  save(b, dir / "b.png");
  save(filled(8, 9, kGrey), dir / "tall.png");
  std::ofstream(dir / "corrupt.png", std::ios::binary) << "\x89PNG\r\n\x1a\n truncated";

  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "a.png"), dir.path()).exit_code == 0);
  const CommandOutput different = run_diff(q(dir / "a.png") + " " + q(dir / "b.png"), dir.path());
  CHECK(different.exit_code == 1);
  CHECK_THAT(different.out, Catch::Contains("differing pixels    2"));
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --max-pixels 2", dir.path()).exit_code == 0);
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --max-percent 3.125", dir.path()).exit_code ==
        0);
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --ignore 2,2,2,1", dir.path()).exit_code == 0);
  // Repeated --ignore before the images: each takes one rectangle, the files stay positional.
  CHECK(run_diff("--ignore 2,2,1,1 --ignore 3,2,1,1 " + q(dir / "a.png") + " " + q(dir / "b.png"), dir.path())
            .exit_code == 0);
  CHECK(run_diff("--ignore 2,2,1,1 " + q(dir / "a.png") + " " + q(dir / "b.png"), dir.path()).exit_code == 1);
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "tall.png"), dir.path()).exit_code == 2);

  const CommandOutput corrupt = run_diff(q(dir / "a.png") + " " + q(dir / "corrupt.png"), dir.path());
  CHECK(corrupt.exit_code == 3);
  CHECK_THAT(corrupt.err, Catch::StartsWith("curvescan diff: error: "));
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "absent.png"), dir.path()).exit_code == 3);
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --ignore 1,2,x", dir.path()).exit_code == 64);
  // A number past INT_MAX is refused as a usage error, not read as whatever scanf's overflow gives; a
  // trailing field or comma is refused too; blanks around the numbers and a '+' are accepted.
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --ignore 0,0,99999999999,1", dir.path())
            .exit_code == 64);
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --ignore 1,2,3,4,", dir.path()).exit_code ==
        64);
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --ignore 1,2,3,4,5", dir.path()).exit_code ==
        64);
  CHECK(
      run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --ignore '2, 2 ,+2,1'", dir.path()).exit_code ==
      0);
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --threshold 2", dir.path()).exit_code == 64);
  CHECK(run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --threshold 0.2 --channel-tolerance 3",
                 dir.path())
            .exit_code == 64);

  const CommandOutput help = run_shell(shell_quote(curvescan_binary()) + " diff --help", dir.path());
  CHECK(help.exit_code == 0);
  CHECK_THAT(help.out, Catch::Contains("Exit codes: 0"));
}

TEST_CASE("pair mode --json has the documented shape, and -o writes the diff image", "[diff][cli]") {
  ScratchDirectory dir("cli-json");
  const Image a = filled(10, 6, kGrey);
  Image b = a;
  paint(b, 7, 1, 9, 4, Rgba8{255, 255, 255, 255});
  save(a, dir / "a.png");
  save(b, dir / "b.png");
  const CommandOutput out =
      run_diff(q(dir / "a.png") + " " + q(dir / "b.png") + " --json -o " + q(dir / "diff.png"), dir.path());
  REQUIRE(out.exit_code == 1);
  const nlohmann::json json = nlohmann::json::parse(out.out);
  CHECK(json["verdict"] == "different");
  CHECK(json["expected_size"] == nlohmann::json::array({10, 6}));
  CHECK(json["actual_size"] == nlohmann::json::array({10, 6}));
  CHECK(json["different_pixels"] == 6);
  CHECK(json["total_pixels"] == 60);
  CHECK(json["max_channel_delta"] == 155);
  CHECK(json["difference_bounds"] == nlohmann::json({{"x", 7}, {"y", 1}, {"width", 2}, {"height", 3}}));
  for (const char* key :
       {"compared_pixels", "changed_pixels", "different_percent", "antialiased_pixels", "mean_channel_delta",
        "rmse", "psnr", "options", "expected", "actual", "diff_image"}) {
    CHECK(json.contains(key));
  }
  CHECK(json["options"]["metric"] == "perceptual");
  CHECK(json["diff_image"] == (dir / "diff.png").string());
  const Result<Image> diff = read_png(dir / "diff.png");
  REQUIRE(diff.is_ok());
  CHECK(diff->at(7, 1) == Rgba8{255, 0, 0, 255});

  const CommandOutput same = run_diff(q(dir / "a.png") + " " + q(dir / "a.png") + " --json", dir.path());
  REQUIRE(same.exit_code == 0);
  CHECK(nlohmann::json::parse(same.out)["psnr"].is_null());  // infinite PSNR: JSON has no infinity
}

TEST_CASE("directory mode groups failed / new / missing / passed and writes HTML, JSON and JUnit",
          "[diff][cli]") {
  ScratchDirectory dir("cli-dir");
  const Image a = filled(12, 12, kGrey);
  Image changed = a;
  paint(changed, 3, 3, 6, 6, Rgba8{0, 0, 0, 255});
  save(a, dir / "expected/same.png");
  save(a, dir / "actual/same.png");
  save(a, dir / "expected/nested/deep/same two.png");
  save(a, dir / "actual/nested/deep/same two.png");
  save(a, dir / "expected/changed.png");
  save(changed, dir / "actual/changed.png");
  save(a, dir / "expected/gone.png");
  save(a, dir / "actual/nested/added.png");
  std::ofstream(dir / "actual/notes.txt") << "not an image: ignored";

  const std::string args = "--expected " + q(dir / "expected") + " --actual " + q(dir / "actual") +
                           " --report " + q(dir / "report");
  const CommandOutput out = run_diff(args, dir.path());
  CHECK(out.exit_code == 1);
  CHECK_THAT(out.out, Catch::Contains("1 failed, 1 new, 1 missing, 2 passed"));

  const nlohmann::json summary = nlohmann::json::parse(read_text(dir / "report/summary.json"));
  CHECK(summary["counts"] ==
        nlohmann::json(
            {{"failed", 1}, {"new", 1}, {"missing", 1}, {"passed", 2}, {"error", 0}, {"size_mismatch", 0}}));
  std::map<std::string, std::string> outcome;
  for (const auto& file : summary["files"]) outcome[file["name"]] = file["outcome"];
  CHECK(outcome == std::map<std::string, std::string>{{"changed.png", "failed"},
                                                      {"gone.png", "missing"},
                                                      {"nested/added.png", "new"},
                                                      {"nested/deep/same two.png", "passed"},
                                                      {"same.png", "passed"}});
  CHECK(std::filesystem::exists(dir / "report/images/changed.png/diff.png"));
  CHECK(std::filesystem::exists(dir / "report/images/changed.png/expected.png"));
  CHECK(std::filesystem::exists(dir / "report/images/changed.png/actual.png"));

  const std::string junit = read_text(dir / "report/junit.xml");
  CHECK_THAT(junit, Catch::Contains("tests=\"5\" failures=\"3\" errors=\"0\""));
  CHECK_THAT(junit, Catch::Contains("<testcase classname=\"curvescan.diff\" name=\"changed.png\""));
  const std::string html = read_text(dir / "report/index.html");
  CHECK_THAT(html, Catch::Contains("<b class=\"count\" data-status=\"failed\">1</b>"));
  CHECK_THAT(html, Catch::Contains("images/changed.png/diff.png"));
  CHECK_THAT(html, !Catch::Contains("http://") && !Catch::Contains("https://"));  // no external resource

  // A report directory inside the actual tree is not scanned as actual images on the next run.
  const std::string inside = "--expected " + q(dir / "expected") + " --actual " + q(dir / "actual") +
                             " --report " + q(dir / "actual/report");
  CHECK(run_diff(inside, dir.path()).exit_code == 1);
  CHECK_THAT(run_diff(inside, dir.path()).out, Catch::Contains("1 failed, 1 new, 1 missing, 2 passed"));
  std::filesystem::remove_all(dir / "actual/report");

  // --update resolves failed and new files; the missing one still fails the run.
  const CommandOutput updated = run_diff(args + " --update", dir.path());
  CHECK(updated.exit_code == 1);
  CHECK_THAT(updated.out, Catch::Contains("copied 2 actual images"));
  const CommandOutput after = run_diff(args, dir.path());
  CHECK_THAT(after.out, Catch::Contains("0 failed, 0 new, 1 missing, 4 passed"));
  std::filesystem::remove(dir / "expected/gone.png");
  CHECK(run_diff(args, dir.path()).exit_code == 0);

  // An unreadable file is an error: exit code 3, listed with the failures.
  std::ofstream(dir / "actual/same.png", std::ios::binary | std::ios::trunc) << "garbage";
  const CommandOutput broken = run_diff(args, dir.path());
  CHECK(broken.exit_code == 3);
  CHECK_THAT(broken.out, Catch::Contains("error\tsame.png"));
}
