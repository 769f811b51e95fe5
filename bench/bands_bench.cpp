// Two cores: the Ghostscript tiger rendered at 4096 px wide with 1 and with 2 threads (large fills cut into
// bands, Canvas::set_threads), parse excluded; reported as the ratio of median wall times (1 thread ÷ 2
// threads; goal ≥ 1.7) and whether the two images are byte-identical (they must be).
//
// The tiger is read from ../shared/bench/tiger.svg beside the checkout, or from the path given as the
// first argument; it is never committed. Wall time, not CPU time: the point is two cores working at once,
// so run it on an otherwise idle machine (the 1-minute load average is printed with the result). The
// median of ROUNDS renders each (default 7), 1 and 2 threads alternating.
// Run: bands_bench [tiger.svg] [width] [rounds]
// Profile: bands_bench --profile=THREADS[,RENDERS] [tiger.svg] [width] renders RENDERS times (default 1)
// with THREADS threads and times nothing (for valgrind --tool=callgrind or perf: what stays serial shows
// in a 1-thread profile).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "curvescan/svg/document.h"

namespace {

using namespace curvescan;

struct Timed {
  double seconds = -1.0;
  std::optional<Image> image;
};

Timed render(const svg::Document& document, double width, int threads) {
  svg::RenderOptions options;
  options.width = width;
  options.threads = threads;
  const auto start = std::chrono::steady_clock::now();
  Result<svg::RenderedDocument> rendered = document.render(options);
  const auto stop = std::chrono::steady_clock::now();
  Timed out;
  if (!rendered) return out;
  out.seconds = std::chrono::duration<double>(stop - start).count();
  out.image = std::move(rendered->image);
  return out;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int profile_threads = 0, profile_renders = 1;
  if (argc > 1 && std::string(argv[1]).rfind("--profile=", 0) == 0) {
    profile_threads = std::max(1, std::atoi(argv[1] + 10));
    if (const char* comma = std::strchr(argv[1], ',')) profile_renders = std::max(1, std::atoi(comma + 1));
    --argc;
    ++argv;
  }
  const std::string path = argc > 1 ? argv[1] : std::string(CURVESCAN_SOURCE_DIR) + "/../shared/bench/tiger.svg";
  const double width = argc > 2 ? std::atof(argv[2]) : 4096.0;
  const int rounds = argc > 3 ? std::max(1, std::atoi(argv[3])) : 7;
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    std::printf("skipped: %s is absent\n", path.c_str());
    return 0;
  }
  std::ostringstream text;
  text << file.rdbuf();
  Result<svg::Document> document = svg::Document::parse(text.str());
  if (!document) {
    std::fprintf(stderr, "cannot parse %s\n", path.c_str());
    return 1;
  }
  for (int i = 0; profile_threads > 0 && i < profile_renders; ++i) {
    if (render(*document, width, profile_threads).seconds < 0) return 1;
  }
  if (profile_threads > 0) return 0;
  std::vector<double> one, two;
  bool identical = true;
  for (int round = 0; round < rounds; ++round) {
    Timed a = render(*document, width, 1);
    Timed b = render(*document, width, 2);
    if (a.seconds < 0 || b.seconds < 0) {
      std::fprintf(stderr, "render failed\n");
      return 1;
    }
    identical = identical && *a.image == *b.image;
    one.push_back(a.seconds);
    two.push_back(b.seconds);
  }
  double load = -1.0;
  if (std::FILE* loadavg = std::fopen("/proc/loadavg", "r")) {
    if (std::fscanf(loadavg, "%lf", &load) != 1) load = -1.0;
    std::fclose(loadavg);
  }
  std::printf(
      "tiger %.0f px wide, %d rounds, load %.2f: 1 thread %.1f ms, 2 threads %.1f ms, speed-up %.2fx, images "
      "%s\n",
      width, rounds, load, 1e3 * median(one), 1e3 * median(two), median(one) / median(two),
      identical ? "byte-identical" : "DIFFERENT");
  return identical ? 0 : 1;
}
