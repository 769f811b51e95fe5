// Interpolating C2 cubic splines (Gallivan, *Parametric Curves*, "Parameterization", Dill, *Introduction to Parametric Curves*, "A Physical Basis for Cubic
// Splines", Ince, *Curves*, "Spline Interpolation"); moment equations and the cyclic solve as in de Boor,
// "A Practical Guide to Splines", and Press et al., "Numerical Recipes", §2.7 (cyclic tridiagonal).
#include "curvescan/curves/cubic_spline.h"

#include <cmath>
#include <string>

namespace curvescan {
namespace {

Error invalid(std::string message) {
  return Error{ErrorKind::kInvalidArgument, std::move(message)};
}

// Solves the tridiagonal system sub[i] x[i-1] + diag[i] x[i] + super[i] x[i+1] = rhs[i] by the Thomas
// algorithm. Our matrices are strictly diagonally dominant (|diag| = 2 (h_{i-1} + h_i) > h_{i-1} + h_i,
// or a unit row), so no pivoting is needed and every divisor is positive. T is double or Vec2.
template <class T>
std::vector<T> solve_tridiagonal(const std::vector<double>& sub, std::vector<double> diag,
                                 const std::vector<double>& super, std::vector<T> rhs) {
  const std::size_t n = diag.size();
  for (std::size_t i = 1; i < n; ++i) {
    const double factor = sub[i] / diag[i - 1];
    diag[i] -= factor * super[i - 1];
    rhs[i] -= rhs[i - 1] * factor;
  }
  rhs[n - 1] = rhs[n - 1] * (1.0 / diag[n - 1]);
  for (std::size_t i = n - 1; i-- > 0;) rhs[i] = (rhs[i] - rhs[i + 1] * super[i]) * (1.0 / diag[i]);
  return rhs;
}

// Second derivatives M_i of the open spline through points[0..n] at parameters t.
std::vector<Vec2> open_moments(std::span<const Point> points, const std::vector<double>& t,
                               const CubicSplineOptions& options) {
  const std::size_t n = points.size() - 1;  // pieces
  std::vector<double> h(n);
  std::vector<Vec2> slope(n);
  for (std::size_t i = 0; i < n; ++i) {
    h[i] = t[i + 1] - t[i];
    slope[i] = (points[i + 1] - points[i]) / h[i];
  }
  std::vector<double> sub(n + 1, 0.0), diag(n + 1, 1.0), super(n + 1, 0.0);
  std::vector<Vec2> rhs(n + 1, Vec2{});
  for (std::size_t i = 1; i < n; ++i) {
    sub[i] = h[i - 1];
    diag[i] = 2.0 * (h[i - 1] + h[i]);
    super[i] = h[i];
    rhs[i] = (slope[i] - slope[i - 1]) * 6.0;
  }
  if (options.ends == SplineEnds::kClamped) {
    // P'(t_0) = s_0 - h_0 (2 M_0 + M_1) / 6 and P'(t_n) = s_{n-1} + h_{n-1} (M_{n-1} + 2 M_n) / 6.
    diag[0] = 2.0 * h[0];
    super[0] = h[0];
    rhs[0] = (slope[0] - options.start_tangent) * 6.0;
    sub[n] = h[n - 1];
    diag[n] = 2.0 * h[n - 1];
    rhs[n] = (options.end_tangent - slope[n - 1]) * 6.0;
  }  // natural: rows 0 and n stay M = 0
  return solve_tridiagonal(sub, diag, super, rhs);
}

// Second derivatives of the closed spline through points[0..N-1] with t[N] the return parameter: the
// cyclic system, solved as a tridiagonal one plus a rank-one (Sherman–Morrison) correction for the two
// corner entries (Numerical Recipes §2.7, "cyclic").
std::vector<Vec2> closed_moments(std::span<const Point> points, const std::vector<double>& t) {
  const std::size_t n = points.size();  // pieces == points, n >= 3
  std::vector<double> h(n);
  std::vector<Vec2> slope(n);
  for (std::size_t i = 0; i < n; ++i) {
    h[i] = t[i + 1] - t[i];
    slope[i] = (points[(i + 1) % n] - points[i]) / h[i];
  }
  std::vector<double> sub(n), diag(n), super(n);
  std::vector<Vec2> rhs(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t prev = (i + n - 1) % n;
    sub[i] = h[prev];
    diag[i] = 2.0 * (h[prev] + h[i]);
    super[i] = h[i];
    rhs[i] = (slope[i] - slope[prev]) * 6.0;
  }
  const double corner_bottom = super[n - 1];  // row n-1, column 0
  const double corner_top = sub[0];           // row 0, column n-1
  const double gamma = -diag[0];
  std::vector<double> modified = diag;
  modified[0] -= gamma;
  modified[n - 1] -= corner_bottom * corner_top / gamma;
  const std::vector<Vec2> x = solve_tridiagonal(sub, modified, super, rhs);
  std::vector<double> u(n, 0.0);
  u[0] = gamma;
  u[n - 1] = corner_bottom;
  const std::vector<double> z = solve_tridiagonal(sub, modified, super, u);
  const Vec2 factor = (x[0] + x[n - 1] * (corner_top / gamma)) / (1.0 + z[0] + corner_top * z[n - 1] / gamma);
  std::vector<Vec2> moments(n);
  for (std::size_t i = 0; i < n; ++i) moments[i] = x[i] - factor * z[i];
  return moments;
}

// The piece on [t0, t0 + h] from a to b with second derivatives ma, mb, as a Bézier.
Bezier piece(Point a, Point b, Vec2 ma, Vec2 mb, double h) {
  const Vec2 slope = (b - a) / h;
  const Vec2 start_tangent = slope - (ma * 2.0 + mb) * (h / 6.0);
  const Vec2 end_tangent = slope + (ma + mb * 2.0) * (h / 6.0);
  return Bezier({a, a + start_tangent * (h / 3.0), b - end_tangent * (h / 3.0), b});
}

// The points the spline passes through: for a closed spline a last point equal to the first is dropped.
std::span<const Point> effective_points(std::span<const Point> points, bool closed) {
  if (closed && points.size() > 1 && points.back() == points.front()) return points.first(points.size() - 1);
  return points;
}

}  // namespace

Result<std::vector<double>> spline_parameters(std::span<const Point> points,
                                              SplineParameterization parameterization, bool closed) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].is_finite())
      return invalid("point " + std::to_string(i) + " has a NaN or infinite coordinate.");
  }
  points = effective_points(points, closed);
  const std::size_t minimum = closed ? 3 : 2;
  if (points.size() < minimum) {
    return invalid(std::string("a ") + (closed ? "closed" : "open") + " cubic spline needs at least " +
                   std::to_string(minimum) + " points, got " + std::to_string(points.size()) + ".");
  }
  const std::size_t pieces = closed ? points.size() : points.size() - 1;
  std::vector<double> t(pieces + 1, 0.0);
  for (std::size_t i = 1; i <= pieces; ++i) {
    if (parameterization == SplineParameterization::kUniform) {
      t[i] = static_cast<double>(i) / static_cast<double>(pieces);
      continue;
    }
    const double chord = points[i - 1].distance(points[i % points.size()]);
    if (!(chord > 0.0)) {
      return invalid("points " + std::to_string(i - 1) + " and " + std::to_string(i % points.size()) +
                     " coincide, so chord-length parameters do not increase.");
    }
    t[i] = t[i - 1] + chord;
    if (!std::isfinite(t[i])) return invalid("the total chord length overflows a double.");
  }
  return t;
}

Result<std::vector<Bezier>> cubic_spline(std::span<const Point> points, const CubicSplineOptions& options) {
  const bool closed = options.ends == SplineEnds::kClosed;
  auto parameters = spline_parameters(points, options.parameterization, closed);
  if (!parameters) return parameters.error();
  if (options.ends == SplineEnds::kClamped &&
      !(options.start_tangent.is_finite() && options.end_tangent.is_finite())) {
    return invalid("clamped cubic spline end tangents must be finite.");
  }
  points = effective_points(points, closed);
  const std::vector<double>& t = *parameters;
  const std::vector<Vec2> moments = closed ? closed_moments(points, t) : open_moments(points, t, options);
  const std::size_t pieces = t.size() - 1;
  std::vector<Bezier> segments;
  segments.reserve(pieces);
  for (std::size_t i = 0; i < pieces; ++i) {
    const std::size_t next = (i + 1) % points.size();
    segments.push_back(
        piece(points[i], points[next], moments[i], moments[(i + 1) % moments.size()], t[i + 1] - t[i]));
  }
  return segments;
}

}  // namespace curvescan
