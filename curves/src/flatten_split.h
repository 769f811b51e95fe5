// flatten_split.h (private to the flattener): de Casteljau subdivision of a Bézier at one parameter.
//
// The edges of the de Casteljau triangle at u are the control points of the two halves of the curve:
// the left edge p_{0,0}, p_{1,0}, ..., p_{n,0} describes [0, u], the right edge p_{n,0}, p_{n-1,1}, ...,
// p_{0,n} describes [u, 1] (Gallivan, *Parametric Curves*, "DeCasteljau's Algorithm", Ince, *Curves*, "Construction by de Casteljau
// Algorithm"). The same code splits 2D points, homogeneous points of a rational curve (Umetani, *Parametric Curve*, §4.1) and
// the 1D Bernstein coefficients of the flatness bound, so it is a template over the coefficient type.
//
// Exactness the flattener relies on: left[0] == src[0] and right[n] == src[n] bit for bit, because they
// are copies, never results of a lerp.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>

namespace curvescan::detail {

/// Splits the Bézier with coefficients `src` at parameter `u`. `left` and `right` receive the control
/// points of the pieces [0, u] and [u, 1] (either may be empty to skip it); `scratch` must hold
/// src.size() elements. `lerp_fn(a, b, u)` is (1 - u)·a + u·b. Total: NaN in, NaN out.
template <class T, class Lerp>
void split_bezier(std::span<const T> src, double u, std::span<T> left, std::span<T> right,
                  std::span<T> scratch, Lerp lerp_fn) noexcept {
  const std::size_t count = src.size();
  if (count == 0) return;
  std::copy(src.begin(), src.end(), scratch.begin());
  const std::size_t n = count - 1;
  if (!left.empty()) left[0] = scratch[0];
  if (!right.empty()) right[n] = scratch[n];
  for (std::size_t level = 1; level <= n; ++level) {
    for (std::size_t i = 0; i + level <= n; ++i) scratch[i] = lerp_fn(scratch[i], scratch[i + 1], u);
    if (!left.empty()) left[level] = scratch[0];
    if (!right.empty()) right[n - level] = scratch[n - level];
  }
}

}  // namespace curvescan::detail
