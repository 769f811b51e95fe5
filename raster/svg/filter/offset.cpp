// feOffset (offset.h).
#include "offset.h"

#include <algorithm>

namespace curvescan::svg::detail::filter {

void offset(const FilterImage& in, PixelRect subregion, long long dx, long long dy,
            FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    float* row = out.pixel(r.x0, y);
    const long long sy = y - dy;
    // The columns whose source x - dx lies inside `in` are copied; the rest read transparent black.
    const long long from = std::clamp<long long>(dx, r.x0, r.x1),
                    to = std::clamp<long long>(static_cast<long long>(in.width) + dx, from, r.x1);
    if (sy < 0 || sy >= in.height || from >= to) {
      std::fill(row, row + 4 * r.width(), 0.0f);
      continue;
    }
    std::fill(row, row + 4 * (from - r.x0), 0.0f);
    const float* source = in.pixel(static_cast<int>(from - dx), static_cast<int>(sy));
    std::copy(source, source + 4 * (to - from), row + 4 * (from - r.x0));
    std::fill(row + 4 * (to - r.x0), row + 4 * r.width(), 0.0f);
  }
}

}  // namespace curvescan::svg::detail::filter
