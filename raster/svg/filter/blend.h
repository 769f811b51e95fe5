// feBlend (Filter Effects 1, section 9.6, with the modes of Compositing and Blending 1, sections 5.3 and
// 5.7): `in` is the source (Cs, αs) and `in2` the backdrop (Cb, αb). With premultiplied cs, cb and the
// unpremultiplied Cs, Cb, the result is (Compositing 1, 5.1 "simple alpha compositing" of the blended
// colour):
//   co = cs · (1 - αb) + cb · (1 - αs) + αs · αb · B(Cb, Cs)
//   αo = αs + αb - αs · αb
// B is per channel for the separable modes (normal, multiply, screen, overlay, darken, lighten, color-dodge,
// color-burn, hard-light, soft-light, difference, exclusion) and on the whole colour for the non-separable
// ones (hue, saturation, color, luminosity; section 5.7's SetLum / SetSat / ClipColor): blend_colors of the
// core (layer.h), the function mix-blend-mode uses.
#pragma once


#include "curvescan/raster/layer.h"
#include "filter_image.h"

namespace curvescan::svg::detail::filter {

using curvescan::BlendMode;  // the modes of mix-blend-mode (layer.h), one set for both

/// out = in blended onto in2 inside `subregion`.
void blend(const FilterImage& in, const FilterImage& in2, BlendMode mode, PixelRect subregion,
           FilterImage& out) noexcept;

}  // namespace curvescan::svg::detail::filter
