// Fuzz target curve_spec: the JSON curve spec of `curvescan curve` (docs/curve-spec.md), through the
// tool's own reader (tools/curvescan/curve_spec.cpp, compiled into this target) and the flattener.
//
// The flattening mirrors the command (tools/curvescan/cmd_curve.cpp, flatten_segments) with a smaller
// vertex budget, so that one input stays fast: a spec whose polyline outgrows it is rejected as the
// command rejects one past its own limit.
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "curve_spec.h"
#include "curvescan/curves/flatten.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {
namespace {

constexpr std::size_t kMaxPolylineVertices = 200'000;

void flatten_segments(const std::vector<cli::CurveSegment>& segments, double tolerance) {
  std::vector<Point> polyline;
  if (segments.empty()) return;
  polyline.push_back(segments.front().points.front());
  for (const cli::CurveSegment& segment : segments) {
    if (polyline.back() != segment.points.front()) polyline.push_back(segment.points.front());
    const FlattenOutcome outcome = segment.weights.empty()
                                       ? flatten_bezier(segment.points, tolerance, polyline)
                                       : flatten_rational(segment.points, segment.weights, tolerance, polyline);
    if (outcome != FlattenOutcome::kOk || polyline.size() > kMaxPolylineVertices) return;
  }
}

}  // namespace

int fuzz_curve_spec(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);  // bytes as characters
  const nlohmann::json spec = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (spec.is_discarded()) return 0;
  cli::CurveSpecLimits limits;
  limits.max_points = 10'000;
  const Result<std::vector<cli::CurveSegment>> segments = cli::build_curve_segments(spec, limits);
  if (!segments) return 0;
  for (const cli::CurveSegment& segment : *segments) {
    // build_curve_segments promises pieces of degree >= 1 with matching weights; the flattener and the
    // command's output code rely on it, so a broken promise is reported as a crash here.
    if (segment.points.size() < 2 || (!segment.weights.empty() && segment.weights.size() != segment.points.size())) {
      __builtin_trap();
    }
  }
  flatten_segments(*segments, kDefaultFlattenTolerance);
  return 0;
}

}  // namespace curvescan::fuzz
