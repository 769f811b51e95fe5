#include "figure/graphs.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "curvescan/curves/bspline.h"
#include "curvescan/curves/interpolate_points.h"

namespace curvescan::figure {

namespace {

/// N_{i,p} on `knots` as a basis function of a clamped knot vector whose domain is N_{i,p}'s support.
struct LocalBasis {
  std::vector<double> knots;
  std::size_t index = 0;
};

/// N_{i,p} depends on u_i .. u_{i+p+1} only, so it is also a basis function of the clamped knot vector
/// made of those knots with u_i and u_{i+p+1} repeated to multiplicity p + 1. There, unlike on the
/// original vector, the whole support lies in the domain, where the bases are the textbook functions, sum
/// to one, and the Greville abscissae reproduce u exactly. nullopt for an empty support or bad indices.
std::optional<LocalBasis> local_basis(std::span<const double> knots, int degree, std::size_t i) {
  if (degree < 0) return std::nullopt;
  const auto p = static_cast<std::size_t>(degree);
  if (i + p + 1 >= knots.size()) return std::nullopt;
  const std::span<const double> support = knots.subspan(i, p + 2);  // u_i .. u_{i+p+1}
  const double lo = support.front();
  const double hi = support.back();
  if (!(lo < hi)) return std::nullopt;
  const auto left = static_cast<std::size_t>(std::count(support.begin(), support.end(), lo));
  const auto right = static_cast<std::size_t>(std::count(support.begin(), support.end(), hi));
  LocalBasis local;
  local.knots.assign(p + 1 - left, lo);
  local.knots.insert(local.knots.end(), support.begin(), support.end());
  local.knots.insert(local.knots.end(), p + 1 - right, hi);
  local.index = p + 1 - left;  // where N_{i,p} landed
  return local;
}

}  // namespace

double basis_function(std::span<const double> knots, int degree, std::size_t i, double u) {
  if (std::isnan(u)) return u;
  const std::optional<LocalBasis> local = local_basis(knots, degree, i);
  if (!local || u < local->knots.front() || u > local->knots.back()) return 0.0;
  // At the support's right end the clamped vector's right-end convention gives the limit from the left;
  // the half-open convention (Ince: t_i <= t < t_{i+1}) gives 0 there, except at the last knot.
  if (u == local->knots.back() && u != knots.back()) return 0.0;
  return bspline_basis(local->knots, degree, local->index, u);
}

std::vector<Bezier> basis_function_graph(std::span<const double> knots, int degree, std::size_t i) {
  std::optional<LocalBasis> local = local_basis(knots, degree, i);
  if (!local) return {};
  const double lo = local->knots.front();
  const double hi = local->knots.back();
  if (degree == 0) return {Bezier({{lo, 1.0}, {hi, 1.0}})};
  const auto p = static_cast<std::size_t>(degree);
  const std::size_t count = local->knots.size() - p - 1;
  std::vector<Point> control;
  control.reserve(count);
  for (std::size_t j = 0; j < count; ++j) {
    double greville = 0.0;
    for (std::size_t k = j + 1; k <= j + p; ++k) greville += local->knots[k];
    control.push_back({greville / static_cast<double>(p), j == local->index ? 1.0 : 0.0});
  }
  Result<BSpline> graph = BSpline::create(std::move(control), std::move(local->knots), degree);
  if (!graph) return {};
  return graph->to_beziers();
}

Bezier bernstein_graph(int n, int i) {
  std::vector<Point> control;
  for (int k = 0; k <= n; ++k) {
    control.push_back({static_cast<double>(k) / static_cast<double>(n), k == i ? 1.0 : 0.0});
  }
  return Bezier(std::move(control));
}

Bezier blending_graph(const BasisMatrix& m, int column) {
  const auto j = static_cast<std::size_t>(column);
  // Row r of M multiplies t^(3-r); power_to_bezier takes ascending powers. x(t) = t.
  const std::vector<Vec2> coefficients{{0.0, m[3][j]}, {1.0, m[2][j]}, {0.0, m[1][j]}, {0.0, m[0][j]}};
  return power_to_bezier(coefficients);
}

Bezier quadratic_graph(double a, double b, double fa, double fm, double fb) {
  const std::optional<QuadraticPowerForm> form =
      interpolate_quadratic({a, fa}, {0.5 * (a + b), fm}, {b, fb}, 0.5);
  if (!form) return Bezier();
  return form->to_bezier();
}

}  // namespace curvescan::figure
