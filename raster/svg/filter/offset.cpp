// feOffset (offset.h).
#include "offset.h"

#include <algorithm>

namespace curvescan::svg::detail::filter {

void offset(const FilterImage& in, PixelRect subregion, long long dx, long long dy,
            FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    const long long sy = y - dy;
    for (int x = r.x0; x < r.x1; ++x) {
      const long long sx = x - dx;
      float* target = out.pixel(x, y);
      if (sx < 0 || sy < 0 || sx >= in.width || sy >= in.height) {
        std::fill(target, target + 4, 0.0f);
      } else {
        const float* source = in.pixel(static_cast<int>(sx), static_cast<int>(sy));
        std::copy(source, source + 4, target);
      }
    }
  }
}

}  // namespace curvescan::svg::detail::filter
