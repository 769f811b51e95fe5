// RationalBezier: homogeneous split, subsegment, derivative, reversal and arc length (rational_bezier.h).
#include "curvescan/curves/rational_bezier.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

#include "bernstein_roots.h"
#include "bezier_p.h"

namespace curvescan {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using detail::Homogeneous;

std::vector<Homogeneous> lift(std::span<const Point> points, std::span<const double> weights) {
  std::vector<Homogeneous> lifted(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) lifted[i] = Homogeneous::lift(points[i], weights[i]);
  return lifted;
}

RationalBezier project(std::span<const Homogeneous> lifted) {
  std::vector<Point> points(lifted.size());
  std::vector<double> weights(lifted.size());
  for (std::size_t i = 0; i < lifted.size(); ++i) {
    points[i] = lifted[i].project();
    weights[i] = lifted[i].w;
  }
  return {std::move(points), std::move(weights)};
}

// Binomial coefficients C(m, 0..m) as doubles (exact up to m = 56, within an ulp or so above: degrees
// up to 64 give m <= 127, C(127, 63) ~ 5e36).
std::vector<double> binomial_row(std::size_t m) {
  std::vector<double> row(m + 1, 1.0);
  for (std::size_t k = 1; k <= m; ++k) {
    row[k] = row[k - 1] * static_cast<double>(m - k + 1) / static_cast<double>(k);
  }
  return row;
}

}  // namespace

Rect RationalBezier::bounding_box() const noexcept {
  const Rect invalid{kNaN, kNaN, kNaN, kNaN};
  if (!is_well_formed()) return invalid;
  Rect box = Rect::from_point(points_.front());
  box.include(points_.back());
  double w_max = 0.0;
  for (std::size_t i = 0; i < points_.size(); ++i) {
    if (!points_[i].is_finite() || !std::isfinite(weights_[i])) return invalid;
    w_max = std::max(w_max, std::fabs(weights_[i]));
  }
  const std::size_t n = points_.size() - 1;
  if (n < 2 || !(w_max > 0.0)) return box;  // a line (or no curve): its ends
  // For one coordinate x, with the origin at x_0 (extrema do not move with it, and the products stay
  // small) and weights scaled by their largest (nor with that): N_i = w_i (x_i - x_0), D_i = w_i. Then
  // H'W - HW' = n sum_i sum_j C(n-1,i) C(n,j) B_{i+j}^{2n-1} / C(2n-1,i+j) (dN_i D_j - dD_i N_j), the
  // factor n dropped (it moves no root).
  const std::vector<double> c_n1 = binomial_row(n - 1), c_n = binomial_row(n),
                            c_2n1 = binomial_row(2 * n - 1);
  std::vector<double> numerator(points_.size()), denominator(points_.size()), coeffs(2 * n), roots;
  for (int axis = 0; axis < 2; ++axis) {
    const double origin = axis == 0 ? points_[0].x : points_[0].y;
    for (std::size_t i = 0; i <= n; ++i) {
      denominator[i] = weights_[i] / w_max;
      numerator[i] = denominator[i] * ((axis == 0 ? points_[i].x : points_[i].y) - origin);
    }
    bool finite = true;
    for (std::size_t k = 0; k < 2 * n; ++k) {
      double sum = 0.0;
      for (std::size_t i = k > n ? k - n : 0; i <= std::min(n - 1, k); ++i) {
        const std::size_t j = k - i;
        sum += c_n1[i] * c_n[j] *
               ((numerator[i + 1] - numerator[i]) * denominator[j] -
                (denominator[i + 1] - denominator[i]) * numerator[j]);
      }
      coeffs[k] = sum / c_2n1[k];
      finite = finite && std::isfinite(coeffs[k]);
    }
    if (!finite) {  // overflow: the control points' extent on this axis still bounds the curve
      for (const Point& p : points_) box.include(axis == 0 ? Point{p.x, box.y0} : Point{box.x0, p.y});
      continue;
    }
    roots.clear();
    detail::bernstein_roots(coeffs, roots);
    for (const double t : roots) {
      if (t > 0.0 && t < 1.0) box.include(eval(t));
    }
  }
  return box;
}

Vec2 RationalBezier::deriv_at(double t) const noexcept {
  if (!is_well_formed()) return {kNaN, kNaN};
  if (points_.size() == 1) return {0.0, 0.0};
  std::vector<Homogeneous> scratch = lift(points_, weights_);
  // Reduce to the last-but-one level: two points b0, b1 with H(t) = lerp(b0, b1, t), H'(t) = n (b1 - b0)
  // (Umetani, *Parametric Curve*, §2.1: the de Casteljau triangle also yields the tangent).
  const std::size_t n = scratch.size() - 1;
  for (std::size_t level = n; level > 1; --level) {
    for (std::size_t i = 0; i < level; ++i) scratch[i] = detail::lerp(scratch[i], scratch[i + 1], t);
  }
  const Homogeneous value = detail::lerp(scratch[0], scratch[1], t);
  const double degree = static_cast<double>(n);
  const double dwx = degree * (scratch[1].wx - scratch[0].wx);
  const double dwy = degree * (scratch[1].wy - scratch[0].wy);
  const double dw = degree * (scratch[1].w - scratch[0].w);
  // d/dt (H/W) = (H' W - H W') / W².
  const double w2 = value.w * value.w;
  return {(dwx * value.w - value.wx * dw) / w2, (dwy * value.w - value.wy * dw) / w2};
}

std::pair<RationalBezier, RationalBezier> RationalBezier::split(double t) const {
  if (!is_well_formed()) return {};
  std::vector<Homogeneous> work = lift(points_, weights_);
  std::vector<Homogeneous> left(work.size()), right(work.size());
  detail::de_casteljau_split<Homogeneous>(work, t, left, right);
  return {project(left), project(right)};
}

RationalBezier RationalBezier::subsegment(double t0, double t1) const {
  if (!is_well_formed()) return {};
  const std::vector<Homogeneous> lifted = lift(points_, weights_);
  return project(detail::blossom_subsegment<Homogeneous>(lifted, t0, t1));
}

RationalBezier RationalBezier::reversed() const {
  return {std::vector<Point>(points_.rbegin(), points_.rend()),
          std::vector<double>(weights_.rbegin(), weights_.rend())};
}

double RationalBezier::arc_length(double accuracy) const noexcept {
  if (!is_well_formed()) return kNaN;
  if (points_.size() == 1) return 0.0;
  const auto speed = [this](double t) { return deriv_at(t).length(); };
  return detail::integrate_adaptive(speed, accuracy);
}

}  // namespace curvescan
