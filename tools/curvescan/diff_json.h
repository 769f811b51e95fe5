// JSON and JUnit renderings of image comparisons, shared by both modes of `curvescan diff`
// (the shapes are documented in docs/diff.md, "JSON output" and "Reports").
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "curvescan/diff/image_diff.h"

namespace curvescan::cli {

/// {"verdict", "expected_size", "actual_size", and for equal sizes the metrics of DiffMetrics and the
/// listed regions, [{x, y, width, height, pixels, max_channel_delta}]}; PSNR is null when infinite
/// (identical images) since JSON has no infinity; the bounds are null when empty.
nlohmann::json comparison_json(const ImageComparison& comparison);

/// The options that decided the verdicts: metric, threshold or tolerance, AA, regions, per-image limits.
nlohmann::json options_json(const DiffOptions& options);

/// A JUnit XML document (the de-facto schema read by Jenkins, GitLab and GitHub test reporters): one
/// <testcase> per entry, a <failure> for failed/new/missing, an <error> for unreadable files.
/// `seconds` holds the time each entry took, same order as `entries`.
std::string junit_xml(const std::vector<DiffReportEntry>& entries, const std::vector<double>& seconds,
                      double total_seconds);

}  // namespace curvescan::cli
