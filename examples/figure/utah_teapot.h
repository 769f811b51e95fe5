// The Utah teapot's patch data (utah_teapot.cpp): control point indices of each bicubic patch, row by row
// (P_ij at 4 i + j), and the control points.
#pragma once

#include <array>

#include "curvescan/curves/bezier_patch.h"

namespace curvescan::figure {

inline constexpr std::size_t kTeapotPatchCount = 32;
inline constexpr std::size_t kTeapotVertexCount = 306;

extern const std::array<std::array<int, 16>, kTeapotPatchCount> kTeapotPatches;
extern const std::array<Point3, kTeapotVertexCount> kTeapotVertices;

/// Patch `index` of the teapot.
[[nodiscard]] BezierPatch teapot_patch(std::size_t index) noexcept;

}  // namespace curvescan::figure
