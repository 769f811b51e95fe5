// feBlend (blend.h).
#include "blend.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace curvescan::svg::detail::filter {

void blend(const FilterImage& in, const FilterImage& in2, BlendMode mode, PixelRect subregion,
           FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds()).intersect(in.bounds()).intersect(in2.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      const float* s = in.pixel(x, y);
      const float* b = in2.pixel(x, y);
      float* o = out.pixel(x, y);
      const float as = s[3], ab = b[3];
      float source[3] = {0.0f, 0.0f, 0.0f}, backdrop[3] = {0.0f, 0.0f, 0.0f}, mixed[3];
      for (int c = 0; c < 3; ++c) {
        if (as > 0.0f) source[c] = std::clamp(s[c] / as, 0.0f, 1.0f);
        if (ab > 0.0f) backdrop[c] = std::clamp(b[c] / ab, 0.0f, 1.0f);
      }
      blend_colors(mode, backdrop, source, mixed);
      const float alpha = as + ab - as * ab;
      for (int c = 0; c < 3; ++c) {
        const float value =
            s[c] * (1.0f - ab) + b[c] * (1.0f - as) + as * ab * std::clamp(mixed[c], 0.0f, 1.0f);
        o[c] = std::clamp(value, 0.0f, alpha);
      }
      o[3] = alpha;
    }
  }
}

}  // namespace curvescan::svg::detail::filter
