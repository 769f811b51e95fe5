// feColorMatrix (Filter Effects 1, section 9.8): a 4 x 5 matrix applied to each unpremultiplied pixel
// [R G B A 1], the result clamped to [0, 1] and premultiplied again. type="saturate", "hueRotate" and
// "luminanceToAlpha" are matrices too, written out in the specification; they are built here.
#pragma once

#include <array>

#include "filter_image.h"

namespace curvescan::svg::detail::filter {

/// Row-major: R' = m[0]·R + m[1]·G + m[2]·B + m[3]·A + m[4], and so on for G', B', A'.
using ColorMatrix = std::array<double, 20>;

[[nodiscard]] ColorMatrix identity_color_matrix() noexcept;
/// type="saturate" with value s (the spec's matrix; s = 0 is grey, 1 the identity).
[[nodiscard]] ColorMatrix saturate_matrix(double s) noexcept;
/// type="hueRotate" by `degrees`.
[[nodiscard]] ColorMatrix hue_rotate_matrix(double degrees) noexcept;
/// type="luminanceToAlpha": A' = 0.2125 R + 0.7154 G + 0.0721 B, colour 0.
[[nodiscard]] ColorMatrix luminance_to_alpha_matrix() noexcept;

/// out = matrix applied to in, inside `subregion`.
void color_matrix(const FilterImage& in, const ColorMatrix& matrix, PixelRect subregion,
                  FilterImage& out) noexcept;

}  // namespace curvescan::svg::detail::filter
