// Test support for the closed-form bounds of a sub-arc (flatten_quadratic_test.cpp, flatten_cubic_test.cpp):
// the sub-arc's control points by the general walk's de Casteljau splits, a sampled lower estimate of its
// distance to its chord, and whether it overshoots the chord's ends (where the bound's along term counts).
#pragma once

#include <algorithm>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/point.h"
#include "hausdorff_measure.h"
// Private to curves/ (not API); reached by path, as flatness_bound_test does.
#include "../../../curves/src/flatten_split.h"

namespace curvescan::testing {

/// The control points of the sub-arc [a, b] of `ctrl` by two de Casteljau splits (the general walk's way).
inline std::vector<Point> sub_arc(const std::vector<Point>& ctrl, double a, double b) {
  std::vector<Point> right(ctrl.size()), piece(ctrl.size()), scratch(ctrl.size());
  auto lerp_fn = [](Point p, Point q, double u) { return lerp(p, q, u); };
  detail::split_bezier<Point>(ctrl, a, {}, right, scratch, lerp_fn);
  detail::split_bezier<Point>(right, (b - a) / (1.0 - a), piece, {}, scratch, lerp_fn);
  return piece;
}

/// max over `count` + 1 samples of the distance from the piece to its chord (a lower estimate of the
/// Hausdorff distance; the chord -> curve side is dominated, see flatness_bound.h).
inline double sampled_chord_distance(const std::vector<Point>& piece, int count) {
  double worst = 0.0;
  for (int i = 0; i <= count; ++i) {
    const Point p = de_casteljau(piece, static_cast<double>(i) / count);
    worst = std::max(worst, point_segment_distance(p, piece.front(), piece.back()));
  }
  return worst;
}

/// Whether the piece leaves the strip across its chord's ends (2001 samples).
inline bool overshoots(const std::vector<Point>& piece) {
  const Vec2 chord = piece.back() - piece.front();
  for (int k = 0; k <= 2000; ++k) {
    const double s = (de_casteljau(piece, k / 2000.0) - piece.front()).dot(chord) / chord.length_squared();
    if (s < 0.0 || s > 1.0) return true;
  }
  return false;
}

}  // namespace curvescan::testing
