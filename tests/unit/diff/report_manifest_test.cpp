// update_report_manifest: a report removes the stale files it wrote itself, and nothing else — not a
// user's file, not a file changed since, not a path outside the report directory, whatever the manifest
// says.
#include <catch2/catch.hpp>

#include "curvescan/diff/image_diff.h"
#include "diff_test_support.h"

using namespace curvescan;
using namespace curvescan::test;

namespace {

namespace fs = std::filesystem;

void put(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  write_text(path, text);
}

ReportPruning update(const fs::path& dir, const std::vector<std::string>& written) {
  Result<ReportPruning> pruning = update_report_manifest(dir, written);
  INFO((pruning ? std::string() : pruning.error().message));
  REQUIRE(pruning.is_ok());
  return *pruning;
}

}  // namespace

TEST_CASE("report manifest: files the report no longer writes are removed, with their empty directories",
          "[diff][manifest]") {
  ScratchDirectory dir("manifest");
  const fs::path report = dir / "report";
  put(report / "index.html", "one");
  put(report / "images/a.png/diff.png", "diff a");
  put(report / "images/deep/b.png/diff.png", "diff b");
  put(report / "images/user-notes.txt", "mine");  // never written by the report
  put(report / "user.png", "mine too");

  ReportPruning first = update(report, {"index.html", "images/a.png/diff.png", "images/deep/b.png/diff.png"});
  CHECK(first.removed_files == 0);  // no previous manifest: nothing to prune
  CHECK(fs::exists(report / kReportManifestName));

  // Second run: b passes now, so only a's image is written again.
  put(report / "index.html", "two");
  put(report / "images/a.png/diff.png", "diff a, again");
  const ReportPruning second = update(report, {"index.html", "images/a.png/diff.png"});
  CHECK(second.removed_files == 1);
  CHECK(second.removed_directories == 2);  // images/deep/b.png and images/deep
  CHECK(second.kept_changed.empty());
  CHECK_FALSE(fs::exists(report / "images/deep"));
  CHECK(fs::exists(report / "images/a.png/diff.png"));
  CHECK(read_text(report / "images/user-notes.txt") == "mine");
  CHECK(read_text(report / "user.png") == "mine too");
  CHECK(fs::exists(report / "images"));  // still holds a.png and the user's notes

  // Third run writes nothing but the page: a's image goes, the user's files stay.
  const ReportPruning third = update(report, {"index.html"});
  CHECK(third.removed_files == 1);
  CHECK_FALSE(fs::exists(report / "images/a.png"));
  CHECK(fs::exists(report / "images/user-notes.txt"));
}

TEST_CASE("report manifest: a file changed since the report wrote it is kept", "[diff][manifest]") {
  ScratchDirectory dir("manifest-changed");
  const fs::path report = dir / "report";
  put(report / "images/a.png/actual.png", "the report's bytes");
  put(report / "images/b.png/actual.png", "same size 1");
  (void)update(report, {"images/a.png/actual.png", "images/b.png/actual.png"});
  put(report / "images/a.png/actual.png", "a user's bytes, another size");
  put(report / "images/b.png/actual.png", "same size 2");  // same size, other content: the hash decides
  const ReportPruning pruning = update(report, {});
  CHECK(pruning.removed_files == 0);
  CHECK(pruning.kept_changed ==
        std::vector<std::string>{"images/a.png/actual.png", "images/b.png/actual.png"});
  CHECK(fs::exists(report / "images/a.png/actual.png"));
  CHECK(fs::exists(report / "images/b.png/actual.png"));
}

TEST_CASE("report manifest: a tampered manifest cannot reach outside the report directory",
          "[diff][manifest]") {
  ScratchDirectory dir("manifest-hostile");
  const fs::path report = dir / "report";
  const fs::path outside = dir / "outside";
  put(outside / "precious.txt", "keep");
  put(report / "index.html", "page");
  (void)update(report, {"index.html"});
  const std::string manifest = read_text(report / kReportManifestName);

  // The outside file's own size and hash, listed under hostile paths. A listed line's stamp is copied
  // from a manifest that listed a file with the same bytes.
  put(dir / "probe/precious.txt", "keep");
  (void)update(dir / "probe", {"precious.txt"});
  const std::string probe = read_text(dir / "probe" / kReportManifestName);
  const std::string stamp = probe.substr(probe.find('\n') + 1, probe.rfind(' ') - probe.find('\n'));
  fs::create_directory_symlink(outside, report / "link");
  write_text(report / kReportManifestName,
             manifest + stamp + "..%2Foutside%2Fprecious.txt\n" + stamp + "../outside/precious.txt\n" +
                 stamp + (outside / "precious.txt").generic_string() + "\n" + stamp + "link/precious.txt\n");
  const ReportPruning pruning = update(report, {"index.html"});
  CHECK(pruning.removed_files == 0);
  CHECK(read_text(outside / "precious.txt") == "keep");
  CHECK(fs::is_symlink(report / "link"));

  // A manifest that is not one (garbage, another format) removes nothing.
  put(report / "images/x.png", "x");
  (void)update(report, {"index.html", "images/x.png"});
  write_text(report / kReportManifestName, "not a manifest\n");
  CHECK(update(report, {"index.html"}).removed_files == 0);
  CHECK(fs::exists(report / "images/x.png"));
}

TEST_CASE("report manifest: names with spaces, percent signs and newlines survive the round trip",
          "[diff][manifest]") {
  ScratchDirectory dir("manifest-names");
  const fs::path report = dir / "report";
  const std::string odd = "images/50% off\nline two/é.png";
  put(report / odd, "bytes");
  (void)update(report, {odd});
  CHECK(update(report, {}).removed_files == 1);
  CHECK_FALSE(fs::exists(report / odd));
}

TEST_CASE("report manifest: a report directory that does not exist is an error naming it",
          "[diff][manifest]") {
  ScratchDirectory dir("manifest-missing");
  const Result<ReportPruning> pruning = update_report_manifest(dir / "nowhere", {});
  REQUIRE_FALSE(pruning.is_ok());
  CHECK_THAT(pruning.error().message, Catch::Contains("nowhere"));
}

TEST_CASE("report manifest: a NUL byte in a listed path, raw or %00, makes the manifest malformed",
          "[diff][manifest]") {
  // The system reads a path up to its first NUL: "index.html\0" named the page the run had just written,
  // under a name not in its written list, and removed it (found by the report_manifest fuzz target). No
  // path holds a NUL (relative_url escapes every control character), so such a manifest is not one of
  // curvescan's: it removes nothing.
  for (const std::string& nul : {std::string(1, '\0'), std::string("%00")}) {
    INFO((nul == "%00" ? "%00" : "a raw NUL"));
    ScratchDirectory dir("manifest-nul");
    const fs::path report = dir / "report";
    put(report / "index.html", "page");
    put(report / "images/x.png", "x");
    (void)update(report, {"index.html", "images/x.png"});
    std::string manifest = read_text(report / kReportManifestName);
    const std::size_t page_line = manifest.find("index.html\n");
    REQUIRE(page_line != std::string::npos);
    manifest.insert(page_line + std::string("index.html").size(), nul);
    write_text(report / kReportManifestName, manifest);
    const ReportPruning pruning = update(report, {"index.html"});
    CHECK(pruning.removed_files == 0);
    CHECK(read_text(report / "index.html") == "page");
    CHECK(fs::exists(report / "images/x.png"));  // the whole manifest is refused, as any malformed one
  }
}
