// The two colour spaces filter primitives work in (Filter Effects 1, section 16
// "color-interpolation-filters"; SVG 1.1 12.7.3): sRGB, the space of the document's colours, and linearRGB,
// where light adds linearly.
//
// The transfer functions are sRGB's (IEC 61966-2-1, as SVG 1.1 gives them in "color-interpolation"):
//   linear = srgb / 12.92                      for srgb <= 0.04045
//          = ((srgb + 0.055) / 1.055)^2.4      otherwise
// and the inverse. They apply to colour without alpha, so a premultiplied image is unpremultiplied first and
// premultiplied again after. The image conversions use a 4096-interval table with linear interpolation
// (error below 2e-5, far under one 8-bit level) rather than pow() per channel: a blur over a large region
// converts millions of channels.
#pragma once

#include "filter_image.h"

namespace curvescan::svg::detail::filter {

enum class ColorSpace { kSrgb, kLinearRgb };

/// The exact transfer functions, on one channel in [0, 1].
[[nodiscard]] float srgb_to_linear(float srgb) noexcept;
[[nodiscard]] float linear_to_srgb(float linear) noexcept;

/// Converts every pixel of `image` (premultiplied) inside its extent from `from` to `to`; nothing when they
/// are equal.
void convert_color_space(FilterImage& image, ColorSpace from, ColorSpace to) noexcept;

/// Converts `count` premultiplied pixels (4 floats each) from `from` to `to`, `in` to `out` (which may be
/// the same memory): the arithmetic of the image conversions, a row at a time.
void convert_pixels(const float* in, float* out, int count, ColorSpace from, ColorSpace to) noexcept;

/// Writes the pixels of `in` inside `in.extent` into `out` (the same size), converted from `from` to `to`;
/// `out` takes `in`'s extent. Pixels of `out` outside it are left as they are.
void convert_color_space(const FilterImage& in, ColorSpace from, ColorSpace to, FilterImage& out) noexcept;

}  // namespace curvescan::svg::detail::filter
