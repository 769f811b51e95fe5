// feTile (tile.h).
#include "tile.h"

#include <algorithm>

namespace curvescan::svg::detail::filter {

void tile(const FilterImage& in, PixelRect tile_rect, PixelRect subregion, FilterImage& out) noexcept {
  const PixelRect source = tile_rect.intersect(in.bounds());
  const PixelRect r = subregion.intersect(out.bounds());
  if (source.empty()) return;
  const int w = source.width(), h = source.height();
  for (int y = r.y0; y < r.y1; ++y) {
    const int sy = source.y0 + (((y - source.y0) % h) + h) % h;
    for (int x = r.x0; x < r.x1; ++x) {
      const int sx = source.x0 + (((x - source.x0) % w) + w) % w;
      std::copy(in.pixel(sx, sy), in.pixel(sx, sy) + 4, out.pixel(x, y));
    }
  }
}

}  // namespace curvescan::svg::detail::filter
