// feOffset (offset.h).
#include "offset.h"

#include <algorithm>
#include <cstring>

namespace curvescan::svg::detail::filter {

void offset(const FilterImage& in, PixelRect subregion, long long dx, long long dy,
            FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds());
  if (r.empty()) return;
  // When `out` is `in` (the filter graph moves an image in its own memory), row y reads row y - dy: the rows
  // are visited so that each is read before it is overwritten -- from the bottom when the image moves down.
  const bool upwards = dy > 0;
  for (int k = 0; k < r.height(); ++k) {
    const int y = upwards ? r.y1 - 1 - k : r.y0 + k;
    float* row = out.pixel(r.x0, y);
    const long long sy = y - dy;
    // The columns whose source x - dx lies inside `in` are copied; the rest read transparent black.
    const long long from = std::clamp<long long>(dx, r.x0, r.x1),
                    to = std::clamp<long long>(static_cast<long long>(in.width) + dx, from, r.x1);
    if (sy < 0 || sy >= in.height || from >= to) {
      std::fill(row, row + 4 * r.width(), 0.0f);
      continue;
    }
    // The copy first (memmove: within one row source and target may overlap), then the transparent ends,
    // which in the same memory may be where the copy read from.
    const float* source = in.pixel(static_cast<int>(from - dx), static_cast<int>(sy));
    std::memmove(row + 4 * (from - r.x0), source, sizeof(float) * 4 * static_cast<std::size_t>(to - from));
    std::fill(row, row + 4 * (from - r.x0), 0.0f);
    std::fill(row + 4 * (to - r.x0), row + 4 * r.width(), 0.0f);
  }
}

}  // namespace curvescan::svg::detail::filter
