// feComponentTransfer (Filter Effects 1, section 9.10): one transfer function per channel (feFuncR, feFuncG,
// feFuncB, feFuncA) on unpremultiplied colour C in [0, 1], the result clamped to [0, 1]:
//   identity  C' = C
//   table     n values v0..v(n-1): for C in [k/(n-1), (k+1)/(n-1)], C' = vk + (C - k/(n-1))·(n-1)·(vk+1 - vk)
//   discrete  n values: C' = vk for C in [k/n, (k+1)/n), k = n-1 for C = 1
//   linear    C' = slope·C + intercept
//   gamma     C' = amplitude·C^exponent + offset
// A table or discrete function with an empty list is the identity (the spec's rule).
#pragma once

#include <array>
#include <vector>

#include "filter_image.h"

namespace curvescan::svg::detail::filter {

struct TransferFunction {
  enum class Type { kIdentity, kTable, kDiscrete, kLinear, kGamma } type = Type::kIdentity;
  std::vector<double> table_values;
  double slope = 1.0, intercept = 0.0;
  double amplitude = 1.0, exponent = 1.0, offset = 0.0;

  /// C' for C in [0, 1], clamped to [0, 1].
  [[nodiscard]] double apply(double c) const noexcept;
};

/// R, G, B, A.
using TransferFunctions = std::array<TransferFunction, 4>;

void component_transfer(const FilterImage& in, const TransferFunctions& functions, PixelRect subregion,
                        FilterImage& out) noexcept;

}  // namespace curvescan::svg::detail::filter
