#include "diff_json.h"

#include <cmath>
#include <cstdio>

namespace curvescan::cli {
namespace {

std::string seconds_text(double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4f", seconds);
  return buffer;
}

std::string_view verdict_name(DiffVerdict verdict) {
  switch (verdict) {
    case DiffVerdict::kSame:
      return "same";
    case DiffVerdict::kDifferent:
      return "different";
    case DiffVerdict::kSizeMismatch:
      return "size-mismatch";
  }
  return "different";
}

}  // namespace

nlohmann::json comparison_json(const ImageComparison& comparison) {
  const DiffMetrics& m = comparison.metrics;
  nlohmann::json out;
  out["verdict"] = verdict_name(comparison.verdict);
  out["expected_size"] = {m.expected_width, m.expected_height};
  out["actual_size"] = {m.actual_width, m.actual_height};
  if (comparison.verdict == DiffVerdict::kSizeMismatch) return out;
  out["total_pixels"] = m.total_pixels;
  out["compared_pixels"] = m.compared_pixels;
  out["changed_pixels"] = m.changed_pixels;
  out["different_pixels"] = m.different_pixels;
  out["different_percent"] = m.different_percent;
  out["antialiased_pixels"] = m.antialiased_pixels;
  out["max_channel_delta"] = m.max_channel_delta;
  out["mean_channel_delta"] = m.mean_channel_delta;
  out["rmse"] = m.rmse;
  out["psnr"] = std::isfinite(m.psnr) ? nlohmann::json(m.psnr) : nlohmann::json(nullptr);
  const PixelBox& box = m.difference_bounds;
  out["difference_bounds"] =
      box.empty() ? nlohmann::json(nullptr)
                  : nlohmann::json{{"x", box.x}, {"y", box.y}, {"width", box.width}, {"height", box.height}};
  out["region_count"] = m.region_count;
  nlohmann::json regions = nlohmann::json::array();
  for (const DifferenceRegion& r : comparison.regions) {
    regions.push_back({{"x", r.box.x},
                       {"y", r.box.y},
                       {"width", r.box.width},
                       {"height", r.box.height},
                       {"pixels", r.pixels},
                       {"max_channel_delta", r.max_channel_delta}});
  }
  out["regions"] = std::move(regions);
  return out;
}

nlohmann::json options_json(const DiffOptions& options) {
  nlohmann::json out;
  if (options.metric == PixelMetric::kPerceptual) {
    out["metric"] = "perceptual";
    out["threshold"] = options.yiq_threshold;
  } else {
    out["metric"] = "channel";
    out["channel_tolerance"] = options.channel_tolerance;
  }
  out["ignore_antialiasing"] = options.ignore_antialiasing;
  out["ignore_regions"] = nlohmann::json::array();
  for (const PixelBox& r : options.ignore_regions) {
    out["ignore_regions"].push_back({{"x", r.x}, {"y", r.y}, {"width", r.width}, {"height", r.height}});
  }
  out["max_pixels"] = options.max_different_pixels ? nlohmann::json(*options.max_different_pixels) : nullptr;
  out["max_percent"] =
      options.max_different_percent ? nlohmann::json(*options.max_different_percent) : nullptr;
  out["region_gap"] = options.region_gap;
  out["max_regions"] = options.max_regions;
  return out;
}

std::string junit_xml(const std::vector<DiffReportEntry>& entries, const std::vector<double>& seconds,
                      double total_seconds) {
  std::size_t failures = 0, errors = 0;
  for (const DiffReportEntry& e : entries) {
    if (e.outcome == DiffOutcome::kError) {
      ++errors;
    } else if (e.outcome != DiffOutcome::kPassed) {
      ++failures;
    }
  }
  const std::string counts = " tests=\"" + std::to_string(entries.size()) + "\" failures=\"" +
                             std::to_string(failures) + "\" errors=\"" + std::to_string(errors) +
                             "\" time=\"" + seconds_text(total_seconds) + "\"";
  std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"curvescan diff\"" +
                    counts + ">\n<testsuite name=\"curvescan diff\"" + counts + " skipped=\"0\">\n";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const DiffReportEntry& e = entries[i];
    xml += "<testcase classname=\"curvescan.diff\" name=\"" + markup_escape(e.name) + "\" time=\"" +
           seconds_text(i < seconds.size() ? seconds[i] : 0.0) + "\"";
    if (e.outcome == DiffOutcome::kPassed) {
      xml += "/>\n";
      continue;
    }
    const char* element = e.outcome == DiffOutcome::kError ? "error" : "failure";
    xml += ">\n<" + std::string(element) + " type=\"" + std::string(to_string(e.outcome)) + "\" message=\"" +
           markup_escape(e.message) + "\">" + markup_escape(e.message) + "</" + element + ">\n</testcase>\n";
  }
  xml += "</testsuite>\n</testsuites>\n";
  return xml;
}

}  // namespace curvescan::cli
