// Geometry bent onto a textPath's path (text_path_bend.h).
#include "text_path_bend.h"

#include <algorithm>
#include <cmath>

namespace curvescan::svg::detail {

Point bend_point(const PathMeasure& path, Point p) noexcept {
  const PathMeasure::Sample sample = path.at_smooth(p.x);
  Point on = sample.point;
  if (p.x < 0.0) on = on + sample.tangent * p.x;
  if (p.x > path.length()) on = on + sample.tangent * (p.x - path.length());
  return on + Vec2{-sample.tangent.y, sample.tangent.x} * p.y;
}

void bend_polygon(const PathMeasure& path, std::span<const Point> polygon, double step,
                  std::vector<Point>& bent) {
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point a = polygon[i], b = polygon[(i + 1) % n];
    bent.push_back(bend_point(path, a));
    if (n < 2) break;
    const double length = (b - a).length();
    const int cuts =
        std::isfinite(length) && step > 0.0 ? std::min(1000, static_cast<int>(length / step)) : 0;
    for (int k = 1; k <= cuts; ++k)
      bent.push_back(bend_point(path, a + (b - a) * (static_cast<double>(k) / (cuts + 1))));
  }
}

}  // namespace curvescan::svg::detail
