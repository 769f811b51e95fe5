// Where the numbers of a filter primitive land in the filter image (Filter Effects 1, sections 9.3-9.6).
//
// The renderer draws a filtered element into a filter image whose axes are the user space's axes scaled to
// device resolution: user point (x, y) is pixel ((x - origin_x) * scale_x, (y - origin_y) * scale_y).
// A rotation or skew of the element's transform is applied when the filtered result is drawn, not before:
// that is "render in a filter space" of the specification, and it keeps a blur's stdDeviation an
// axis-aligned pair as the primitive defines it.
//
// primitiveUnits="objectBoundingBox" makes every number of a primitive a fraction of the element's bounding
// box: x coordinates are bbox.x0 + v * width, lengths along x are v * width, and a length that has no
// axis (a light's z, a displacement scale) is v * sqrt((width^2 + height^2) / 2) (SVG 1.1 7.10, "units").
#pragma once

#include <cmath>

#include "curvescan/curves/point.h"
#include "curvescan/curves/rect.h"

namespace curvescan::svg::detail::filter {

struct FilterSpace {
  double scale_x = 1.0;             ///< filter pixels per user unit along x (> 0)
  double scale_y = 1.0;             ///< filter pixels per user unit along y (> 0)
  double origin_x = 0.0;            ///< the user-space x at the left edge of pixel column 0
  double origin_y = 0.0;            ///< the user-space y at the top edge of pixel row 0
  bool bounding_box_units = false;  ///< primitiveUnits="objectBoundingBox"
  Rect bbox;                        ///< the element's user-space bounding box (used with bounding_box_units)

  /// A primitive's x coordinate attribute (after primitiveUnits) in user space.
  [[nodiscard]] double user_x(double v) const noexcept {
    return bounding_box_units ? bbox.x0 + v * bbox.width() : v;
  }
  [[nodiscard]] double user_y(double v) const noexcept {
    return bounding_box_units ? bbox.y0 + v * bbox.height() : v;
  }
  /// A primitive's length along x (stdDeviation x, dx, radius x, kernelUnitLength x) in user units.
  [[nodiscard]] double user_width(double v) const noexcept {
    return bounding_box_units ? v * bbox.width() : v;
  }
  [[nodiscard]] double user_height(double v) const noexcept {
    return bounding_box_units ? v * bbox.height() : v;
  }
  /// A primitive's length without an axis (a light's z, feDisplacementMap's scale) in user units.
  [[nodiscard]] double user_length(double v) const noexcept {
    if (!bounding_box_units) return v;
    const double w = bbox.width(), h = bbox.height();
    return v * std::sqrt((w * w + h * h) / 2.0);
  }

  /// User space -> filter pixels, for positions and for lengths.
  [[nodiscard]] Point to_pixels(Point user) const noexcept {
    return {(user.x - origin_x) * scale_x, (user.y - origin_y) * scale_y};
  }
  [[nodiscard]] double x_to_pixels(double user_length_x) const noexcept { return user_length_x * scale_x; }
  [[nodiscard]] double y_to_pixels(double user_length_y) const noexcept { return user_length_y * scale_y; }
  /// An axis-free length (light z): scaled by the mean of the two axis scales, as sqrt((sx^2 + sy^2) / 2).
  [[nodiscard]] double length_to_pixels(double user_len) const noexcept {
    return user_len * std::sqrt((scale_x * scale_x + scale_y * scale_y) / 2.0);
  }
};

}  // namespace curvescan::svg::detail::filter
