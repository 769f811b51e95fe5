// The curve families of `curvescan curve` that are not a chain of Bézier pieces (docs/curve-spec.md):
// explicit curves y = f(x) and implicit curves f(x, y) = 0, flattened with interval proofs into polylines
// (explicit_curve.h, implicit_curve.h), and Bézier surface patches, whose isoparametric curves project to
// exact (rational) cubics, each flattened on its own (bezier_patch.h, view_transform.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "curve_spec.h"
#include "curvescan/curves/point.h"
#include "curvescan/status.h"

namespace curvescan::cli {

/// One curve of these families: its exact pieces (the projected iso-curves of patches; none for explicit
/// and implicit curves), its polylines, and notes for the user (where an explicit graph was split, a
/// singular point, cells without a topology certificate).
struct FamilyCurve {
  std::vector<CurveSegment> segments;
  std::vector<std::vector<Point>> polylines;
  std::vector<std::string> notes;
};

/// Whether `type` is one of "explicit", "implicit", "bezier-patch".
bool is_family_type(std::string_view type);

/// Validates `spec` and draws it at `tolerance` with at most `max_segments` polyline segments (explicit:
/// pieces examined; implicit: quadtree cells examined; patches: segments of all iso-curves). Every error
/// names the field or the limit to raise.
Result<FamilyCurve> build_family_curve(const nlohmann::json& spec, double tolerance, std::size_t max_segments,
                                       const CurveSpecLimits& limits);

}  // namespace curvescan::cli
