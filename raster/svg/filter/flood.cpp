// feFlood (flood.h).
#include "flood.h"

#include <algorithm>

namespace curvescan::svg::detail::filter {

std::array<float, 4> premultiplied(FilterColor color) noexcept {
  const float a = std::clamp(color.a, 0.0f, 1.0f);
  return {std::clamp(color.r, 0.0f, 1.0f) * a, std::clamp(color.g, 0.0f, 1.0f) * a,
          std::clamp(color.b, 0.0f, 1.0f) * a, a};
}

void flood(FilterColor color, PixelRect subregion, FilterImage& out) noexcept {
  const std::array<float, 4> value = premultiplied(color);
  const PixelRect r = subregion.intersect(out.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) std::copy(value.begin(), value.end(), out.pixel(x, y));
  }
}

}  // namespace curvescan::svg::detail::filter
