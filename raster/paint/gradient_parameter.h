// The gradient parameter t of device pixel centres, for the span compositor (gradient_span_compositor.h):
// the same value GradientShader::parameter_at gives for the mapped point, with the per-gradient constants
// taken out of the pixel loop.
//
//  - LinearParameter: t(X, Y) = ((M·(X, Y) − start) · axis) / |axis|² is affine in the device point, so it
//    is three coefficients, t = t0 + tx·X + ty·Y (the reference compositor's expression, evaluated in the
//    same order, so the same doubles).
//  - RadialParameter: gradient.cpp's two-circle solve (SVG 2 section 14.4.3) with A = e·e − dr², fr·dr and
//    fr² computed once. Of the roots (B ± sqrt(B² − A·C)) / A the larger is (B + root) / A when A > 0 and
//    (B − root) / A when A < 0 (dividing by A keeps or reverses the order of B − root <= B + root, also in
//    floating point, rounding being monotonic), so the usual case divides once instead of twice; the
//    smaller root is computed only when the larger one lies on a circle of negative radius. Non-finite
//    intermediate values (overflowing geometry) go to parameter_at itself, whose max/min of a NaN pair
//    decides those. tests/unit/paint/span_fast_paths_test.cpp holds both to parameter_at bit for bit.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/gradient.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace curvescan::detail {

class LinearParameter {
 public:
  LinearParameter(const LinearGradient& linear, const Affine& device_to_gradient) noexcept {
    const Vec2 axis = linear.end - linear.start;
    const Vec2 scaled = axis / axis.length_squared();
    const Affine& m = device_to_gradient;
    t_per_x_ = m.a * scaled.x + m.b * scaled.y;
    t_per_y_ = m.c * scaled.x + m.d * scaled.y;
    t_at_origin_ = (Point{m.e, m.f} - linear.start).dot(scaled);
  }
  [[nodiscard]] double at(double center_x, double center_y) const noexcept {
    return t_at_origin_ + t_per_x_ * center_x + t_per_y_ * center_y;
  }
  /// out[i] = at(x + i + 0.5, center_y) for i in [0, n): the same operations two pixels at a time.
  void fill(int x, double center_y, int n, double* out) const noexcept {
    const double row = t_per_y_ * center_y;
    int i = 0;
#if defined(__SSE2__)
    const __m128d origin = _mm_set1_pd(t_at_origin_), per_x = _mm_set1_pd(t_per_x_), row2 = _mm_set1_pd(row);
    __m128d center_x = _mm_setr_pd(x + 0.5, x + 1.5);
    const __m128d two = _mm_set1_pd(2.0);
    for (; i + 2 <= n; i += 2, center_x = _mm_add_pd(center_x, two)) {
      _mm_storeu_pd(out + i, _mm_add_pd(_mm_add_pd(origin, _mm_mul_pd(per_x, center_x)), row2));
    }
#endif
    for (; i < n; ++i) out[i] = at(x + i + 0.5, center_y);
  }
  /// True when t does not change along a row (a gradient vector parallel to the device y axis).
  [[nodiscard]] bool constant_along_rows() const noexcept {
    return t_per_x_ == 0.0;
  }

 private:
  double t_per_x_ = 0.0, t_per_y_ = 0.0, t_at_origin_ = 0.0;
};

class RadialParameter {
 public:
  RadialParameter(const GradientShader& shader, const Affine& device_to_gradient) noexcept
      : shader_(shader), m_(device_to_gradient) {
    const RadialGradient& radial = shader.radial();
    focal_ = radial.focal;
    e_ = radial.center - radial.focal;
    fr_ = radial.focal_radius;
    dr_ = radial.radius - fr_;
    a_ = e_.dot(e_) - dr_ * dr_;
    fr_dr_ = fr_ * dr_;
    fr_squared_ = fr_ * fr_;
  }

  /// out[i] = at(x + i + 0.5, center_y) for i in [0, n): the same operations on two pixels at a time in
  /// SSE2 double lanes (the selection of the root by masks); a pair with a non-finite intermediate value,
  /// and every pixel when A = 0, take at() itself. B and C of a stretch of pixels are computed first and
  /// the roots second, so that neither loop holds more constants than SSE2 has registers.
  void fill(int x, double center_y, int n, double* out) const noexcept {
    int i = 0;
#if defined(__SSE2__)
    if (a_ != 0.0) {
      constexpr int kStretch = 64;
      alignas(16) double b_values[kStretch];
      alignas(16) double c_values[kStretch];
      const int pairs_end = n & ~1;
      while (i < pairs_end) {
        const int count = std::min(kStretch, pairs_end - i);
        coefficients(x + i, center_y, count, b_values, c_values);
        roots(x + i, center_y, count, b_values, c_values, out + i);
        i += count;
      }
    }
#endif
    for (; i < n; ++i) out[i] = at(x + i + 0.5, center_y);
  }

  [[nodiscard, gnu::always_inline]] double at(double center_x, double center_y) const noexcept {
    const Point p = m_.apply(Point{center_x, center_y});
    const Vec2 d = p - focal_;
    const double b = d.dot(e_) + fr_dr_;
    const double c = d.dot(d) - fr_squared_;
    constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
    if (a_ == 0.0) {
      if (b == 0.0) return kNone;
      const double t = c / (2.0 * b);
      return on_circle(t) ? t : kNone;
    }
    const double discriminant = b * b - a_ * c;
    if (!(discriminant >= 0.0)) return kNone;  // no real root, or NaN input
    const double root = std::sqrt(discriminant);
    if (!(std::isfinite(b) && std::isfinite(root))) return shader_.parameter_at(p);
    const double high = a_ > 0.0 ? (b + root) / a_ : (b - root) / a_;
    if (on_circle(high)) return high;
    const double low = a_ > 0.0 ? (b - root) / a_ : (b + root) / a_;
    return on_circle(low) ? low : kNone;
  }

 private:
  [[nodiscard]] bool on_circle(double t) const noexcept {
    return fr_ + t * dr_ >= 0.0;
  }

#if defined(__SSE2__)
  /// B and C of pixels x .. x + count − 1 (count even), as at() computes them.
  void coefficients(int x, double center_y, int count, double* b_values, double* c_values) const noexcept {
    const __m128d row_x = _mm_set1_pd(m_.c * center_y), row_y = _mm_set1_pd(m_.d * center_y);
    const __m128d ma = _mm_set1_pd(m_.a), mb = _mm_set1_pd(m_.b), me = _mm_set1_pd(m_.e),
                  mf = _mm_set1_pd(m_.f);
    const __m128d focal_x = _mm_set1_pd(focal_.x), focal_y = _mm_set1_pd(focal_.y);
    const __m128d ex = _mm_set1_pd(e_.x), ey = _mm_set1_pd(e_.y);
    const __m128d fr_dr = _mm_set1_pd(fr_dr_), fr_squared = _mm_set1_pd(fr_squared_);
    const __m128d two = _mm_set1_pd(2.0);
    __m128d center_x = _mm_setr_pd(x + 0.5, x + 1.5);
    for (int i = 0; i < count; i += 2, center_x = _mm_add_pd(center_x, two)) {
      // Affine::apply: (a·x + c·y) + e, (b·x + d·y) + f; then d = p − focal, B = d·e + fr·dr, C = d·d − fr².
      const __m128d px = _mm_add_pd(_mm_add_pd(_mm_mul_pd(ma, center_x), row_x), me);
      const __m128d py = _mm_add_pd(_mm_add_pd(_mm_mul_pd(mb, center_x), row_y), mf);
      const __m128d dx = _mm_sub_pd(px, focal_x), dy = _mm_sub_pd(py, focal_y);
      _mm_store_pd(b_values + i, _mm_add_pd(_mm_add_pd(_mm_mul_pd(dx, ex), _mm_mul_pd(dy, ey)), fr_dr));
      _mm_store_pd(c_values + i, _mm_sub_pd(_mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy)), fr_squared));
    }
  }

  /// t of pixels x .. x + count − 1 (count even) from their B and C: the larger root on a circle of
  /// non-negative radius, else the smaller, else NaN. (B − root) / A is computed as (B + (−root)) / A,
  /// the same double, so the larger root is one division whatever the sign of A.
  void roots(int x, double center_y, int count, const double* b_values, const double* c_values,
             double* out) const noexcept {
    const __m128d fr = _mm_set1_pd(fr_), dr = _mm_set1_pd(dr_), a = _mm_set1_pd(a_);
    const __m128d zero = _mm_setzero_pd();
    const __m128d none = _mm_set1_pd(std::numeric_limits<double>::quiet_NaN());
    // A > 0: the larger root takes +root; A < 0: −root (the sign bit flipped).
    const __m128d root_sign = _mm_set1_pd(a_ > 0.0 ? 0.0 : -0.0);
    const auto finite = [&](__m128d v) { return _mm_cmpeq_pd(_mm_sub_pd(v, v), zero); };
    const auto select = [](__m128d mask, __m128d yes, __m128d no) {
      return _mm_or_pd(_mm_and_pd(mask, yes), _mm_andnot_pd(mask, no));
    };
    for (int i = 0; i < count; i += 2) {
      const __m128d b = _mm_load_pd(b_values + i), c = _mm_load_pd(c_values + i);
      const __m128d discriminant = _mm_sub_pd(_mm_mul_pd(b, b), _mm_mul_pd(a, c));
      const __m128d real = _mm_cmpge_pd(discriminant, zero);  // false for NaN, as !(d >= 0)
      const __m128d root = _mm_sqrt_pd(_mm_and_pd(real, discriminant));
      const int real_lanes = _mm_movemask_pd(real);
      if ((_mm_movemask_pd(_mm_and_pd(finite(b), finite(root))) & real_lanes) != real_lanes) {
        out[i] = at(x + i + 0.5, center_y);
        out[i + 1] = at(x + i + 1.5, center_y);
        continue;
      }
      const __m128d signed_root = _mm_xor_pd(root, root_sign);
      const __m128d high = _mm_div_pd(_mm_add_pd(b, signed_root), a);
      const __m128d on_high = _mm_cmpge_pd(_mm_add_pd(fr, _mm_mul_pd(high, dr)), zero);
      __m128d t = select(on_high, high, none);
      if ((_mm_movemask_pd(on_high) & real_lanes) != real_lanes) {
        const __m128d low = _mm_div_pd(_mm_sub_pd(b, signed_root), a);
        const __m128d on_low = _mm_cmpge_pd(_mm_add_pd(fr, _mm_mul_pd(low, dr)), zero);
        t = select(on_high, high, select(on_low, low, none));
      }
      _mm_storeu_pd(out + i, select(real, t, none));
    }
  }
#endif

  const GradientShader& shader_;
  Affine m_;
  Point focal_;
  Vec2 e_;
  double fr_ = 0.0, dr_ = 0.0, a_ = 0.0, fr_dr_ = 0.0, fr_squared_ = 0.0;
};

}  // namespace curvescan::detail
