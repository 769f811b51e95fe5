// Seeded random Bézier curves for the curve tests (one generator, so every test states its seed).
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/rational_bezier.h"
#include "curvescan/curves/rect.h"

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

/// The box of `samples` + 1 points of `curve` at evenly spaced parameters in [0, 1]: inside the true box,
/// approaching it from inside as the samples grow.
template <typename Curve>
Rect sampled_box(const Curve& curve, int samples) {
  Rect box = Rect::from_point(curve.eval(0.0));
  for (int k = 1; k <= samples; ++k) box.include(curve.eval(k / static_cast<double>(samples)));
  return box;
}

/// Requires `box` (a computed bounding box) to contain `dense` (the box of dense samples of the same
/// curve) within `contain_slack`, and every side of it to be reached by the samples within `touch_gap`:
/// the box is tight, not a control-point box.
inline void require_tight_box(const Rect& box, const Rect& dense, double contain_slack, double touch_gap) {
  REQUIRE(box.is_finite());
  REQUIRE(dense.x0 >= box.x0 - contain_slack);
  REQUIRE(dense.y0 >= box.y0 - contain_slack);
  REQUIRE(dense.x1 <= box.x1 + contain_slack);
  REQUIRE(dense.y1 <= box.y1 + contain_slack);
  REQUIRE(dense.x0 - box.x0 <= touch_gap);
  REQUIRE(dense.y0 - box.y0 <= touch_gap);
  REQUIRE(box.x1 - dense.x1 <= touch_gap);
  REQUIRE(box.y1 - dense.y1 <= touch_gap);
}

}  // namespace curvescan::test
