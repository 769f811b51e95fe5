// sRGB <-> linearRGB conversions of filter images (color_space.h).
#include "color_space.h"

#include <array>
#include <cmath>

namespace curvescan::svg::detail::filter {
namespace {

constexpr int kTableIntervals = 4096;

using Table = std::array<float, kTableIntervals + 2>;  // one extra entry so that v = 1 interpolates safely

template <float (*Function)(float)>
const Table& table() {
  static const Table values = [] {
    Table t{};
    for (int i = 0; i <= kTableIntervals; ++i) t[i] = Function(static_cast<float>(i) / kTableIntervals);
    t[kTableIntervals + 1] = t[kTableIntervals];
    return t;
  }();
  return values;
}

float lookup(const Table& t, float v) noexcept {
  if (!(v > 0.0f)) return t[0];  // NaN counts as 0
  if (v >= 1.0f) return t[kTableIntervals];
  const float position = v * kTableIntervals;
  const int index = static_cast<int>(position);
  const float fraction = position - static_cast<float>(index);
  return t[index] + (t[index + 1] - t[index]) * fraction;
}

}  // namespace

float srgb_to_linear(float srgb) noexcept {
  if (srgb <= 0.04045f) return srgb / 12.92f;
  return static_cast<float>(std::pow((srgb + 0.055) / 1.055, 2.4));
}

float linear_to_srgb(float linear) noexcept {
  if (linear <= 0.0031308f) return linear * 12.92f;
  return static_cast<float>(1.055 * std::pow(static_cast<double>(linear), 1.0 / 2.4) - 0.055);
}

void convert_color_space(FilterImage& image, ColorSpace from, ColorSpace to) noexcept {
  if (from == to) return;
  const Table& t = to == ColorSpace::kLinearRgb ? table<srgb_to_linear>() : table<linear_to_srgb>();
  float* p = image.rgba.data();
  const std::size_t count = image.rgba.size() / 4;
  for (std::size_t i = 0; i < count; ++i, p += 4) {
    const float alpha = p[3];
    if (!(alpha > 0.0f)) {
      p[0] = p[1] = p[2] = p[3] = 0.0f;
      continue;
    }
    for (int c = 0; c < 3; ++c) p[c] = lookup(t, p[c] / alpha) * alpha;
  }
}

}  // namespace curvescan::svg::detail::filter
