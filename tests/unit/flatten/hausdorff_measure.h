// Test support for the flattener: a dense, independent measurement of the Hausdorff distance between a
// curve and the polyline the flattener emitted for it.
//
// Method (deliberately unlike the flattener, which never samples):
//  - the curve is sampled at N uniform parameters with the library's de Casteljau evaluators;
//  - curve -> polyline: the largest distance from a curve sample to the polyline (exact point-to-segment
//    distances);
//  - polyline -> curve: every polyline vertex and 7 interior points of every polyline segment, located
//    on the nearest chord of the samples, then measured to the curve itself by a golden-section search
//    around it: a distance to a real curve point, so this direction can only err on the strict side.
//    (Between two test points of a segment the distance to the curve changes by at most their spacing
//    over 2, but the segment's own interior maximum is where the curve bulges most, which the 7 points
//    resolve to (1/16)^2 of the bulge: the chord -> curve distance is |d| there, quadratic in position.)
// Why N makes the curve -> polyline direction meaningful: for a polynomial of degree n with control points
// P_i, |C''| <= n(n-1)·max|P_{i+2} - 2P_{i+1} + P_i| =: M2 (the second hodograph lies in the hull of its
// coefficients, Ince, *Curves*, "Convex hull property"). The sampled maximum of the distance to the polyline
// misses the true maximum, where that is a smooth interior extremum (the case that matters: the chord's
// sagitta, |d(t)| with |d''| <= |C''|), by at most M2·dt^2/8. N is chosen so that M2·dt^2/8 <=
// tolerance/1000: the measurement resolves 0.1 % of the tolerance. Rational curves: M2 is estimated from
// second differences of the samples (with a factor 4 of headroom), the same resolution argument then holds
// approximately.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "curvescan/curves/bezier.h"
#include "curvescan/curves/point.h"
#include "curvescan/curves/rational_bezier.h"

namespace curvescan::testing {

inline double point_segment_distance(Point p, Point a, Point b) {
  const Vec2 ab = b - a;
  const double len2 = ab.length_squared();
  double t = len2 > 0.0 ? (p - a).dot(ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return p.distance(lerp(a, b, t));
}

/// Nearest segment of the polyline `points` to p, searched first in a window around `hint` (both the query
/// points and the polyline run along the curve, so the nearest segment moves little between queries);
/// if the window's best is above `threshold`, every segment is searched. The window's result is a real
/// distance, so it can only over-estimate: the answer is exact whenever it matters for a check against
/// `threshold`. Returns the distance; `hint` becomes the nearest segment's index.
inline double nearest_segment(const std::vector<Point>& points, Point p, std::size_t& hint,
                              std::size_t window, double threshold) {
  const std::size_t segments = points.size() - 1;
  if (segments == 0) return p.distance(points[0]);
  auto search = [&](std::size_t first, std::size_t last) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = first; i < last; ++i) {
      const double d = point_segment_distance(p, points[i], points[i + 1]);
      if (d < best) {
        best = d;
        hint = i;
      }
    }
    return best;
  };
  const std::size_t first = hint > window ? hint - window : 0;
  const double local = search(first, std::min(segments, hint + 2 * window + 1));
  return local <= threshold ? local : search(0, segments);
}

/// Nearest segment of `points` to p by descent from `hint`: step to the neighbouring segment while that
/// is no farther. Finds a local minimum in O(distance moved); `hint` becomes its index.
inline double descend_segment(const std::vector<Point>& points, Point p, std::size_t& hint) {
  const std::size_t segments = points.size() - 1;
  if (segments == 0) return p.distance(points[0]);
  hint = std::min(hint, segments - 1);
  auto at = [&](std::size_t i) { return point_segment_distance(p, points[i], points[i + 1]); };
  double best = at(hint);
  while (hint + 1 < segments && at(hint + 1) <= best) best = at(++hint);
  while (hint > 0 && at(hint - 1) < best) best = at(--hint);
  return best;
}

/// Distance from p to the curve near parameter interval [t0, t1]: golden-section minimization of
/// |C(t) - p| there, down to an interval of `resolution` (the distance is stationary at its minimum, so
/// the error is second order in it). Always the distance to a real curve point, so never below the true
/// distance.
template <class Eval>
double refined_curve_distance(Eval eval, Point p, double t0, double t1, double resolution) {
  const double inv_phi = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = std::max(0.0, t0), b = std::min(1.0, t1);
  double c = b - inv_phi * (b - a), d = a + inv_phi * (b - a);
  double fc = eval(c).distance(p), fd = eval(d).distance(p);
  for (int i = 0; i < 100 && b - a > resolution; ++i) {
    if (fc < fd) {
      b = d, d = c, fd = fc;
      c = b - inv_phi * (b - a);
      fc = eval(c).distance(p);
    } else {
      a = c, c = d, fc = fd;
      d = a + inv_phi * (b - a);
      fd = eval(d).distance(p);
    }
  }
  return std::min({fc, fd, eval(std::max(0.0, t0)).distance(p), eval(std::min(1.0, t1)).distance(p)});
}

struct Measurement {
  double curve_to_polyline = 0.0;  ///< sampled sup over the curve of the distance to the polyline
  double polyline_to_curve = 0.0;  ///< sup over polyline test points of the distance to the curve (strict)
  double vertex_to_curve = 0.0;    ///< largest distance of a polyline vertex to the curve (strict)
  std::size_t samples = 0;
  [[nodiscard]] double hausdorff() const { return std::max(curve_to_polyline, polyline_to_curve); }
};

/// M2 = n(n-1)·max|second difference| of the control points: a bound on |C''| of a polynomial Bézier.
inline double second_derivative_bound(std::span<const Point> ctrl) {
  const double n = static_cast<double>(ctrl.size()) - 1.0;
  double m = 0.0;
  for (std::size_t i = 0; i + 2 < ctrl.size(); ++i) {
    m = std::max(m, (ctrl[i + 2] - ctrl[i + 1] - (ctrl[i + 1] - ctrl[i])).length());
  }
  return n * (n - 1.0) * m;
}

/// Samples count for the resolution stated above: M2·dt^2/8 <= tolerance/1000, within [1024, 1 << 17]
/// (the cap binds only for the sharpest rational curves and the 1e6-scale ones, whose resolution is then
/// M2·dt^2/8 with dt = 2^-17, still below 1 % of the tolerance in this corpus).
inline std::size_t sample_count(double m2, double tolerance) {
  const double needed = std::sqrt(m2 * 1000.0 / (8.0 * tolerance));
  return static_cast<std::size_t>(std::clamp(std::ceil(needed), 1024.0, double(1 << 17)));
}

/// Measures `polyline` (first vertex included) against the curve `eval` over [0, 1] with `count` samples.
/// Checks against `tolerance` decide when the windowed searches must fall back to full ones.
template <class Eval>
Measurement measure(Eval eval, std::size_t count, double tolerance, const std::vector<Point>& polyline) {
  std::vector<Point> samples(count + 1);
  const double dt = 1.0 / static_cast<double>(count);
  for (std::size_t i = 0; i <= count; ++i) samples[i] = eval(static_cast<double>(i) * dt);
  Measurement m;
  m.samples = count + 1;
  std::size_t hint = 0;
  for (const Point& s : samples) {
    const double local = descend_segment(polyline, s, hint);
    const double d = local <= tolerance ? local : nearest_segment(polyline, s, hint, 0, -1.0);
    m.curve_to_polyline = std::max(m.curve_to_polyline, d);
  }
  // Polyline -> curve: the nearest sample chord locates the nearest curve point, then a golden-section
  // search around it gives the distance to the curve itself (no sampling error, never too small). A
  // result above `threshold` (tolerance for segment points, tolerance/100 for vertices, which lie on the
  // curve) is re-done with the globally nearest chord, in case the window found another branch.
  hint = 0;
  auto refine_at_hint = [&](Point x) {
    const double t = static_cast<double>(hint) * dt;
    return refined_curve_distance(eval, x, t - dt, t + 2.0 * dt, dt * 1e-6);
  };
  auto to_curve = [&](Point x, double threshold) {
    descend_segment(samples, x, hint);
    const double local = refine_at_hint(x);
    if (local <= threshold) return local;
    const std::size_t local_hint = hint;
    nearest_segment(samples, x, hint, 0, -1.0);  // threshold -1: search every chord
    const double global = std::min(local, refine_at_hint(x));
    hint = local_hint;
    return global;
  };
  for (std::size_t i = 0; i < polyline.size(); ++i) {
    const double dv = to_curve(polyline[i], tolerance / 100.0);
    m.vertex_to_curve = std::max(m.vertex_to_curve, dv);
    m.polyline_to_curve = std::max(m.polyline_to_curve, dv);
    if (i + 1 == polyline.size()) break;
    for (int k = 1; k < 8; ++k) {
      const Point x = lerp(polyline[i], polyline[i + 1], k / 8.0);
      m.polyline_to_curve = std::max(m.polyline_to_curve, to_curve(x, tolerance));
    }
  }
  return m;
}

/// Measurement of a polynomial Bézier's polyline (resolution from the M2 bound).
inline Measurement measure_bezier(std::span<const Point> ctrl, double tolerance,
                                  const std::vector<Point>& polyline) {
  const double m2 = second_derivative_bound(ctrl);
  const std::size_t count = sample_count(m2, tolerance);
  return measure([ctrl](double t) { return de_casteljau(ctrl, t); }, count, tolerance, polyline);
}

/// Measurement of a rational Bézier's polyline (M2 estimated from sample second differences, x4).
inline Measurement measure_rational(std::span<const Point> ctrl, std::span<const double> weights,
                                    double tolerance, const std::vector<Point>& polyline) {
  auto eval = [ctrl, weights](double t) { return rational_de_casteljau(ctrl, weights, t); };
  constexpr std::size_t kProbe = 4096;
  const double h = 1.0 / kProbe;
  double m2 = 0.0;
  for (std::size_t i = 1; i < kProbe; ++i) {
    const double t = static_cast<double>(i) * h;
    m2 = std::max(m2, (eval(t + h) - eval(t) - (eval(t) - eval(t - h))).length() / (h * h));
  }
  m2 *= 4.0;
  const std::size_t count = sample_count(m2, tolerance);
  return measure(eval, count, tolerance, polyline);
}

}  // namespace curvescan::testing
