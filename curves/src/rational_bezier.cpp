// RationalBezier: homogeneous split, subsegment, derivative, reversal and arc length (rational_bezier.h).
#include "curvescan/curves/rational_bezier.h"

#include <cstddef>
#include <limits>
#include <utility>
#include <vector>

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

}  // namespace

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
