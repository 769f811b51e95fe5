// feDropShadow (drop_shadow.h).
#include "drop_shadow.h"

#include <algorithm>
#include <cmath>

#include "composite.h"
#include "gaussian_blur.h"
#include "offset.h"

namespace curvescan::svg::detail::filter {

void drop_shadow(const FilterImage& in, const DropShadowParams& params, PixelRect subregion,
                 FilterImage& out) {
  FilterImage alpha(in.width, in.height);
  const PixelRect r = subregion.intersect(in.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) alpha.pixel(x, y)[3] = in.pixel(x, y)[3];
  }
  FilterImage blurred(in.width, in.height);
  gaussian_blur(alpha, subregion, params.sigma_x, params.sigma_y, EdgeMode::kNone, blurred);
  FilterImage shadow(in.width, in.height);
  offset(blurred, subregion, whole_pixel_offset(params.dx), whole_pixel_offset(params.dy), shadow);
  const float a = std::clamp(params.color.a, 0.0f, 1.0f);
  const float colour[4] = {std::clamp(params.color.r, 0.0f, 1.0f) * a,
                           std::clamp(params.color.g, 0.0f, 1.0f) * a,
                           std::clamp(params.color.b, 0.0f, 1.0f) * a, a};
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      float* p = shadow.pixel(x, y);
      const float coverage = p[3];
      for (int c = 0; c < 4; ++c) p[c] = colour[c] * coverage;  // flood "in" the shadow's alpha
    }
  }
  merge({&shadow, &in}, subregion, out);
}

}  // namespace curvescan::svg::detail::filter
