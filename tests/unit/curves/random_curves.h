// Seeded random Bézier curves for the curve tests (one generator, so every test states its seed).
#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/rational_bezier.h"

namespace curvescan::test {

/// A Bézier of the given degree with coordinates uniform in [-extent, extent].
inline Bezier random_bezier(std::mt19937_64& rng, int degree, double extent = 100.0) {
  std::uniform_real_distribution<double> coord(-extent, extent);
  std::vector<Point> ctrl(static_cast<std::size_t>(degree) + 1);
  for (Point& p : ctrl) p = {coord(rng), coord(rng)};
  return Bezier(std::move(ctrl));
}

/// A rational Bézier with weights uniform in [0.2, 5] (a 25:1 range keeps the curve well conditioned).
inline RationalBezier random_rational(std::mt19937_64& rng, int degree, double extent = 100.0) {
  std::uniform_real_distribution<double> coord(-extent, extent);
  std::uniform_real_distribution<double> weight(0.2, 5.0);
  std::vector<Point> ctrl(static_cast<std::size_t>(degree) + 1);
  std::vector<double> weights(ctrl.size());
  for (std::size_t i = 0; i < ctrl.size(); ++i) {
    ctrl[i] = {coord(rng), coord(rng)};
    weights[i] = weight(rng);
  }
  return RationalBezier(std::move(ctrl), std::move(weights));
}

/// The largest absolute coordinate among the control points: the scale of rounding errors.
inline double coordinate_scale(std::span<const Point> points) {
  double scale = 0.0;
  for (const Point& p : points) scale = std::max({scale, std::abs(p.x), std::abs(p.y)});
  return scale;
}

}  // namespace curvescan::test
