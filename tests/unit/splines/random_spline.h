// Seeded random B-spline data for the spline tests: valid knot vectors (with repeated knots up to
// multiplicity p + 1, clamped or not) and control points in a box. Header-only, test-only.
#pragma once

#include <catch2/catch.hpp>
#include <cstddef>
#include <random>
#include <vector>

#include "curvescan/curves/bspline.h"
#include "curvescan/curves/knot_vector.h"
#include "curvescan/curves/point.h"

namespace curvescan::test {

/// A valid knot vector for `point_count` points of degree `degree`: gaps uniform in [0.5, 1.5] (spans of
/// comparable length, so derivatives stay moderate), each gap zero with probability 1/4 while the run stays
/// within multiplicity degree + 1; ends clamped (multiplicity p + 1) when `clamp_ends`.
inline std::vector<double> random_knots(std::mt19937_64& rng, std::size_t point_count, int degree,
                                        bool clamp_ends) {
  const std::size_t p = static_cast<std::size_t>(degree);
  const std::size_t count = point_count + p + 1;
  std::uniform_real_distribution<double> gap(0.5, 1.5);
  std::bernoulli_distribution repeat(0.25);
  for (;;) {
    std::vector<double> knots(count);
    knots[0] = std::uniform_real_distribution<double>(-2.0, 2.0)(rng);
    std::size_t run = 1;
    for (std::size_t i = 1; i < count; ++i) {
      const bool at_clamped_end = clamp_ends && (i <= p || i >= count - p);
      const bool same = at_clamped_end || (run < p + 1 && repeat(rng));
      knots[i] = same ? knots[i - 1] : knots[i - 1] + gap(rng);
      run = same ? run + 1 : 1;
    }
    if (validate_knots(knots, point_count, degree)) return knots;
  }
}

inline std::vector<Point> random_points(std::mt19937_64& rng, std::size_t count, double half_width = 1.0) {
  std::uniform_real_distribution<double> coord(-half_width, half_width);
  std::vector<Point> points(count);
  for (Point& point : points) point = {coord(rng), coord(rng)};
  return points;
}

/// A random valid B-spline of the given degree with degree + 1 .. degree + 8 control points.
inline BSpline random_bspline(std::mt19937_64& rng, int degree, bool clamp_ends, double half_width = 1.0) {
  const std::size_t count =
      static_cast<std::size_t>(degree) + 1 + std::uniform_int_distribution<std::size_t>(0, 7)(rng);
  auto spline = BSpline::create(random_points(rng, count, half_width),
                                random_knots(rng, count, degree, clamp_ends), degree);
  REQUIRE(spline.is_ok());
  return std::move(spline).value();
}

/// `count` parameters uniform in [start, end], plus both ends and every knot inside.
inline std::vector<double> sample_parameters(std::mt19937_64& rng, const BSpline& spline, std::size_t count) {
  const double start = spline.domain_start(), end = spline.domain_end();
  std::uniform_real_distribution<double> in_domain(start, end);
  std::vector<double> us{start, end};
  for (const double knot : spline.knots()) {
    if (knot >= start && knot <= end) us.push_back(knot);
  }
  for (std::size_t i = 0; i < count; ++i) us.push_back(in_domain(rng));
  return us;
}

}  // namespace curvescan::test
