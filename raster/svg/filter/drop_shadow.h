// feDropShadow (Filter Effects 1, section 9.11) and the drop-shadow() function (section 13): the input's
// alpha blurred by (σx, σy), moved by (dx, dy), coloured with flood-color at flood-opacity, and the input
// drawn over it -- the specification's equivalent of feGaussianBlur in=SourceAlpha, feOffset, feFlood,
// feComposite operator="in" and feMerge, computed here in that order.
//
// Only where the result can differ from transparent black and is needed: the input's ink, and the ink grown
// by the blur's reach and moved by the offset, inside `needed`. The shadow is blurred only at the pixels
// that land there, reading the input's alpha directly, so the cost follows the ink and the needed pixels,
// not the subregion (a huge stdDeviation over a huge region costs what the canvas's pixels cost).
#pragma once

#include "filter_image.h"
#include "flood.h"

namespace curvescan::svg::detail::filter {

struct DropShadowParams {
  double sigma_x = 0.0, sigma_y = 0.0;  ///< filter pixels (>= 0)
  double dx = 0.0, dy = 0.0;            ///< filter pixels, rounded as feOffset rounds them
  FilterColor color;                    ///< unpremultiplied, in the primitive's colour space
};

/// Writes the shadowed input into `out` (not `in`) inside `subregion` ∩ `needed`, where `out` must be
/// transparent; reads `in` only inside `subregion` and its extent. Sets `out.extent` to where it wrote.
void drop_shadow(const FilterImage& in, const DropShadowParams& params, PixelRect subregion, FilterImage& out,
                 PixelRect needed = PixelRect{-(1 << 30), -(1 << 30), 1 << 30, 1 << 30});

}  // namespace curvescan::svg::detail::filter
