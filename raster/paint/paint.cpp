// Paint::solid: straight doubles to premultiplied bytes the way Cairo does it (see paint.h):
// cairo-color.c multiplies each channel by alpha and rounds to 16 bits (_cairo_color_double_to_short:
// d·65535 + 0.5, truncated), and pixman keeps the high byte of each 16-bit channel for an 8-bit colour.
#include "curvescan/raster/paint.h"

#include <cmath>

namespace curvescan {
namespace {

// Clamps to [0, 1]; NaN to 0 (the comparison is false for NaN), so the conversion below is total.
double unit_interval(double v) noexcept {
  return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
}

std::uint8_t cairo_channel(double premultiplied) noexcept {
  const auto c16 = static_cast<unsigned>(premultiplied * 65535.0 + 0.5);  // in [0, 65535]
  return static_cast<std::uint8_t>(c16 >> 8);
}

}  // namespace

Paint Paint::solid(Color color) noexcept {
  const double alpha = unit_interval(color.a);
  return {{cairo_channel(unit_interval(color.r) * alpha), cairo_channel(unit_interval(color.g) * alpha),
           cairo_channel(unit_interval(color.b) * alpha), cairo_channel(alpha)},
          nullptr,
          nullptr};
}

}  // namespace curvescan
