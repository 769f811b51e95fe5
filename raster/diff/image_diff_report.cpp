// The HTML report of image comparisons (contract in image_diff.h) and the small text helpers it shares
// with the golden helper and the CLI.
//
// The page is one file with inline CSS and JS and no external resource; images are referenced by relative
// URLs (the callers copy them beside the report), which keeps a report of thousands of files small and
// lets a CI system archive the report directory as it is. The cases are listed failures first; each
// failed case shows its difference regions as boxes over its images and offers three views (side by
// side, slider, blink). The style sheet and the script, and what the page does without the script, are
// in report_page_assets.h.

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>
#include <system_error>

#include "curvescan/diff/image_diff.h"
#include "curvescan/raster/file_io.h"
#include "report_page_assets.h"

namespace curvescan {
namespace {

std::string fixed(double value, int decimals) {
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  if (std::isnan(value)) return "nan";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

std::string box_text(const PixelBox& box) {
  if (box.empty()) return "none";
  return "x=" + std::to_string(box.x) + " y=" + std::to_string(box.y) + " w=" + std::to_string(box.width) +
         " h=" + std::to_string(box.height);
}

std::string describe_options(const DiffOptions& options) {
  std::string text =
      options.metric == PixelMetric::kPerceptual
          ? "perceptual YIQ metric, threshold " + fixed(options.yiq_threshold, 3)
          : "per-channel metric, tolerance " + std::to_string(options.channel_tolerance) + " levels";
  text += options.ignore_antialiasing ? "; anti-aliasing ignored" : "; anti-aliasing counted";
  if (!options.ignore_regions.empty()) {
    text += "; " + std::to_string(options.ignore_regions.size()) + " ignore region(s)";
  }
  text += "; tolerance: ";
  if (!options.max_different_pixels && !options.max_different_percent) text += "no differing pixel";
  if (options.max_different_pixels) text += std::to_string(*options.max_different_pixels) + " pixels";
  if (options.max_different_pixels && options.max_different_percent) text += " and ";
  if (options.max_different_percent) text += fixed(*options.max_different_percent, 3) + "%";
  return text;
}

/// The statuses in the report's order: failures first, passed last.
constexpr std::string_view kStatusOrder[] = {"error", "failed", "size-mismatch", "new", "missing", "passed"};

std::size_t status_rank(std::string_view status) {
  for (std::size_t i = 0; i < std::size(kStatusOrder); ++i) {
    if (kStatusOrder[i] == status) return i;
  }
  return std::size(kStatusOrder);
}

std::string percent(double part, int whole) {
  return fixed(whole > 0 ? 100.0 * part / whole : 0.0, 4) + "%";
}

/// The region boxes over one image of `width` x `height` pixels, positioned in percentages of the image so
/// that they follow the zoom. The outline is drawn outside the box, so it never hides a differing pixel.
void write_region_boxes(std::ostringstream& html, const std::vector<DifferenceRegion>& regions, int width,
                        int height) {
  if (regions.empty() || width <= 0 || height <= 0) return;
  html << "<div class=\"boxes\">";
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const DifferenceRegion& r = regions[i];
    html << "<span class=\"box\" style=\"left:" << percent(r.box.x, width)
         << ";top:" << percent(r.box.y, height) << ";width:" << percent(r.box.width, width)
         << ";height:" << percent(r.box.height, height) << "\" title=\"region " << (i + 1) << ": "
         << box_text(r.box) << ", " << r.pixels << " pixels, max channel delta " << r.max_channel_delta
         << "\"></span>";
  }
  html << "</div>";
}

void write_metrics_table(std::ostringstream& html, const ImageComparison& c) {
  const DiffMetrics& m = c.metrics;
  const auto row = [&](const char* label, const std::string& value) {
    html << "<tr><td>" << label << "</td><td>" << markup_escape(value) << "</td></tr>";
  };
  html << "<details class=\"metrics\"><summary>metrics</summary><table class=\"metrics\">";
  if (c.verdict == DiffVerdict::kSizeMismatch) {
    row("expected size", std::to_string(m.expected_width) + " x " + std::to_string(m.expected_height));
    row("actual size", std::to_string(m.actual_width) + " x " + std::to_string(m.actual_height));
  } else {
    row("size", std::to_string(m.expected_width) + " x " + std::to_string(m.expected_height));
    row("differing pixels", std::to_string(m.different_pixels) + " (" + fixed(m.different_percent, 3) + "%)");
    row("anti-aliasing pixels", std::to_string(m.antialiased_pixels));
    row("changed pixels (any byte)", std::to_string(m.changed_pixels));
    row("max channel |delta|", std::to_string(m.max_channel_delta));
    row("mean channel |delta|", fixed(m.mean_channel_delta, 4));
    row("RMSE", fixed(m.rmse, 4));
    row("PSNR", fixed(m.psnr, 2) + " dB");
    row("differences in", box_text(m.difference_bounds));
    row("difference regions", std::to_string(m.region_count));
  }
  html << "</table></details>\n";
}

/// The listed regions, numbered as their boxes' tooltips are, with what was left out.
void write_region_list(std::ostringstream& html, const ImageComparison& c) {
  if (c.regions.empty()) return;
  html << "<ol class=\"regions\">";
  for (const DifferenceRegion& r : c.regions) {
    html << "<li>" << box_text(r.box) << ": " << r.pixels << " pixels, max channel delta "
         << r.max_channel_delta << "</li>";
  }
  html << "</ol>";
  if (c.metrics.region_count > c.regions.size()) {
    html << "<p class=\"message\">and " << (c.metrics.region_count - c.regions.size())
         << " smaller regions (not boxed)</p>";
  }
  html << "\n";
}

std::string image_tag(const std::string& url, const std::string& alt, const char* extra = "") {
  return "<img src=\"" + markup_escape(url) + "\" alt=\"" + markup_escape(alt) + "\"" + extra + ">";
}

/// One image in a frame that carries the region boxes, with a caption.
void write_figure(std::ostringstream& html, const std::string& url, const char* caption,
                  const std::vector<DifferenceRegion>& regions, int width, int height) {
  if (url.empty()) return;
  html << "<figure><div class=\"frame\">" << image_tag(url, caption);
  write_region_boxes(html, regions, width, height);
  html << "</div><figcaption>" << caption << "</figcaption></figure>";
}

void write_entry(std::ostringstream& html, const DiffReportEntry& entry, std::size_t index) {
  const std::string_view status = report_status(entry);
  const bool has_views = !entry.expected_image.empty() && !entry.actual_image.empty();
  const bool compact = entry.outcome == DiffOutcome::kPassed;
  html << "<article class=\"case" << (compact ? " compact" : "") << "\" id=\"case-" << index
       << "\" data-status=\"" << status << "\" tabindex=\"-1\""
       << (has_views ? " data-views data-view=\"side\" data-frame=\"expected\"" : "")
       << "><h2><a href=\"#case-" << index << "\">" << markup_escape(entry.name)
       << "</a><span class=\"badge s-" << status << "\">" << status << "</span></h2>\n";
  if (!entry.message.empty()) {
    html << "<p class=\"message\">" << markup_escape(entry.message) << "</p>\n";
  } else if (entry.comparison) {
    html << "<p class=\"message\">" << markup_escape(describe_comparison(*entry.comparison)) << "</p>\n";
  }
  if (compact) {
    html << "</article>\n";
    return;
  }
  const std::vector<DifferenceRegion> no_regions;
  const std::vector<DifferenceRegion>& regions = entry.comparison ? entry.comparison->regions : no_regions;
  const int width = entry.comparison ? entry.comparison->metrics.expected_width : 0;
  const int height = entry.comparison ? entry.comparison->metrics.expected_height : 0;
  if (entry.comparison) {
    write_metrics_table(html, *entry.comparison);
    write_region_list(html, *entry.comparison);
  }
  if (!has_views) {
    html << "<div>";
    write_figure(html, entry.expected_image, "expected", no_regions, 0, 0);
    write_figure(html, entry.actual_image, "actual", no_regions, 0, 0);
    html << "</div></article>\n";
    return;
  }
  html << "<div class=\"views\" role=\"group\" aria-label=\"view\">"
          "<button type=\"button\" class=\"on\" data-view=\"side\">side by side</button>"
          "<button type=\"button\" data-view=\"slider\">slider</button>"
          "<button type=\"button\" data-view=\"blink\">blink</button></div>\n";
  html << "<div class=\"view\" data-view=\"side\">";
  write_figure(html, entry.expected_image, "expected", regions, width, height);
  write_figure(html, entry.actual_image, "actual", regions, width, height);
  write_figure(html, entry.diff_image, "diff (red: different, yellow: anti-aliasing, blue: ignored)", regions,
               width, height);
  html << "</div>\n";
  html << "<div class=\"view\" data-view=\"slider\" hidden><div class=\"frame slider\">"
       << image_tag(entry.expected_image, "expected")
       << image_tag(entry.actual_image, "actual", " class=\"over\"")
       << "<div class=\"handle\" style=\"left:50%\"></div>";
  write_region_boxes(html, regions, width, height);
  html
      << "</div><label class=\"slider-label\">actual left of the line, expected right: <input type=\"range\" "
         "class=\"slider-range\" min=\"0\" max=\"100\" value=\"50\" aria-label=\"slider position, percent\">"
         "</label></div>\n";
  html << "<div class=\"view\" data-view=\"blink\" hidden><div class=\"frame blink\" title=\"click to flip\">"
       << image_tag(entry.expected_image, "expected")
       << image_tag(entry.actual_image, "actual", " class=\"over\"");
  write_region_boxes(html, regions, width, height);
  html << "</div><p class=\"blink-state\">showing <b>expected</b></p></div>\n</article>\n";
}

constexpr const char* kKeyboardHelp =
    "<details class=\"keys\" open><summary>Keyboard shortcuts</summary><table>"
    "<tr><td><kbd>j</kbd> / <kbd>k</kbd></td><td>next / previous case (<kbd>n</kbd> / <kbd>p</kbd> "
    "too)</td></tr>"
    "<tr><td><kbd>1</kbd> <kbd>2</kbd> <kbd>3</kbd></td><td>every case side by side / slider / "
    "blink</td></tr>"
    "<tr><td><kbd>&#8592;</kbd> <kbd>&#8594;</kbd></td><td>move the current case's slider by 5%</td></tr>"
    "<tr><td><kbd>b</kbd></td><td>pause or resume blinking</td></tr>"
    "<tr><td><kbd>t</kbd></td><td>show the other image (pauses blinking; clicking the image does the "
    "same)</td></tr>"
    "<tr><td><kbd>r</kbd></td><td>show or hide the region boxes</td></tr>"
    "<tr><td><kbd>+</kbd> / <kbd>-</kbd></td><td>zoom in / out (1x to 8x)</td></tr>"
    "</table></details>\n";

}  // namespace

std::string_view report_status(const DiffReportEntry& entry) noexcept {
  if (entry.outcome == DiffOutcome::kFailed && entry.comparison &&
      entry.comparison->verdict == DiffVerdict::kSizeMismatch) {
    return "size-mismatch";
  }
  return to_string(entry.outcome);
}

std::string_view to_string(DiffOutcome outcome) noexcept {
  switch (outcome) {
    case DiffOutcome::kPassed:
      return "passed";
    case DiffOutcome::kFailed:
      return "failed";
    case DiffOutcome::kNew:
      return "new";
    case DiffOutcome::kMissing:
      return "missing";
    case DiffOutcome::kError:
      return "error";
  }
  return "error";
}

std::string relative_url(const std::filesystem::path& relative_path) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : relative_path.generic_string()) {
    const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '.' || c == '_' || c == '~' || c == '/';
    if (keep) {
      out += static_cast<char>(c);
    } else {
      out += '%';
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

Status write_text_file_atomically(const std::filesystem::path& path, std::string_view text) {
  std::error_code ec;
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path(), ec);
  if (ec) {
    return Error{ErrorKind::kIoError,
                 "cannot create the directory '" + path.parent_path().string() + "': " + ec.message()};
  }
  return write_output_file(path, text);
}

std::string describe_comparison(const ImageComparison& c) {
  const DiffMetrics& m = c.metrics;
  if (c.verdict == DiffVerdict::kSizeMismatch) {
    return "the sizes differ: expected " + std::to_string(m.expected_width) + " x " +
           std::to_string(m.expected_height) + ", actual " + std::to_string(m.actual_width) + " x " +
           std::to_string(m.actual_height);
  }
  std::string text = std::to_string(m.different_pixels) + " of " + std::to_string(m.total_pixels) +
                     " pixels differ (" + fixed(m.different_percent, 3) + "%)";
  if (m.antialiased_pixels > 0)
    text += ", " + std::to_string(m.antialiased_pixels) + " anti-aliasing pixels ignored";
  text += ", max channel delta " + std::to_string(m.max_channel_delta) + ", RMSE " + fixed(m.rmse, 3) +
          ", PSNR " + fixed(m.psnr, 2) + " dB";
  if (!m.difference_bounds.empty()) text += ", in the box " + box_text(m.difference_bounds);
  return text;
}

Status write_html_report(const std::filesystem::path& html_file, std::string_view title,
                         const std::vector<DiffReportEntry>& entries, const DiffOptions& options) {
  // Failures first: the cases ordered by status rank, each status in the callers' order.
  std::vector<std::size_t> order(entries.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return status_rank(report_status(entries[a])) < status_rank(report_status(entries[b]));
  });
  std::size_t counts[std::size(kStatusOrder) + 1] = {};
  for (const DiffReportEntry& entry : entries) ++counts[status_rank(report_status(entry))];

  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       << "<meta name=\"viewport\" content=\"width=device-width,initial-scale=1\"><title>"
       << markup_escape(title) << "</title><style>" << detail::kReportStyle
       << "</style></head>\n<body>\n<header><h1>" << markup_escape(title) << "</h1>\n<p class=\"options\">"
       << entries.size() << " files compared: " << markup_escape(describe_options(options)) << ".</p>\n"
       << "<div class=\"filters\" role=\"group\" aria-label=\"show the files of status\">show:";
  for (std::size_t i = 0; i < std::size(kStatusOrder); ++i) {
    const std::string_view status = kStatusOrder[i];
    html << "<label class=\"chip s-" << status << "\"><input type=\"checkbox\" data-status=\"" << status
         << "\" checked> " << status << " <b class=\"count\" data-status=\"" << status << "\">" << counts[i]
         << "</b></label>";
  }
  html << "</div>\n<div class=\"toolbar\">view of every case: "
          "<button type=\"button\" class=\"on\" data-view=\"side\">side by side (1)</button>"
          "<button type=\"button\" data-view=\"slider\">slider (2)</button>"
          "<button type=\"button\" data-view=\"blink\">blink (3)</button>"
          "<label>blink every <select id=\"interval\"><option value=\"250\">250 ms</option>"
          "<option value=\"500\" selected>500 ms</option><option value=\"1000\">1 s</option>"
          "<option value=\"2000\">2 s</option></select></label>"
          "<button type=\"button\" id=\"blink-toggle\">pause blinking (b)</button>"
          "<label>zoom <select id=\"zoom\"><option value=\"1\">1x</option><option value=\"2\">2x</option>"
          "<option value=\"4\">4x</option><option value=\"8\">8x</option></select></label>"
          "<label><input type=\"checkbox\" id=\"show-regions\" checked> region boxes (r)</label></div>\n"
       << kKeyboardHelp << "</header>\n<main>\n"
       << "<p class=\"empty\" id=\"empty\" hidden>No file has a status the filter shows.</p>\n";
  for (std::size_t position = 0; position < order.size(); ++position) {
    write_entry(html, entries[order[position]], position);
  }
  html << "</main>\n<script>" << detail::kReportScript << "</script>\n</body></html>\n";
  return write_text_file_atomically(html_file, html.str());
}

std::string markup_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        // XML 1.0 forbids most control characters, even escaped; a file name could hold one.
        out += (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') ? '?' : c;
    }
  }
  return out;
}

}  // namespace curvescan
