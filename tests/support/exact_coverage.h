// Test support: exact per-pixel coverage oracles, independent of curvescan's rasterizer.
//
// 1. sutherland_hodgman_coverage: each pixel square clips the polygon (Sutherland & Hodgman, "Reentrant
//    polygon clipping", CACM 1974) and the clipped polygon's shoelace area is the pixel's coverage. Exact
//    (up to double rounding) for a simple polygon, whose winding number is 0 outside and ±1 inside.
// 2. rule_resolved_coverage: for any set of closed contours and either rule. Inside one row, cut at every
//    vertex height, every height where two edges cross and every height where an edge crosses a pixel
//    column line. Between two consecutive cuts the filled set on a scanline is a union of intervals whose
//    ends move linearly and keep their order, so the filled length inside each column is a linear function
//    of y; the midpoint rule integrates a linear function exactly. So the area = Σ length(mid-height) ·
//    height is exact up to rounding — the scanline at each midpoint finds the winding numbers by sorting the
//    crossings, which has nothing in common with the rasterizer's trapezoid accumulation.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "coverage_mask.h"
#include "curvescan/raster/path.h"

namespace curvescan::testing {

/// Signed area of the part of `contour` inside the pixel square [x, x+1] x [y, y+1].
inline double clipped_signed_area(const Contour& contour, int px, int py) {
  std::vector<Point> poly = contour;
  std::vector<Point> next;
  // Keep the side where inside(p) >= 0 of each of the four lines of the square.
  const auto clip = [&](auto inside) {
    next.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Point a = poly[i];
      const Point b = poly[(i + 1) % poly.size()];
      const double da = inside(a);
      const double db = inside(b);
      if (da >= 0.0) next.push_back(a);
      if ((da >= 0.0) != (db >= 0.0)) next.push_back(lerp(a, b, da / (da - db)));
    }
    poly.swap(next);
  };
  const double x0 = px, x1 = px + 1.0, y0 = py, y1 = py + 1.0;
  clip([&](Point p) { return p.x - x0; });
  clip([&](Point p) { return x1 - p.x; });
  clip([&](Point p) { return p.y - y0; });
  clip([&](Point p) { return y1 - p.y; });
  double twice_area = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Point a = poly[i];
    const Point b = poly[(i + 1) % poly.size()];
    twice_area += a.x * b.y - b.x * a.y;
  }
  return 0.5 * twice_area;
}

/// Exact coverage of a simple polygon, per pixel of a width x height canvas.
inline std::vector<double> sutherland_hodgman_coverage(const Contour& polygon, int width, int height) {
  std::vector<double> coverage(static_cast<std::size_t>(width) * height, 0.0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      coverage[static_cast<std::size_t>(y) * width + x] = std::abs(clipped_signed_area(polygon, x, y));
    }
  }
  return coverage;
}

/// Exact rule-resolved coverage of any shape, per pixel of a width x height canvas (see the header).
inline std::vector<double> rule_resolved_coverage(const Shape& shape, int width, int height, FillRule rule) {
  struct Edge {
    Point a, b;
  };
  std::vector<Edge> edges;
  for (const Contour& c : shape) {
    for (std::size_t i = 0; i < c.size(); ++i) {
      const Point a = c[i];
      const Point b = c[(i + 1) % c.size()];
      if (a.y != b.y) edges.push_back({a, b});
    }
  }
  std::vector<double> coverage(static_cast<std::size_t>(width) * height, 0.0);
  std::vector<double> cuts;
  std::vector<std::pair<double, int>> hits;
  for (int row = 0; row < height; ++row) {
    const double r0 = row, r1 = row + 1.0;
    cuts = {r0, r1};
    const auto add_cut = [&](double y) {
      if (y > r0 && y < r1) cuts.push_back(y);
    };
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const Edge& e = edges[i];
      add_cut(e.a.y);
      add_cut(e.b.y);
      // Column lines crossed by the edge.
      const double lo = std::min(e.a.x, e.b.x), hi = std::max(e.a.x, e.b.x);
      for (double x = std::max(0.0, std::ceil(lo)); x <= std::min(hi, static_cast<double>(width)); x += 1.0) {
        if (x > lo && x < hi) add_cut(e.a.y + (x - e.a.x) * (e.b.y - e.a.y) / (e.b.x - e.a.x));
      }
      for (std::size_t j = i + 1; j < edges.size(); ++j) {
        const Edge& f = edges[j];
        const Vec2 d1 = e.b - e.a, d2 = f.b - f.a;
        const double denom = d1.cross(d2);
        if (denom == 0.0)
          continue;  // parallel: no isolated crossing (overlaps change nothing between vertices)
        const double t = (f.a - e.a).cross(d2) / denom;
        const double u = (f.a - e.a).cross(d1) / denom;
        if (t > 0.0 && t < 1.0 && u > 0.0 && u < 1.0) add_cut(e.a.y + t * d1.y);
      }
    }
    std::sort(cuts.begin(), cuts.end());
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double h = cuts[k + 1] - cuts[k];
      if (!(h > 0.0)) continue;
      const double ym = 0.5 * (cuts[k] + cuts[k + 1]);
      hits.clear();
      for (const Edge& e : edges) {
        const double top = std::min(e.a.y, e.b.y), bot = std::max(e.a.y, e.b.y);
        if (ym >= top && ym < bot) {
          hits.push_back({e.a.x + (ym - e.a.y) * (e.b.x - e.a.x) / (e.b.y - e.a.y), e.b.y > e.a.y ? 1 : -1});
        }
      }
      std::sort(hits.begin(), hits.end());
      int winding = 0;
      for (std::size_t i = 0; i + 1 < hits.size(); ++i) {
        winding += hits[i].second;
        const bool filled = rule == FillRule::kNonZero ? winding != 0 : (winding & 1) != 0;
        if (!filled) continue;
        const double xl = std::max(hits[i].first, 0.0);
        const double xr = std::min(hits[i + 1].first, static_cast<double>(width));
        for (int c = static_cast<int>(std::floor(xl)); c < width && c < xr; ++c) {
          const double len = std::min(xr, c + 1.0) - std::max(xl, static_cast<double>(c));
          if (len > 0.0) coverage[static_cast<std::size_t>(row) * width + c] += len * h;
        }
      }
    }
  }
  return coverage;
}

/// max over pixels of |mask - exact·255|, in 8-bit steps (1/255). Rounding the exact value to 8 bits
/// accounts for up to 0.5 of it.
inline double max_error_vs_exact(const CoverageMask& mask, const std::vector<double>& exact) {
  double worst = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    worst = std::max(worst, std::abs(mask.values[i] - exact[i] * 255.0));
  }
  return worst;
}

}  // namespace curvescan::testing
