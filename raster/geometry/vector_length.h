// Private to the stroker and dasher: |v| with one square root where the squares cannot overflow or
// underflow, std::hypot elsewhere.
//
// Why: glibc's hypot scales its operands and corrects the rounding of x² + y² (about 50 instructions per
// call); the stroker measures every control polygon edge, chord and tangent of a curve's pieces with it:
// 8 % of all instructions of a 20 px stroke of 50 cubics went to hypot (docs/benchmarks.md). Where
// 1e-280 < x² + y² < 1e280 no square or sum leaves the normal range, and sqrt(x² + y²) is within about
// 1.5 ulp of |v| (each square and the sum round by half an ulp, the square root halves the relative error
// and rounds once more), against hypot's 1 ulp: the same length for every use here (tangents,
// comparisons with tolerances, arc lengths), each a few ulps from exact either way.
#pragma once

#include <cmath>

#include "curvescan/curves/point.h"

namespace curvescan::detail {

/// |v|: sqrt(x² + y²) where that is safe, std::hypot(x, y) otherwise (huge, tiny, infinite or NaN).
[[nodiscard]] inline double vector_length(Vec2 v) noexcept {
  const double squared = v.length_squared();
  if (squared > 1e-280 && squared < 1e280) return std::sqrt(squared);
  return std::hypot(v.x, v.y);
}

/// v / |v| with vector_length.
[[nodiscard]] inline Vec2 unit_vector(Vec2 v) noexcept {
  return v / vector_length(v);
}

}  // namespace curvescan::detail
