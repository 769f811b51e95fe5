// Filter cost: the Ghostscript tiger drawn plain and wrapped in the drop-shadow recipe real files use
// (feGaussianBlur of SourceAlpha, feOffset, feFlood, feComposite operator="in", feMerge with SourceGraphic;
// Filter Effects 1, section 9), in one process, at zoom 1 (200 x 200) and 4 (800 x 800). Reported as the
// ratio filtered / plain of the whole render (parse excluded); goal: at most 3x.
//
// There is no Cairo side: Cairo has no filters (librsvg implements its own on top of it), so the plain
// tiger -- whose speed against Cairo render_bench.sh measures -- is the reference.
//
// The tiger is read from ../shared/bench/tiger.svg beside the checkout, or from the path given as the
// first argument; it is never committed. Timing: thread CPU time (the machine is shared), the median of 9
// renders, the plain and the filtered document alternating so that both see the same load.
// Run: filter_bench [tiger.svg]
// Profile (only the filtered render, for callgrind or perf): filter_bench --profile ZOOM SIGMA ROUNDS
// [tiger.svg]
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "curvescan/svg/document.h"

namespace {

using namespace curvescan;

constexpr int kRounds = 9;

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The document with its content inside <g filter="url(#shadow)">, the filter defined first.
std::string with_drop_shadow(const std::string& svg, double deviation) {
  const std::size_t open = svg.find("<svg");
  const std::size_t open_end = svg.find('>', open);
  const std::size_t close = svg.rfind("</svg>");
  if (open == std::string::npos || open_end == std::string::npos || close == std::string::npos) return {};
  const std::string filter =
      "<filter id=\"shadow\" x=\"-0.2\" y=\"-0.2\" width=\"1.4\" height=\"1.4\">"
      "<feGaussianBlur in=\"SourceAlpha\" stdDeviation=\"" +
      std::to_string(deviation) +
      "\"/><feOffset dx=\"4\" dy=\"4\" result=\"offset\"/>"
      "<feFlood flood-color=\"#203040\" flood-opacity=\"0.6\"/><feComposite in2=\"offset\" operator=\"in\"/>"
      "<feMerge><feMergeNode/><feMergeNode in=\"SourceGraphic\"/></feMerge></filter>";
  return svg.substr(0, open_end + 1) + filter + "<g filter=\"url(#shadow)\">" +
         svg.substr(open_end + 1, close - open_end - 1) + "</g>" + svg.substr(close);
}

// Seconds of thread CPU time to render `document` at `zoom`, or a negative number when the render fails.
double render_seconds(const svg::Document& document, double zoom) {
  svg::RenderOptions options;
  options.zoom = zoom;
  const double start = thread_seconds();
  const Result<svg::RenderedDocument> rendered = document.render(options);
  const double elapsed = thread_seconds() - start;
  if (!rendered) {
    std::fprintf(stderr, "render failed: %s\n", rendered.error().message.c_str());
    return -1.0;
  }
  return elapsed;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

std::optional<std::string> read_file(const std::string& path) {
  std::ifstream file(path);
  if (!file) return std::nullopt;
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

int main(int argc, char** argv) {
  const bool profile = argc >= 5 && std::string(argv[1]) == "--profile";
  const int path_argument = profile ? 5 : 1;
  const std::string path = argc > path_argument
                               ? argv[path_argument]
                               : std::string(CURVESCAN_SOURCE_DIR) + "/../shared/bench/tiger.svg";
  const std::optional<std::string> plain_svg = read_file(path);
  if (!plain_svg) {
    std::fprintf(stderr, "filter_bench: cannot read %s (give the tiger's path as the first argument)\n",
                 path.c_str());
    return 1;
  }
  if (profile) {
    const double zoom = std::atof(argv[2]), deviation = std::atof(argv[3]);
    const int rounds = std::max(1, std::atoi(argv[4]));
    const Result<svg::Document> shadow = svg::Document::parse(with_drop_shadow(*plain_svg, deviation));
    if (!shadow) {
      std::fprintf(stderr, "filter_bench: %s\n", shadow.error().message.c_str());
      return 1;
    }
    for (int round = 0; round < rounds; ++round) {
      if (render_seconds(*shadow, zoom) < 0.0) return 1;
    }
    return 0;
  }
  const Result<svg::Document> plain = svg::Document::parse(*plain_svg);
  if (!plain) {
    std::fprintf(stderr, "filter_bench: %s\n", plain.error().message.c_str());
    return 1;
  }
  std::printf("%-10s %6s %12s %12s %8s\n", "zoom", "sigma", "plain_ms", "shadow_ms", "ratio");
  for (const double zoom : {1.0, 4.0}) {
    for (const double deviation : {2.0, 8.0}) {
      const Result<svg::Document> shadow = svg::Document::parse(with_drop_shadow(*plain_svg, deviation));
      if (!shadow) {
        std::fprintf(stderr, "filter_bench: %s\n", shadow.error().message.c_str());
        return 1;
      }
      std::vector<double> base, filtered;
      for (int round = 0; round < kRounds; ++round) {
        base.push_back(render_seconds(*plain, zoom));
        filtered.push_back(render_seconds(*shadow, zoom));
        if (base.back() < 0.0 || filtered.back() < 0.0) return 1;
      }
      const double b = median(base), f = median(filtered);
      std::printf("%-10.0f %6.0f %12.2f %12.2f %7.2fx\n", zoom, deviation, b * 1e3, f * 1e3, f / b);
    }
  }
  return 0;
}
