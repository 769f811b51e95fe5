// feDropShadow (Filter Effects 1, section 9.11) and the drop-shadow() function (section 13): the input's
// alpha blurred by (σx, σy), moved by (dx, dy), coloured with flood-color at flood-opacity, and the input
// drawn over it -- the specification's equivalent of feGaussianBlur in=SourceAlpha, feOffset, feFlood,
// feComposite operator="in" and feMerge, computed here in that order.
#pragma once

#include "filter_image.h"
#include "flood.h"

namespace curvescan::svg::detail::filter {

struct DropShadowParams {
  double sigma_x = 0.0, sigma_y = 0.0;  ///< filter pixels (>= 0)
  double dx = 0.0, dy = 0.0;            ///< filter pixels, rounded as feOffset rounds them
  FilterColor color;                    ///< unpremultiplied, in the primitive's colour space
};

void drop_shadow(const FilterImage& in, const DropShadowParams& params, PixelRect subregion,
                 FilterImage& out);

}  // namespace curvescan::svg::detail::filter
