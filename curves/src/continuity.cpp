// classify_join: C^k and G^k of a Bézier join (continuity.h; U. of Toronto, *Parametric Curves*, "Geometric and Parametric
// Continuity", Dill, *Introduction to Parametric Curves*, "Joining Bezier Curves").
#include "curvescan/curves/continuity.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include "curvescan/curves/rect.h"

namespace curvescan {
namespace {

struct EndDerivatives {
  Vec2 first;
  Vec2 second;
};

// Derivatives at t = 1 when at_end, else at t = 0, from the end control points (zero when the degree is too
// low to have them). Walking from the end, the signs of the differences flip: A'(1) = n (P_n - P_{n-1}) but
// B'(0) = n (Q_1 - Q_0); A'' needs no flip since its stencil is symmetric.
EndDerivatives end_derivatives(std::span<const Point> p, bool at_end) {
  const std::size_t n = p.size() - 1;
  auto at = [&](std::size_t k) { return at_end ? p[n - k] : p[k]; };  // k-th point from the join
  const double degree = static_cast<double>(n);
  EndDerivatives d{{0.0, 0.0}, {0.0, 0.0}};
  if (n >= 1) {
    const Vec2 leg = (at(1) - at(0)) * degree;  // points away from the join
    d.first = at_end ? -leg : leg;
  }
  if (n >= 2) d.second = ((at(0) - at(1)) - (at(1) - at(2))) * (degree * (degree - 1.0));
  return d;
}

bool same_vector(Vec2 u, Vec2 v, double tolerance, double scale) {
  return (u - v).length() <= tolerance * std::max({u.length(), v.length(), scale});
}

}  // namespace

JoinContinuity classify_join(const Bezier& a, const Bezier& b, double relative_tolerance) noexcept {
  JoinContinuity result;
  if (a.points().empty() || b.points().empty() || !(relative_tolerance >= 0.0)) return result;
  Rect box = Rect::from_point(a.points().front());
  for (const Point& p : a.points()) box.include(p);
  for (const Point& p : b.points()) box.include(p);
  if (!box.is_finite()) return result;
  const double size = std::max(box.width(), box.height());
  const double tol = relative_tolerance;

  // C0 / G0: positions compared as vectors from the box corner, so a far-away origin does not loosen it.
  const Point corner{box.x0, box.y0};
  if (!same_vector(a.end() - corner, b.start() - corner, tol, size)) return result;
  result = {0, 0};

  const EndDerivatives da = end_derivatives(a.points(), true);
  const EndDerivatives db = end_derivatives(b.points(), false);

  if (same_vector(da.first, db.first, tol, size)) {
    result.parametric = 1;
    if (same_vector(da.second, db.second, tol, size)) result.parametric = 2;
  }

  // G1: both tangents must be non-zero at the scale of the drawing to have a direction.
  const double speed_a = da.first.length(), speed_b = db.first.length();
  if (!(speed_a > tol * size) || !(speed_b > tol * size)) return result;
  const Vec2 ua = da.first / speed_a, ub = db.first / speed_b;
  if (!((ua - ub).length() <= tol)) return result;
  result.geometric = 1;

  // G2: equal signed curvature κ = (X' × X'') / |X'|³.
  const double kappa_a = da.first.cross(da.second) / (speed_a * speed_a * speed_a);
  const double kappa_b = db.first.cross(db.second) / (speed_b * speed_b * speed_b);
  const double curvature_scale = size > 0.0 ? 1.0 / size : 0.0;
  if (std::abs(kappa_a - kappa_b) <=
      tol * std::max({std::abs(kappa_a), std::abs(kappa_b), curvature_scale})) {
    result.geometric = 2;
  }
  return result;
}

}  // namespace curvescan
