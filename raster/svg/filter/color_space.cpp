// sRGB <-> linearRGB conversions of filter images (color_space.h).
#include "color_space.h"

#include <algorithm>
#include <array>
#include <cmath>

#if defined(__SSE2__)
#include <xmmintrin.h>
#include <emmintrin.h>
#endif

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
  v = v > 0.0f ? v : 0.0f;  // NaN counts as 0
  v = v < 1.0f ? v : 1.0f;  // 1 itself interpolates towards the extra entry, equal to t[kTableIntervals]
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

namespace {

// One row of `count` premultiplied pixels from `in` to `out` (which may be the same memory) through `t`:
// unpremultiplied, looked up, premultiplied again. A pixel without alpha (or NaN alpha) becomes transparent.
void convert_row(const float* in, float* out, int count, const Table& t) noexcept {
  int i = 0;
#if defined(__SSE2__)
  // Four pixels at a time, turned into one register per channel: the same operations as lookup(), lane by
  // lane, with one division for four alphas. A pixel without alpha (or NaN alpha) has every lane masked to
  // zero at the end, which is what the scalar loop writes for it.
  const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f),
               intervals = _mm_set1_ps(static_cast<float>(kTableIntervals));
  for (; i + 4 <= count; i += 4, in += 16, out += 16) {
    __m128 r = _mm_loadu_ps(in), g = _mm_loadu_ps(in + 4), b = _mm_loadu_ps(in + 8), a = _mm_loadu_ps(in + 12);
    _MM_TRANSPOSE4_PS(r, g, b, a);
    const __m128 visible = _mm_cmpgt_ps(a, zero);  // false for NaN
    if (_mm_movemask_ps(visible) == 0) {
      _mm_storeu_ps(out, zero);
      _mm_storeu_ps(out + 4, zero);
      _mm_storeu_ps(out + 8, zero);
      _mm_storeu_ps(out + 12, zero);
      continue;
    }
    // 1 / alpha, and exactly 1 where alpha is 1 (the scalar loop's shortcut gives the same bits: x · 1 = x).
    const __m128 inverse = _mm_div_ps(one, a);
    __m128 channels[3] = {r, g, b};
    alignas(16) int index[3][4];
    __m128 fraction[3];
    for (int c = 0; c < 3; ++c) {
      __m128 v = _mm_mul_ps(channels[c], inverse);
      v = _mm_min_ps(_mm_max_ps(v, zero), one);  // NaN -> 0 (max returns its second operand for NaN)
      const __m128 position = _mm_mul_ps(v, intervals);
      const __m128i k = _mm_cvttps_epi32(position);
      fraction[c] = _mm_sub_ps(position, _mm_cvtepi32_ps(k));
      _mm_store_si128(reinterpret_cast<__m128i*>(index[c]), k);
    }
    for (int c = 0; c < 3; ++c) {
      const auto at = [&](int lane) { return static_cast<std::size_t>(index[c][lane]); };
      const __m128 low = _mm_setr_ps(t[at(0)], t[at(1)], t[at(2)], t[at(3)]);
      const __m128 high = _mm_setr_ps(t[at(0) + 1], t[at(1) + 1], t[at(2) + 1], t[at(3) + 1]);
      channels[c] = _mm_and_ps(_mm_mul_ps(_mm_add_ps(low, _mm_mul_ps(_mm_sub_ps(high, low), fraction[c])), a),
                               visible);
    }
    __m128 alpha = _mm_and_ps(a, visible);
    _MM_TRANSPOSE4_PS(channels[0], channels[1], channels[2], alpha);
    _mm_storeu_ps(out, channels[0]);
    _mm_storeu_ps(out + 4, channels[1]);
    _mm_storeu_ps(out + 8, channels[2]);
    _mm_storeu_ps(out + 12, alpha);
  }
#endif
  for (; i < count; ++i, in += 4, out += 4) {
    const float alpha = in[3];
    if (!(alpha > 0.0f)) {
      out[0] = out[1] = out[2] = out[3] = 0.0f;
      continue;
    }
    const float inverse = alpha == 1.0f ? 1.0f : 1.0f / alpha;
    const float r = lookup(t, in[0] * inverse), g = lookup(t, in[1] * inverse),
                b = lookup(t, in[2] * inverse);
    out[0] = r * alpha;
    out[1] = g * alpha;
    out[2] = b * alpha;
    out[3] = alpha;
  }
}

const Table& table_to(ColorSpace to) {
  return to == ColorSpace::kLinearRgb ? table<srgb_to_linear>() : table<linear_to_srgb>();
}

}  // namespace

void convert_pixels(const float* in, float* out, int count, ColorSpace from, ColorSpace to) noexcept {
  if (from == to) {
    if (in != out) std::copy(in, in + 4 * static_cast<std::size_t>(count), out);
    return;
  }
  convert_row(in, out, count, table_to(to));
}

void convert_color_space(FilterImage& image, ColorSpace from, ColorSpace to) noexcept {
  if (from == to) return;
  const Table& t = table_to(to);
  const PixelRect r = image.extent.intersect(image.bounds());
  for (int y = r.y0; y < r.y1; ++y) convert_row(image.pixel(r.x0, y), image.pixel(r.x0, y), r.width(), t);
}

void convert_color_space(const FilterImage& in, ColorSpace from, ColorSpace to, FilterImage& out) noexcept {
  const PixelRect r = in.extent.intersect(in.bounds()).intersect(out.bounds());
  out.extent = r;
  if (from == to) {
    for (int y = r.y0; y < r.y1; ++y) std::copy(in.pixel(r.x0, y), in.pixel(r.x1, y), out.pixel(r.x0, y));
    return;
  }
  const Table& t = table_to(to);
  for (int y = r.y0; y < r.y1; ++y) convert_row(in.pixel(r.x0, y), out.pixel(r.x0, y), r.width(), t);
}

}  // namespace curvescan::svg::detail::filter
