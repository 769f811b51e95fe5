// Test support: seeded polygon generators shared by the oracle tests and the benchmark-like scenes.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "coverage_mask.h"

namespace curvescan::testing {

/// The axis-aligned rectangle [x0, x1] x [y0, y1], clockwise on screen (y down).
inline Contour rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

/// The same contour walked the other way: its winding number negated.
inline Contour reversed(Contour c) {
  std::reverse(c.begin(), c.end());
  return c;
}

/// A regular n-gon inscribed in the ellipse (cx, cy, rx, ry), turned by `rotation` radians;
/// counter-clockwise on screen unless `reversed`.
inline Contour regular_polygon(Point centre, double rx, double ry, int n, double rotation = 0.0,
                               bool reversed = false) {
  Contour c;
  for (int i = 0; i < n; ++i) {
    const double a = rotation + 2.0 * std::numbers::pi * (reversed ? -i : i) / n;
    c.push_back({centre.x + rx * std::cos(a), centre.y + ry * std::sin(a)});
  }
  return c;
}

/// A star with `points` tips alternating between radii r_outer and r_inner (simple, not self-crossing).
inline Contour star(Point centre, double r_outer, double r_inner, int points, double rotation = 0.0) {
  Contour c;
  for (int i = 0; i < 2 * points; ++i) {
    const double a = rotation + std::numbers::pi * i / points;
    const double r = i % 2 == 0 ? r_outer : r_inner;
    c.push_back({centre.x + r * std::cos(a), centre.y + r * std::sin(a)});
  }
  return c;
}

/// The star polygon {n/k}: n points on a circle joined every k-th (self-intersecting for 2 <= k < n/2).
inline Contour star_polygon(Point centre, double r, int n, int k, double rotation = 0.0) {
  Contour c;
  for (int i = 0; i < n; ++i) {
    const double a = rotation + 2.0 * std::numbers::pi * ((i * k) % n) / n;
    c.push_back({centre.x + r * std::cos(a), centre.y + r * std::sin(a)});
  }
  return c;
}

/// A random simple polygon: star-shaped around `centre`, sorted random angles, random radii.
inline Contour random_simple_polygon(std::mt19937& rng, Point centre, double r_min, double r_max, int n) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  std::uniform_real_distribution<double> radius(r_min, r_max);
  std::vector<double> angles(static_cast<std::size_t>(n));
  for (double& a : angles) a = angle(rng);
  std::sort(angles.begin(), angles.end());
  Contour c;
  for (const double a : angles) {
    const double r = radius(rng);
    c.push_back({centre.x + r * std::cos(a), centre.y + r * std::sin(a)});
  }
  return c;
}

/// n random vertices in [x0, x1] x [y0, y1]: self-intersecting in general.
inline Contour random_polygon(std::mt19937& rng, double x0, double y0, double x1, double y1, int n) {
  std::uniform_real_distribution<double> ux(x0, x1), uy(y0, y1);
  Contour c;
  for (int i = 0; i < n; ++i) {
    const double x = ux(rng);
    c.push_back({x, uy(rng)});
  }
  return c;
}

}  // namespace curvescan::testing
