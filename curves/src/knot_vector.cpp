// Knot vector generators and validation (Umetani, *Parametric Curve*, §3.1, Gallivan, *Parametric Curves*, "B-spline Curves").
#include "curvescan/curves/knot_vector.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace curvescan {
namespace {

std::string number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

Status check_counts(std::size_t point_count, int degree, int min_degree) {
  if (degree < min_degree) {
    return Status::invalid("B-spline degree " + std::to_string(degree) + " is below the minimum " +
                           std::to_string(min_degree) + ".");
  }
  if (point_count < static_cast<std::size_t>(degree) + 1) {
    return Status::invalid("B-spline of degree " + std::to_string(degree) + " needs at least " +
                           std::to_string(degree + 1) + " control points, got " +
                           std::to_string(point_count) + " (degree must be below the point count).");
  }
  return Status::ok();
}

}  // namespace

Status validate_knots(std::span<const double> knots, std::size_t point_count, int degree) {
  CURVESCAN_PROPAGATE(check_counts(point_count, degree, 0));
  const std::size_t p = static_cast<std::size_t>(degree);
  const std::size_t expected = point_count + p + 1;
  if (knots.size() != expected) {
    return Status::invalid(
        "knot count " + std::to_string(knots.size()) + " != n + p + 1 = " + std::to_string(expected) +
        " for " + std::to_string(point_count) + " control points of degree " + std::to_string(degree) + ".");
  }
  std::size_t run = 1;  // multiplicity of the value ending at index i
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (!std::isfinite(knots[i])) {
      return Status::invalid("knot " + std::to_string(i) + " is not finite (" + number(knots[i]) + ").");
    }
    if (i == 0) continue;
    if (knots[i] < knots[i - 1]) {
      return Status::invalid("knots decrease at index " + std::to_string(i) + " (" + number(knots[i - 1]) +
                             " then " + number(knots[i]) + ").");
    }
    run = knots[i] == knots[i - 1] ? run + 1 : 1;
    if (run > p + 1) {
      return Status::invalid("knot value " + number(knots[i]) + " has multiplicity above degree + 1 = " +
                             std::to_string(p + 1) + " (at index " + std::to_string(i) + ").");
    }
  }
  if (!(knots[p] < knots[point_count])) {
    return Status::invalid("the knot domain [u_p, u_n] = [" + number(knots[p]) + ", " +
                           number(knots[point_count]) + "] is empty.");
  }
  return Status::ok();
}

Result<std::vector<double>> clamped_knots(std::size_t point_count, int degree) {
  CURVESCAN_PROPAGATE(check_counts(point_count, degree, 0));
  const std::size_t p = static_cast<std::size_t>(degree);
  const std::size_t spans = point_count - p;  // number of non-empty spans, >= 1
  std::vector<double> knots(point_count + p + 1);
  for (std::size_t i = 0; i < knots.size(); ++i) {
    if (i <= p) {
      knots[i] = 0.0;
    } else if (i >= point_count) {
      knots[i] = 1.0;
    } else {
      knots[i] = static_cast<double>(i - p) / static_cast<double>(spans);
    }
  }
  return knots;
}

Result<std::vector<double>> uniform_knots(std::size_t point_count, int degree) {
  CURVESCAN_PROPAGATE(check_counts(point_count, degree, 0));
  std::vector<double> knots(point_count + static_cast<std::size_t>(degree) + 1);
  for (std::size_t i = 0; i < knots.size(); ++i) knots[i] = static_cast<double>(i);
  return knots;
}

Result<std::vector<double>> periodic_knots(std::size_t point_count, int degree) {
  CURVESCAN_PROPAGATE(check_counts(point_count, degree, 1));
  // n + p wrapped control points need (n + p) + p + 1 knots.
  return uniform_knots(point_count + static_cast<std::size_t>(degree), degree);
}

}  // namespace curvescan
