// feComponentTransfer (component_transfer.h).
#include "component_transfer.h"

#include <algorithm>
#include <cmath>

namespace curvescan::svg::detail::filter {

double TransferFunction::apply(double c) const noexcept {
  double value = c;
  const std::size_t n = table_values.size();
  switch (type) {
    case Type::kIdentity:
      break;
    case Type::kTable:
      if (n == 1) {
        value = table_values[0];
      } else if (n > 1) {
        const double position = std::clamp(c, 0.0, 1.0) * static_cast<double>(n - 1);
        const std::size_t k = std::min(static_cast<std::size_t>(position), n - 2);
        value =
            table_values[k] + (position - static_cast<double>(k)) * (table_values[k + 1] - table_values[k]);
      }
      break;
    case Type::kDiscrete:
      if (n > 0) {
        const std::size_t k =
            std::min(static_cast<std::size_t>(std::clamp(c, 0.0, 1.0) * static_cast<double>(n)), n - 1);
        value = table_values[k];
      }
      break;
    case Type::kLinear:
      value = slope * c + intercept;
      break;
    case Type::kGamma:
      value = amplitude * std::pow(c, exponent) + offset;
      break;
  }
  return value > 0.0 ? std::min(value, 1.0) : 0.0;  // NaN -> 0
}

void component_transfer(const FilterImage& in, const TransferFunctions& functions, PixelRect subregion,
                        FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds()).intersect(in.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      const float* p = in.pixel(x, y);
      double v[4] = {0.0, 0.0, 0.0, p[3]};
      if (p[3] > 0.0f) {
        for (int c = 0; c < 3; ++c) v[c] = std::min(1.0, static_cast<double>(p[c]) / p[3]);
      }
      double result[4];
      for (int c = 0; c < 4; ++c) result[c] = functions[static_cast<std::size_t>(c)].apply(v[c]);
      float* o = out.pixel(x, y);
      for (int c = 0; c < 3; ++c) o[c] = static_cast<float>(result[c] * result[3]);
      o[3] = static_cast<float>(result[3]);
    }
  }
}

}  // namespace curvescan::svg::detail::filter
