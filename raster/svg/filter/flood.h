// feFlood (Filter Effects 1, section 9.12): the subregion filled with flood-color at flood-opacity.
#pragma once

#include <array>

#include "filter_image.h"

namespace curvescan::svg::detail::filter {

/// A colour of a filter primitive without premultiplication, channels in [0, 1], in the primitive's
/// colour space.
struct FilterColor {
  float r = 0.0f, g = 0.0f, b = 0.0f, a = 0.0f;
};

/// `color` premultiplied, each channel clamped to [0, 1] first: the value of every pixel feFlood fills.
[[nodiscard]] std::array<float, 4> premultiplied(FilterColor color) noexcept;

/// Fills `subregion` of `out` with `color` premultiplied (alpha clamped to [0, 1]).
void flood(FilterColor color, PixelRect subregion, FilterImage& out) noexcept;

}  // namespace curvescan::svg::detail::filter
