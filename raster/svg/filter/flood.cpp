// feFlood (flood.h).
#include "flood.h"

#include <algorithm>

namespace curvescan::svg::detail::filter {

void flood(FilterColor color, PixelRect subregion, FilterImage& out) noexcept {
  const float a = std::clamp(color.a, 0.0f, 1.0f);
  const float premultiplied[4] = {std::clamp(color.r, 0.0f, 1.0f) * a, std::clamp(color.g, 0.0f, 1.0f) * a,
                                  std::clamp(color.b, 0.0f, 1.0f) * a, a};
  const PixelRect r = subregion.intersect(out.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) std::copy(premultiplied, premultiplied + 4, out.pixel(x, y));
  }
}

}  // namespace curvescan::svg::detail::filter
