// The harness shared by the side-by-side benchmarks (fill_bench, stroke_bench, paint_bench): every scene
// is registered twice, "curvescan/NAME" and "cairo/NAME", run as medians of 5 repetitions unless the
// command line asks otherwise, and the medians are kept for the ratio table each benchmark prints.
#pragma once

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace curvescan::bench {

/// Registers `name` for both sides: curvescan/NAME runs `ours`, cairo/NAME runs `cairo`.
template <class Ours, class Cairo>
void register_side_by_side(const std::string& name, Ours ours, Cairo cairo) {
  benchmark::RegisterBenchmark(("curvescan/" + name).c_str(), std::move(ours))->Unit(benchmark::kMicrosecond);
  benchmark::RegisterBenchmark(("cairo/" + name).c_str(), std::move(cairo))->Unit(benchmark::kMicrosecond);
}

/// One side's timed loop: Renderer(scene) sets up, each iteration draws one frame (draw()) whose pixels
/// (data()) must not be optimised away.
template <class Renderer, class Scene>
void time_frames(benchmark::State& state, const Scene& scene) {
  Renderer renderer(scene);
  for (auto _ : state) {
    renderer.draw();
    benchmark::DoNotOptimize(renderer.data());
    benchmark::ClobberMemory();
  }
}

/// Medians of CPU time (µs) by scene name, for each side.
struct SideBySideMedians {
  std::map<std::string, double> medians;
  /// Both sides' medians of `name`, or false when either did not run (--benchmark_filter).
  [[nodiscard]] bool find(const std::string& name, double& ours, double& cairo) const {
    const auto a = medians.find("curvescan/" + name);
    const auto b = medians.find("cairo/" + name);
    if (a == medians.end() || b == medians.end()) return false;
    ours = a->second;
    cairo = b->second;
    return true;
  }
};

/// Runs the registered benchmarks (5 repetitions unless --benchmark_repetitions is given), printing as
/// the console reporter does, and returns the medians. Call benchmark::Shutdown() after using them.
inline SideBySideMedians run_side_by_side(int argc, char** argv) {
  class MedianCollector final : public benchmark::ConsoleReporter {
   public:
    void ReportRuns(const std::vector<Run>& runs) override {
      for (const Run& run : runs) {
        if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median") {
          medians[run.run_name.function_name] = run.GetAdjustedCPUTime();
        }
      }
      ConsoleReporter::ReportRuns(runs);
    }
    std::map<std::string, double> medians;
  };
  std::vector<char*> args(argv, argv + argc);
  std::string repetitions = "--benchmark_repetitions=5";
  bool has_repetitions = false;
  for (int i = 1; i < argc; ++i) has_repetitions |= std::string(argv[i]).starts_with("--benchmark_repetitions");
  if (!has_repetitions) args.push_back(repetitions.data());
  int count = static_cast<int>(args.size());
  benchmark::Initialize(&count, args.data());
  MedianCollector reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  return {std::move(reporter.medians)};
}

}  // namespace curvescan::bench
