// Elliptical arcs as rational quadratic Béziers (Umetani, *Parametric Curve*, §4.1, Dill, *Introduction to Parametric Curves*, "Parametric form"); see arc.h.
#include "curvescan/curves/arc.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "curvescan/curves/affine.h"

namespace curvescan {
namespace {

constexpr double kQuarterTurn = 0.5 * std::numbers::pi;
constexpr double kFullTurn = 2.0 * std::numbers::pi;
// A sweep that exceeds a multiple of 90° only by rounding (e.g. 2π computed as 4·(π/2) + 1 ulp) must not
// produce an extra sliver segment; 1e-12 relative is far above the rounding of such sums and far below
// any sweep a user means.
constexpr double kSegmentCountSlack = 1e-12;

Point unit_circle_point(double angle) noexcept {
  return {std::cos(angle), std::sin(angle)};
}

}  // namespace

std::vector<RationalBezier> elliptical_arc_conics(Point center, double rx, double ry, double x_rotation,
                                                  double start_angle, double sweep_angle) {
  std::vector<RationalBezier> conics;
  if (std::isnan(sweep_angle) || !std::isfinite(start_angle) || sweep_angle == 0.0) return conics;
  const double sweep = std::clamp(sweep_angle, -kFullTurn, kFullTurn);

  const double quarters = std::abs(sweep) / kQuarterTurn;
  const int segment_count = std::max(1, static_cast<int>(std::ceil(quarters * (1.0 - kSegmentCountSlack))));
  const double segment_sweep = sweep / segment_count;
  const double half = 0.5 * segment_sweep;
  const double middle_weight = std::cos(half);  // > 0: |half| <= 45° (plus the slack)

  const Affine to_ellipse =
      Affine::translate(center.x, center.y) * Affine::rotate(x_rotation) * Affine::scale(rx, ry);
  conics.reserve(static_cast<std::size_t>(segment_count));
  // Each segment's angles come from the same expression, so consecutive endpoints are bit-identical; the
  // last, k = segment_count, evaluates to start_angle + sweep exactly as the caller would.
  auto angle_at = [&](int k) {
    return k == segment_count ? start_angle + sweep
                              : start_angle + sweep * (static_cast<double>(k) / segment_count);
  };
  Point from = to_ellipse.apply(unit_circle_point(angle_at(0)));
  for (int k = 0; k < segment_count; ++k) {
    const double a0 = angle_at(k);
    const double a1 = angle_at(k + 1);
    // The tangents at a0 and a1 meet on the bisector at distance 1/cos(φ/2) from the centre.
    const Point apex_on_unit = unit_circle_point(0.5 * (a0 + a1));
    const Point apex{apex_on_unit.x / middle_weight, apex_on_unit.y / middle_weight};
    const Point to = to_ellipse.apply(unit_circle_point(a1));
    conics.emplace_back(std::vector<Point>{from, to_ellipse.apply(apex), to},
                        std::vector<double>{1.0, middle_weight, 1.0});
    from = to;
  }
  return conics;
}

}  // namespace curvescan
