// The HTML report opened in headless Chromium: its images load and its script runs without error.
//
// The page marks <body data-report-ready="1" data-images-loaded=N data-images-broken=M> when its script
// finished and every image settled (image_diff.h); --dump-dom prints the DOM after the load event, so
// the attributes show whether the script ran. Chromium is a required test dependency (build.sh installs
// the Debian package): without it this test fails, it does not skip.
#include <catch2/catch.hpp>
#include <regex>

#include "curvescan/diff/image_diff.h"
#include "curvescan/raster/png_io.h"
#include "diff_test_support.h"

using namespace curvescan;
using namespace curvescan::test;

namespace {

constexpr const char* kChromium = "/usr/bin/chromium";

std::string dump_dom(const std::filesystem::path& html, const ScratchDir& scratch) {
  const std::filesystem::path profile = scratch / "chromium-profile";
  std::filesystem::create_directories(profile);
  const std::string command = std::string(kChromium) +
                              " --headless --no-sandbox --disable-gpu --disable-quic --no-first-run"
                              " --disable-background-networking --disable-component-update --disable-sync"
                              " --user-data-dir=" +
                              shell_quote(profile.string()) + " --enable-logging=stderr --v=0" +
                              " --virtual-time-budget=10000 --dump-dom " +
                              shell_quote("file://" + relative_url(html));
  const CommandOutput out = run_shell("timeout 120 " + command, scratch.path());
  INFO("chromium stderr: " << out.err);
  REQUIRE(out.exit_code == 0);
  return out.out;
}

std::string body_attribute(const std::string& dom, const std::string& name) {
  const std::regex pattern("<body[^>]*\\s" + name + "=\"([^\"]*)\"");
  std::smatch match;
  return std::regex_search(dom, match, pattern) ? match[1].str() : std::string("<absent>");
}

}  // namespace

TEST_CASE("the HTML report loads in headless Chromium: images load, the script runs",
          "[diff][report][browser]") {
  INFO("install Chromium (Debian package 'chromium'): the report test needs " << kChromium);
  REQUIRE(std::filesystem::exists(kChromium));

  ScratchDir dir("report-browser");
  const Image expected = filled(32, 24, Rgba8{200, 200, 200, 255});
  Image actual = expected;
  paint(actual, 5, 5, 15, 12, Rgba8{0, 0, 128, 255});
  std::filesystem::create_directories(dir / "images dir");
  REQUIRE(write_png(expected, dir / "images dir/expected.png").is_ok());
  REQUIRE(write_png(actual, dir / "images dir/actual.png").is_ok());
  Result<ImageComparison> comparison = compare_images(expected, actual, {});
  REQUIRE(comparison.is_ok());
  REQUIRE(write_png(comparison->diff_image, dir / "images dir/diff.png").is_ok());

  DiffReportEntry failed;
  failed.name = "scenes/<quoted & odd> name.png";  // escaped in the page
  failed.outcome = DiffOutcome::kFailed;
  failed.message = describe_comparison(*comparison);
  failed.comparison = std::move(*comparison);
  failed.expected_image = relative_url("images dir/expected.png");
  failed.actual_image = relative_url("images dir/actual.png");
  failed.diff_image = relative_url("images dir/diff.png");
  DiffReportEntry added;
  added.name = "new.png";
  added.outcome = DiffOutcome::kNew;
  added.actual_image = relative_url("images dir/actual.png");
  DiffReportEntry passed;
  passed.name = "passed.png";
  REQUIRE(write_html_report(dir / "report.html", "browser test", {failed, added, passed}, {}).is_ok());

  const std::string dom = dump_dom(std::filesystem::absolute(dir / "report.html"), dir);
  INFO("DOM: " << dom.substr(0, 2000));
  CHECK(body_attribute(dom, "data-report-ready") == "1");
  CHECK(body_attribute(dom, "data-script-error") == "<absent>");
  // side by side 3 + diff view 1 + slider 2 + toggle 1, and the new entry's 1.
  CHECK(body_attribute(dom, "data-images-loaded") == "8");
  CHECK(body_attribute(dom, "data-images-broken") == "0");
  CHECK_THAT(dom, Catch::Contains("&lt;quoted &amp; odd&gt; name.png"));
}
