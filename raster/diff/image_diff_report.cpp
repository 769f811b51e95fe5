// The HTML report of image comparisons (contract in image_diff.h) and the small text helpers it shares
// with the golden helper and the CLI.
//
// The page is one file with inline CSS and JS and no external resource; images are referenced by relative
// URLs (the callers copy them beside the report), which keeps a report of thousands of files small and
// lets a CI system archive the report directory as it is. The script is progressive: without it the page
// still shows every group, the side-by-side view and the metrics; with it the four views of a failed entry
// (side by side, diff, slider, toggle) and the zoom work. It sets data attributes on <body> once every
// image settled so that a headless browser can check the page (the contract in image_diff.h).

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <system_error>

#include "curvescan/diff/image_diff.h"
#include "curvescan/raster/output_file.h"

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

constexpr const char* kStyle = R"css(
body{font:14px/1.4 system-ui,sans-serif;margin:1.5em;color:#222;background:#fafafa}
h1{font-size:1.4em}h2{font-size:1.15em;margin-top:1.6em}
.summary span{display:inline-block;margin-right:1em;padding:.1em .5em;border-radius:3px}
.failed .badge,.summary .failed{background:#fdd}.new .badge,.summary .new{background:#ddf}
.missing .badge,.summary .missing{background:#ffd}.passed .badge,.summary .passed{background:#dfd}
.error .badge{background:#fbb}
.badge{font-size:.8em;padding:.1em .4em;border-radius:3px;margin-left:.5em}
article{background:#fff;border:1px solid #ddd;border-radius:4px;padding:.6em 1em;margin:.8em 0}
article h3{margin:.2em 0;font-size:1em;font-family:monospace}
table.metrics{border-collapse:collapse;margin:.4em 0}table.metrics td{padding:0 .8em 0 0}
table.passed td,table.passed th{padding:.1em .8em .1em 0;text-align:left;font-family:monospace}
.views button{margin-right:.3em}.views button.on{font-weight:bold}
figure{display:inline-block;margin:.3em .6em .3em 0;vertical-align:top}
figcaption{font-size:.85em;color:#555}
img{image-rendering:pixelated;border:1px solid #ccc;
background:repeating-conic-gradient(#eee 0% 25%,#fff 0% 50%) 0 0/16px 16px}
.stack{position:relative;display:inline-block}
.stack img.top{position:absolute;left:0;top:0;width:100%;height:100%;box-sizing:border-box}
[hidden]{display:none!important}
)css";

// Wires the view buttons, the slider, the toggle and the zoom, then reports on <body> (image_diff.h).
constexpr const char* kScript = R"js(
(function () {
  'use strict';
  var body = document.body;
  window.addEventListener('error', function (e) { body.setAttribute('data-script-error', String(e.message)); });
  var zoom = 1;
  function sizeImage(img) { if (img.naturalWidth > 0) img.style.width = (img.naturalWidth * zoom) + 'px'; }
  document.querySelectorAll('article[data-views]').forEach(function (entry) {
    var buttons = entry.querySelectorAll('.views button');
    buttons.forEach(function (button) {
      button.addEventListener('click', function () {
        buttons.forEach(function (b) { b.classList.toggle('on', b === button); });
        entry.querySelectorAll('.view').forEach(function (v) { v.hidden = v.dataset.view !== button.dataset.view; });
      });
    });
    var range = entry.querySelector('input[type=range]');
    var top = entry.querySelector('.stack img.top');
    if (range && top) {
      var clip = function () { top.style.clipPath = 'inset(0 ' + (100 - Number(range.value)) + '% 0 0)'; };
      range.addEventListener('input', clip);
      clip();
    }
    var flip = entry.querySelector('img.flip');
    var flipButton = entry.querySelector('button.flip');
    if (flip && flipButton) {
      var showingA = true;
      var swap = function () {
        showingA = !showingA;
        flip.src = showingA ? flip.dataset.a : flip.dataset.b;
        flipButton.textContent = showingA ? 'showing A (expected): click for B' : 'showing B (actual): click for A';
      };
      flipButton.addEventListener('click', swap);
      flip.addEventListener('click', swap);
    }
  });
  var zoomSelect = document.getElementById('zoom');
  if (zoomSelect) {
    zoomSelect.addEventListener('change', function () {
      zoom = Number(zoomSelect.value);
      Array.prototype.forEach.call(document.images, sizeImage);
    });
  }
  var images = Array.prototype.slice.call(document.images);
  var pending = images.length, loaded = 0, broken = 0;
  function done() {
    body.setAttribute('data-images-loaded', String(loaded));
    body.setAttribute('data-images-broken', String(broken));
    body.setAttribute('data-report-ready', '1');
  }
  function settle(img) {
    if (img.naturalWidth > 0) { loaded++; sizeImage(img); } else { broken++; }
    if (--pending === 0) done();
  }
  images.forEach(function (img) {
    if (img.complete) { settle(img); return; }
    var once = function () {
      img.removeEventListener('load', once); img.removeEventListener('error', once); settle(img);
    };
    img.addEventListener('load', once);
    img.addEventListener('error', once);
  });
  if (images.length === 0) done();
})();
)js";

void write_metrics_table(std::ostringstream& html, const ImageComparison& c) {
  const DiffMetrics& m = c.metrics;
  const auto row = [&](const char* label, const std::string& value) {
    html << "<tr><td>" << label << "</td><td>" << markup_escape(value) << "</td></tr>";
  };
  html << "<table class=\"metrics\">";
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
  }
  html << "</table>\n";
}

std::string image_tag(const std::string& url, const std::string& alt, const char* extra = "") {
  return "<img src=\"" + markup_escape(url) + "\" alt=\"" + markup_escape(alt) + "\"" + extra + ">";
}

void write_figure(std::ostringstream& html, const std::string& url, const char* caption) {
  if (url.empty()) return;
  html << "<figure>" << image_tag(url, caption) << "<figcaption>" << caption << "</figcaption></figure>";
}

void write_entry(std::ostringstream& html, const DiffReportEntry& entry, std::size_t index) {
  const bool has_views = !entry.expected_image.empty() && !entry.actual_image.empty();
  html << "<article class=\"" << to_string(entry.outcome) << "\" id=\"entry-" << index << "\""
       << (has_views ? " data-views" : "") << "><h3>" << markup_escape(entry.name) << "<span class=\"badge\">"
       << to_string(entry.outcome) << "</span></h3>\n";
  if (!entry.message.empty()) html << "<p>" << markup_escape(entry.message) << "</p>\n";
  if (entry.comparison) write_metrics_table(html, *entry.comparison);
  if (!has_views) {
    html << "<div>";
    write_figure(html, entry.expected_image, "expected (A)");
    write_figure(html, entry.actual_image, "actual (B)");
    html << "</div></article>\n";
    return;
  }
  html
      << "<div class=\"views\"><button type=\"button\" class=\"on\" data-view=\"side\">side by side</button>";
  if (!entry.diff_image.empty()) html << "<button type=\"button\" data-view=\"diff\">diff</button>";
  html << "<button type=\"button\" data-view=\"slider\">slider</button>"
          "<button type=\"button\" data-view=\"toggle\">toggle</button></div>\n";
  html << "<div class=\"view\" data-view=\"side\">";
  write_figure(html, entry.expected_image, "expected (A)");
  write_figure(html, entry.actual_image, "actual (B)");
  write_figure(html, entry.diff_image, "diff (red: different, yellow: anti-aliasing, blue: ignored)");
  html << "</div>\n";
  if (!entry.diff_image.empty()) {
    html << "<div class=\"view\" data-view=\"diff\" hidden>";
    write_figure(html, entry.diff_image, "diff over a faded copy of A");
    html << "</div>\n";
  }
  html << "<div class=\"view\" data-view=\"slider\" hidden><div class=\"stack\">"
       << image_tag(entry.expected_image, "expected (A)")
       << image_tag(entry.actual_image, "actual (B)", " class=\"top\"")
       << "</div><div><label>A &#8592; <input type=\"range\" min=\"0\" max=\"100\" value=\"50\"> &#8594; B "
          "(B shown left of the handle)</label></div></div>\n";
  html << "<div class=\"view\" data-view=\"toggle\" hidden><div>"
       << "<img class=\"flip\" src=\"" << markup_escape(entry.expected_image) << "\" data-a=\""
       << markup_escape(entry.expected_image) << "\" data-b=\"" << markup_escape(entry.actual_image)
       << "\" alt=\"A or B\"></div><button type=\"button\" class=\"flip\">showing A (expected): click for B"
       << "</button></div>\n</article>\n";
}

}  // namespace

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
  std::size_t counts[5] = {};
  for (const DiffReportEntry& entry : entries) ++counts[static_cast<int>(entry.outcome)];
  const std::size_t failed =
      counts[static_cast<int>(DiffOutcome::kFailed)] + counts[static_cast<int>(DiffOutcome::kError)];
  const std::size_t added = counts[static_cast<int>(DiffOutcome::kNew)];
  const std::size_t missing = counts[static_cast<int>(DiffOutcome::kMissing)];
  const std::size_t passed = counts[static_cast<int>(DiffOutcome::kPassed)];

  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
       << "<meta name=\"viewport\" content=\"width=device-width,initial-scale=1\"><title>"
       << markup_escape(title) << "</title><style>" << kStyle << "</style></head>\n<body>\n<h1>"
       << markup_escape(title) << "</h1>\n"
       << "<p class=\"summary\"><span class=\"failed\">" << failed << " failed</span><span class=\"new\">"
       << added << " new</span><span class=\"missing\">" << missing
       << " missing</span><span class=\"passed\">" << passed << " passed</span></p>\n<p>"
       << markup_escape(describe_options(options))
       << ". <label>zoom <select id=\"zoom\"><option value=\"1\">1x</option><option value=\"2\">2x</option>"
       << "<option value=\"4\">4x</option><option value=\"8\">8x</option></select></label></p>\n";

  const auto group = [&](const char* heading, const char* id, std::size_t count, auto wanted) {
    html << "<section id=\"" << id << "\"><h2>" << heading << " (" << count << ")</h2>\n";
    for (std::size_t i = 0; i < entries.size(); ++i) {
      if (wanted(entries[i].outcome)) write_entry(html, entries[i], i);
    }
    html << "</section>\n";
  };
  group("Failed", "failed", failed,
        [](DiffOutcome o) { return o == DiffOutcome::kFailed || o == DiffOutcome::kError; });
  group("New (no expected image)", "new", added, [](DiffOutcome o) { return o == DiffOutcome::kNew; });
  group("Missing (no actual image)", "missing", missing,
        [](DiffOutcome o) { return o == DiffOutcome::kMissing; });

  // Passed files are many and alike: one table row each, folded away.
  html << "<section id=\"passed\"><h2>Passed (" << passed << ")</h2><details><summary>show</summary>"
       << "<table class=\"passed\"><tr><th>file</th><th>differing pixels</th><th>max "
          "|delta|</th><th>PSNR</th></tr>\n";
  for (const DiffReportEntry& entry : entries) {
    if (entry.outcome != DiffOutcome::kPassed) continue;
    html << "<tr><td>" << markup_escape(entry.name) << "</td>";
    if (entry.comparison) {
      const DiffMetrics& m = entry.comparison->metrics;
      html << "<td>" << m.different_pixels << "</td><td>" << m.max_channel_delta << "</td><td>"
           << fixed(m.psnr, 2) << "</td>";
    }
    html << "</tr>\n";
  }
  html << "</table></details></section>\n<script>" << kScript << "</script>\n</body></html>\n";
  return write_text_file_atomically(html_file, html.str());
}

std::string markup_escape(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&#39;"; break;
      default:
        // XML 1.0 forbids most control characters, even escaped; a file name could hold one.
        out += (static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r') ? '?' : c;
    }
  }
  return out;
}

}  // namespace curvescan
