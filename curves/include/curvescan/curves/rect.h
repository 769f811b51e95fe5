// Rect: an axis-aligned box, as curve bounding boxes report it.
#pragma once

#include <algorithm>
#include <cmath>

#include "curvescan/curves/point.h"

namespace curvescan {

/// The closed box [x0, x1] × [y0, y1], in the units of the points it was built from. A box built by
/// from_point/include is valid (x0 <= x1, y0 <= y1) as long as every point was finite; a NaN coordinate
/// anywhere makes the box NaN (is_finite() false) rather than silently dropping the point.
struct Rect {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;

  /// The degenerate box holding just `p`.
  [[nodiscard]] static constexpr Rect from_point(Point p) noexcept { return {p.x, p.y, p.x, p.y}; }

  /// Grows the box to hold `p`; NaN in `p` makes the corresponding edges NaN.
  constexpr void include(Point p) noexcept {
    x0 = grow_min(x0, p.x);
    y0 = grow_min(y0, p.y);
    x1 = grow_max(x1, p.x);
    y1 = grow_max(y1, p.y);
  }

  [[nodiscard]] constexpr double width() const noexcept { return x1 - x0; }
  [[nodiscard]] constexpr double height() const noexcept { return y1 - y0; }
  /// Whether `p` lies in the box grown by `slack` on every side (slack >= 0 absorbs rounding).
  [[nodiscard]] constexpr bool contains(Point p, double slack = 0.0) const noexcept {
    return p.x >= x0 - slack && p.x <= x1 + slack && p.y >= y0 - slack && p.y <= y1 + slack;
  }
  [[nodiscard]] bool is_finite() const noexcept {
    return std::isfinite(x0) && std::isfinite(y0) && std::isfinite(x1) && std::isfinite(y1);
  }
  constexpr bool operator==(const Rect&) const noexcept = default;

 private:
  // NaN-propagating min/max (std::min/max keep or drop NaN depending on argument order).
  static constexpr double grow_min(double edge, double v) noexcept { return (v != v || v < edge) ? v : edge; }
  static constexpr double grow_max(double edge, double v) noexcept { return (v != v || v > edge) ? v : edge; }
};

}  // namespace curvescan
