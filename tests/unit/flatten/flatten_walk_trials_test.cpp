// The walks' work is bounded by the caller's segment cap in bound evaluations too, not only in segments
// (WalkTrials, curves/src/flatten_step_search.h). Regression:
// fuzz/regressions/raster_stroke/conic_weight_dbl_max_flattened_past_budget_*: a conic with weights 1,
// DBL_MAX, 1 whose pieces near its corner the bound cannot certify (subnormal scaled weights), so every
// segment's search spent its 200 evaluations: 8 million at a cap of 2^18, 63 s at the default cap.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <vector>

#include "curvescan/curves/flatten.h"
// Private to curves/ (not API); reached by path, as the other flatten tests reach curves/src.
#include "../../../curves/src/flatten_step_search.h"

namespace curvescan {
namespace {

TEST_CASE("a step search evaluates at most its cap of bounds", "[flatten][budget]") {
  for (const int cap : {1, 7, detail::StepSearch::kMaxTrialsPerSegment}) {
    detail::StepSearch search(1.0, 0.1, cap);
    int calls = 0;
    for (bool done = false; !done;) {
      done = search.record(std::numeric_limits<double>::quiet_NaN());  // never passes
      ++calls;
    }
    CHECK(calls == cap);
    CHECK(search.evaluations() == cap);
    CHECK_FALSE(search.passed());
  }
}

TEST_CASE("a walk's allowance is one hard segment plus 8 evaluations per segment of its cap",
          "[flatten][budget]") {
  detail::WalkTrials trials(10);
  CHECK(trials.next_cap() == detail::StepSearch::kMaxTrialsPerSegment);
  CHECK(trials.spend(200 + 8 * 10 - 5));
  CHECK(trials.next_cap() == 5);
  CHECK_FALSE(trials.spend(5));
  detail::WalkTrials unbounded(std::numeric_limits<std::size_t>::max());  // saturates, no overflow
  CHECK(unbounded.spend(1'000'000));
}

TEST_CASE("a conic the bound cannot certify ends within its allowance, complete", "[flatten][budget]") {
  // At tolerance 1e296 the pieces along the legs pass; around the corner, where the scaled end weights
  // (1/DBL_MAX) are subnormal, no trial does. Before the allowance each such segment took 200 bound
  // evaluations and the walk went on to its cap of 4096 segments (819 200 evaluations); now it ends after
  // 200 + 8·4096 evaluations, with fewer segments than the cap.
  constexpr double kMax = std::numeric_limits<double>::max();
  const std::vector<Point> ctrl{{41.25, 27.75}, {24.25, kMax}, {kMax, kMax}};
  const std::vector<double> weights{1.0, kMax, 1.0};
  constexpr std::size_t kCap = 4096;
  std::vector<Point> out;
  CHECK(flatten_rational(ctrl, weights, 1e296, out, kCap) == FlattenOutcome::kSegmentLimit);
  REQUIRE(!out.empty());
  CHECK(out.size() < kCap);
  CHECK(out.back() == ctrl.back());
}

}  // namespace
}  // namespace curvescan
