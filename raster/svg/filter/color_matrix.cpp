// feColorMatrix (color_matrix.h).
#include "color_matrix.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace curvescan::svg::detail::filter {

ColorMatrix identity_color_matrix() noexcept {
  return {1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0};
}

ColorMatrix saturate_matrix(double s) noexcept {
  return {0.213 + 0.787 * s,
          0.715 - 0.715 * s,
          0.072 - 0.072 * s,
          0,
          0,
          0.213 - 0.213 * s,
          0.715 + 0.285 * s,
          0.072 - 0.072 * s,
          0,
          0,
          0.213 - 0.213 * s,
          0.715 - 0.715 * s,
          0.072 + 0.928 * s,
          0,
          0,
          0,
          0,
          0,
          1,
          0};
}

ColorMatrix hue_rotate_matrix(double degrees) noexcept {
  const double a = degrees * std::numbers::pi / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  return {0.213 + c * 0.787 - s * 0.213,
          0.715 - c * 0.715 - s * 0.715,
          0.072 - c * 0.072 + s * 0.928,
          0,
          0,
          0.213 - c * 0.213 + s * 0.143,
          0.715 + c * 0.285 + s * 0.140,
          0.072 - c * 0.072 - s * 0.283,
          0,
          0,
          0.213 - c * 0.213 - s * 0.787,
          0.715 - c * 0.715 + s * 0.715,
          0.072 + c * 0.928 + s * 0.072,
          0,
          0,
          0,
          0,
          0,
          1,
          0};
}

ColorMatrix luminance_to_alpha_matrix() noexcept {
  return {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.2125, 0.7154, 0.0721, 0, 0};
}

void color_matrix(const FilterImage& in, const ColorMatrix& m, PixelRect subregion,
                  FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds()).intersect(in.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      const float* p = in.pixel(x, y);
      double v[4] = {0.0, 0.0, 0.0, p[3]};
      if (p[3] > 0.0f) {
        for (int c = 0; c < 3; ++c) v[c] = p[c] / p[3];
      }
      float* o = out.pixel(x, y);
      double result[4];
      for (int row = 0; row < 4; ++row) {
        const double* k = &m[static_cast<std::size_t>(5 * row)];
        const double value = k[0] * v[0] + k[1] * v[1] + k[2] * v[2] + k[3] * v[3] + k[4];
        result[row] = value > 0.0 ? std::min(value, 1.0) : 0.0;  // NaN -> 0
      }
      for (int c = 0; c < 3; ++c) o[c] = static_cast<float>(result[c] * result[3]);
      o[3] = static_cast<float>(result[3]);
    }
  }
}

}  // namespace curvescan::svg::detail::filter
