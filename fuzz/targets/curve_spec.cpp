// Fuzz target curve_spec: the JSON curve spec of `curvescan curve` (docs/curve-spec.md), through the
// tool's own reader (tools/curvescan/curve_spec.cpp, compiled into this target) and the flattener.
//
// The flattening is the command's own (cli::flatten_curve_segments) with a smaller segment budget, so
// that one input stays fast: a spec whose polyline outgrows it is rejected as the command rejects one
// past its own limit.
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "curve_families.h"
#include "curve_spec.h"
#include "curvescan/curves/flatten.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {
namespace {

// A smaller budget than the command's default (2^22), passed down to the flattener as the command passes
// its own: a curve that cannot be flattened within it (coordinates near ±1e308 at the default tolerance
// need the flattener's whole per-curve cap) then costs at most this many segments.
constexpr std::size_t kMaxPolylineSegments = 200'000;
constexpr std::size_t kMaxFamilyPieces = 5'000;

}  // namespace

int fuzz_curve_spec(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);  // bytes as characters
  const nlohmann::json spec = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (spec.is_discarded()) return 0;
  cli::CurveSpecLimits limits;
  limits.max_points = 10'000;
  if (spec.is_object() && spec.contains("type") && spec["type"].is_string() &&
      cli::is_family_type(spec["type"].get<std::string>())) {
    // Explicit and implicit curves and patches: pieces or cells cost a few evaluations of an expression of
    // up to 4096 nodes each, so a smaller budget, in pieces and in pieces times terms.
    limits.max_work = std::size_t{1} << 16;
    (void)cli::build_family_curve(spec, kDefaultFlattenTolerance, kMaxFamilyPieces, limits);
    return 0;
  }
  const Result<std::vector<cli::CurveSegment>> segments = cli::build_curve_segments(spec, limits);
  if (!segments) return 0;
  for (const cli::CurveSegment& segment : *segments) {
    // build_curve_segments promises pieces of degree >= 1 with matching weights; the flattener and the
    // command's output code rely on it, so a broken promise is reported as a crash here.
    if (segment.points.size() < 2 || (!segment.weights.empty() && segment.weights.size() != segment.points.size())) {
      __builtin_trap();
    }
  }
  (void)cli::flatten_curve_segments(*segments, kDefaultFlattenTolerance, kMaxPolylineSegments);
  return 0;
}

}  // namespace curvescan::fuzz
