// Filter cost: the Ghostscript tiger drawn plain and wrapped in the drop-shadow recipe real files use
// (feGaussianBlur of SourceAlpha, feOffset, feFlood, feComposite operator="in", feMerge with SourceGraphic;
// Filter Effects 1, section 9), in one process, at zoom 1 (200 x 200) and 4 (800 x 800). Reported as the
// ratio filtered / plain of the whole render (parse excluded); goal: at most 3x.
//
// There is no Cairo side: Cairo has no filters (librsvg implements its own on top of it), so the plain
// tiger -- whose speed against Cairo render_bench.sh measures -- is the reference.
//
// The tiger is read from ../shared/bench/tiger.svg beside the checkout, or from the path given as the
// first argument; it is never committed. Timing: thread CPU time (the machine is shared), best of 5.
// Run: filter_bench [tiger.svg]
#include <time.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "curvescan/svg/document.h"

namespace {

using namespace curvescan;

constexpr int kRounds = 5;

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

double best_render_seconds(const svg::Document& document, double zoom) {
  svg::RenderOptions options;
  options.zoom = zoom;
  double best = 1e30;
  for (int round = 0; round < kRounds; ++round) {
    const double start = thread_seconds();
    const Result<svg::RenderedDocument> rendered = document.render(options);
    const double elapsed = thread_seconds() - start;
    if (!rendered) {
      std::fprintf(stderr, "render failed: %s\n", rendered.error().message.c_str());
      return -1.0;
    }
    best = std::min(best, elapsed);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path =
      argc > 1 ? argv[1] : std::string(CURVESCAN_SOURCE_DIR) + "/../shared/bench/tiger.svg";
  std::ifstream file(path);
  if (!file) {
    std::fprintf(stderr, "filter_bench: cannot read %s (give the tiger's path as the first argument)\n",
                 path.c_str());
    return 1;
  }
  std::stringstream text;
  text << file.rdbuf();
  const std::string plain_svg = text.str();
  const Result<svg::Document> plain = svg::Document::parse(plain_svg);
  if (!plain) {
    std::fprintf(stderr, "filter_bench: %s\n", plain.error().message.c_str());
    return 1;
  }
  std::printf("%-10s %6s %12s %12s %8s\n", "zoom", "sigma", "plain_ms", "shadow_ms", "ratio");
  for (const double zoom : {1.0, 4.0}) {
    for (const double deviation : {2.0, 8.0}) {
      const Result<svg::Document> shadow = svg::Document::parse(with_drop_shadow(plain_svg, deviation));
      if (!shadow) {
        std::fprintf(stderr, "filter_bench: %s\n", shadow.error().message.c_str());
        return 1;
      }
      const double base = best_render_seconds(*plain, zoom), filtered = best_render_seconds(*shadow, zoom);
      if (base < 0.0 || filtered < 0.0) return 1;
      std::printf("%-10.0f %6.0f %12.2f %12.2f %7.2fx\n", zoom, deviation, base * 1e3, filtered * 1e3,
                  filtered / base);
    }
  }
  return 0;
}
