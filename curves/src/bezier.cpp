// Bezier: hodograph, split, subsegment, degree elevation, reversal, tight bounds and arc length (bezier.h).
#include "curvescan/curves/bezier.h"

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

// Roots of one coordinate of B' (the differences d_i = P_{i+1} - P_i along that axis) in [0, 1]: the
// scale n of the hodograph does not move them.
void derivative_roots(std::span<const double> differences, std::vector<double>& roots) {
  detail::bernstein_roots(differences, roots);
}

}  // namespace

Bezier Bezier::deriv() const {
  if (points_.empty()) return {};
  if (points_.size() == 1) return Bezier({Point{0.0, 0.0}});
  const double n = static_cast<double>(points_.size() - 1);
  std::vector<Point> hodograph(points_.size() - 1);
  for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
    hodograph[i] = Point::from_vec((points_[i + 1] - points_[i]) * n);
  }
  return Bezier(std::move(hodograph));
}

std::pair<Bezier, Bezier> Bezier::split(double t) const {
  if (points_.empty()) return {};
  std::vector<Point> work = points_, left(points_.size()), right(points_.size());
  detail::de_casteljau_split<Point>(work, t, left, right);
  return {Bezier(std::move(left)), Bezier(std::move(right))};
}

Bezier Bezier::subsegment(double t0, double t1) const {
  if (points_.empty()) return {};
  return Bezier(detail::blossom_subsegment<Point>(points_, t0, t1));
}

Bezier Bezier::elevate() const {
  if (points_.empty()) return {};
  const std::size_t n = points_.size() - 1;
  const double inv = 1.0 / static_cast<double>(n + 1);
  std::vector<Point> raised(n + 2);
  raised.front() = points_.front();
  raised.back() = points_.back();
  for (std::size_t i = 1; i <= n; ++i) {
    // (i P_{i-1} + (n+1-i) P_i) / (n+1) as a lerp from P_i towards P_{i-1}: exact when P_{i-1} == P_i.
    raised[i] = lerp(points_[i], points_[i - 1], static_cast<double>(i) * inv);
  }
  return Bezier(std::move(raised));
}

Bezier Bezier::reversed() const {
  return Bezier(std::vector<Point>(points_.rbegin(), points_.rend()));
}

Rect Bezier::bounding_box() const noexcept {
  if (points_.empty()) return {kNaN, kNaN, kNaN, kNaN};
  Rect box = Rect::from_point(points_.front());
  box.include(points_.back());
  if (!box.is_finite()) return {kNaN, kNaN, kNaN, kNaN};
  for (const Point& p : points_) {
    if (!p.is_finite()) return {kNaN, kNaN, kNaN, kNaN};
  }
  std::vector<double> roots;
  std::vector<double> differences(points_.size() - 1);
  for (int axis = 0; axis < 2; ++axis) {
    for (std::size_t i = 0; i + 1 < points_.size(); ++i) {
      const Vec2 d = points_[i + 1] - points_[i];
      differences[i] = axis == 0 ? d.x : d.y;
    }
    derivative_roots(differences, roots);
  }
  for (double t : roots) {
    if (t > 0.0 && t < 1.0) box.include(eval(t));
  }
  return box;
}

double Bezier::arc_length(double accuracy) const noexcept {
  if (points_.empty()) return kNaN;
  if (points_.size() == 1) return 0.0;
  const Bezier hodograph = deriv();
  const auto speed = [&hodograph](double t) { return hodograph.eval(t).to_vec().length(); };
  return detail::integrate_adaptive(speed, accuracy);
}

}  // namespace curvescan
