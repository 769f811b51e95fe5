// compare_to_golden: the one call a golden test makes (contract in image_diff.h).
//
// A golden test must leave everything a reviewer needs when it fails, in one place named in the failure
// message: the rendered image, the golden, the diff image and the HTML report with its region boxes and
// its side-by-side, slider and blink views (image_diff_report.cpp). Nothing is written when the test
// passes.
#include <system_error>

#include "curvescan/diff/image_diff.h"
#include "curvescan/raster/png_io.h"

namespace curvescan {

Status compare_to_golden(const Image& actual, const std::filesystem::path& golden, const DiffOptions& options,
                         const std::filesystem::path& report_dir) {
  CURVESCAN_PROPAGATE(validate_diff_options(options));
  std::error_code ec;
  const bool golden_exists = std::filesystem::exists(golden, ec);
  Result<Image> expected =
      golden_exists
          ? read_png(golden)
          : Result<Image>(Error{ErrorKind::kIoError, "the golden '" + golden.string() + "' does not exist"});
  std::optional<ImageComparison> comparison;
  if (expected) {
    DiffOptions with_image = options;
    with_image.make_diff_image = true;
    Result<ImageComparison> compared = compare_images(*expected, actual, with_image);
    if (!compared) return compared.error();
    if (compared->verdict == DiffVerdict::kSame) return Status::ok();
    comparison = std::move(*compared);
  }

  // Failure: write the evidence into report_dir/<stem>/.
  const std::filesystem::path dir = report_dir / golden.stem();
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    return Error{ErrorKind::kIoError,
                 "cannot create the report directory '" + dir.string() + "': " + ec.message()};
  }
  DiffReportEntry entry;
  entry.name = golden.filename().string();
  CURVESCAN_PROPAGATE(write_png(actual, dir / "actual.png"));
  entry.actual_image = "actual.png";
  if (comparison) {
    CURVESCAN_PROPAGATE(write_png(*expected, dir / "expected.png"));
    entry.expected_image = "expected.png";
    if (!comparison->diff_image.empty()) {
      CURVESCAN_PROPAGATE(write_png(comparison->diff_image, dir / "diff.png"));
      entry.diff_image = "diff.png";
    }
    entry.outcome = DiffOutcome::kFailed;
    entry.message = describe_comparison(*comparison);
    comparison->diff_image = Image();  // written; the report needs only the metrics
    entry.comparison = std::move(comparison);
  } else {
    entry.outcome = golden_exists ? DiffOutcome::kError : DiffOutcome::kNew;
    entry.message = expected.error().message;
  }
  const std::filesystem::path report = dir / "index.html";
  CURVESCAN_PROPAGATE(write_html_report(report, "golden " + golden.filename().string(), {entry}, options));

  if (!golden_exists) {
    return Error{ErrorKind::kIoError,
                 entry.message + "; review the rendered image " + (dir / "actual.png").string() +
                     " and copy it there if it is right (report: " + report.string() + ")"};
  }
  if (entry.outcome == DiffOutcome::kError) {
    return Error{expected.error().kind, entry.message + " (report: " + report.string() + ")"};
  }
  return Error{ErrorKind::kInvalidArgument, "the image differs from the golden '" + golden.string() +
                                                "': " + entry.message + "; report: " + report.string()};
}

}  // namespace curvescan
