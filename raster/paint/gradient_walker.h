// GradientWalker: the colour of a gradient at parameter t, computed with the arithmetic of pixman's
// gradient walker (pixman-gradient-walker.c, pixman 0.42) so that our bytes are Cairo's bytes.
//
// The method. t is put on pixman's 16.16 fixed grid (pos = t·65536 truncated towards zero, as pixman
// converts its double t to pixman_fixed_48_16_t). The spread method folds pos into [0, 1]: repeat keeps
// the low 16 bits, reflect also mirrors odd periods; pad leaves pos alone and relies on sentinel stops at
// ±2^31 that carry the end colours. The stops around the folded position give a segment [left, right),
// shifted back by the period so that it brackets the unfolded pos. Over the segment each straight channel
// and alpha are linear in y = pos/65536, precomputed as slope·y + intercept in float (channels scaled to
// [0, 1] from 16 bits by 1/257 and 1/255); a segment of zero width or one ending at a pad sentinel is
// constant (the mean of its ends). Then a = 255·alpha(y), c = a·channel(y), each rounded as
// (int)(v + 0.5). So colour and alpha are lerped straight, then premultiplied (see gradient.h).
//
// The walker caches the current segment: along a span t moves little, so most pixels cost two float
// multiply-adds per channel and no search. Error against exact arithmetic (color_at_reference): float
// rounding of the intercept form, at most one level per channel (tests/unit/paint/gradient_color_test.cpp),
// plus the 2^-16 quantization of t, which only shows at a hard stop (two stops at the same offset).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "curvescan/raster/gradient.h"
#include "curvescan/raster/image.h"

namespace curvescan::detail {

inline constexpr std::int64_t kFixedOne = 0x10000;  // 1.0 in 16.16
inline constexpr std::int64_t kPadSentinelLow = -(std::int64_t{1} << 31);
inline constexpr std::int64_t kPadSentinelHigh = (std::int64_t{1} << 31) - 1;
/// |t| is clamped to this before conversion to fixed point, so that the conversion is defined; the
/// colour there is already the spread's (pad: an end colour; repeat/reflect: float y has no fraction left).
inline constexpr double kMaxGradientParameter = 1u << 30;

/// A fraction of a 16.16 step beyond which fixed_position moves to the next step (see there).
inline constexpr double kFixedSnap = 1.0 - 1.0 / 65536.0;

/// t -> pixman's 16.16 position (truncation towards zero); NaN must be handled by the caller.
/// A position within 2^-16 of a fixed-point step is first snapped to it: pixman computes t from exact
/// fixed-point inputs, so a t that is mathematically on the grid (integer end points, pixel-aligned
/// stops) lands on it there, while our double evaluation may fall 1 ulp short and truncate to the step
/// below — the other side of a hard stop.
[[nodiscard]] inline std::int64_t fixed_position(double t) noexcept {
  const double fixed = std::clamp(t, -kMaxGradientParameter, kMaxGradientParameter) * 65536.0;
  std::int64_t truncated = static_cast<std::int64_t>(fixed);       // towards zero, as pixman's cast
  const double fraction = fixed - static_cast<double>(truncated);  // in (-1, 1), exact
  if (fraction > kFixedSnap) ++truncated;                          // just below the next step up
  if (fraction < -kFixedSnap) --truncated;                         // just above the next step down
  return truncated;
}

class GradientWalker {
 public:
  explicit GradientWalker(const GradientShader& shader) noexcept
      : stops_(shader.walker_stops()), spread_(shader.spread()) {}

  /// The premultiplied colour at t (spread applied); NaN -> transparent.
  [[nodiscard]] Rgba8 color_at(double t) noexcept {
    if (std::isnan(t)) return {};
    return color_at_fixed(fixed_position(t));
  }

  [[nodiscard]] Rgba8 color_at_fixed(std::int64_t pos) noexcept {
    if (need_reset_ || pos < left_x_ || pos >= right_x_) reset(pos);
    return evaluate(pos);
  }

  /// color_at_fixed computed one channel at a time in scalar floats, as pixman writes it: the reference
  /// the SSE2 form of evaluate() is held to (tests/unit/paint/span_fast_paths_test.cpp).
  [[nodiscard]] Rgba8 color_at_fixed_plain(std::int64_t pos) noexcept {
    if (need_reset_ || pos < left_x_ || pos >= right_x_) reset(pos);
    return evaluate_plain(pos);
  }

  /// out[i] = color_at_fixed(first + i) for i in [0, count): one segment search per segment (the colour
  /// table of gradient_color_table.h).
  void colors_at_fixed(std::int64_t first, std::size_t count, Rgba8* out) noexcept {
    std::size_t i = 0;
    while (i < count) {
      const std::int64_t pos = first + static_cast<std::int64_t>(i);
      if (need_reset_ || pos < left_x_ || pos >= right_x_) reset(pos);
      // The positions up to right_x_ share these coefficients. Under reflect, reset() may pick an empty
      // segment that does not contain pos (pixman's mirrored hard stop); then only pos uses them.
      const std::size_t run_end =
          std::max(i + 1, static_cast<std::size_t>(std::clamp<std::int64_t>(
                              right_x_ - first, 0, static_cast<std::int64_t>(count))));
      for (; i < run_end; ++i) out[i] = evaluate(first + static_cast<std::int64_t>(i));
    }
  }

 private:
  // Channel order of slopes_ and intercepts_: the order of Rgba8.
  static constexpr int kRed = 0, kGreen = 1, kBlue = 2, kAlpha = 3;

  /// The colour at pos with the current segment's coefficients:
  ///   a = 255·(alpha_slope·y + alpha_intercept),  c = a·(c_slope·y + c_intercept),  y = pos / 65536,
  /// each rounded as pixman writes it, (int32_t)(v + 0.5f) & 0xff, clamped to [0, 255] so that a value a
  /// hair above 255.5 stays 255 instead of wrapping to 0. With SSE2 the four channels are one register:
  /// the same IEEE single-precision products and sums in the same order (x86-64's baseline has no fused
  /// multiply-add to change them), so the same bytes as the scalar form.
  [[nodiscard]] Rgba8 evaluate(std::int64_t pos) const noexcept {
#if defined(__SSE2__)
    const float y = static_cast<float>(pos) * (1.0f / 65536.0f);
    const __m128 ramp =
        _mm_add_ps(_mm_mul_ps(_mm_load_ps(slopes_), _mm_set1_ps(y)), _mm_load_ps(intercepts_));
    const __m128 a = _mm_mul_ps(_mm_set1_ps(255.0f), _mm_shuffle_ps(ramp, ramp, 0xff));
    const __m128 alpha_lane = _mm_castsi128_ps(_mm_setr_epi32(0, 0, 0, -1));
    const __m128 channels =
        _mm_or_ps(_mm_andnot_ps(alpha_lane, _mm_mul_ps(a, ramp)), _mm_and_ps(alpha_lane, a));
    const __m128 rounded = _mm_min_ps(_mm_max_ps(_mm_add_ps(channels, _mm_set1_ps(0.5f)), _mm_setzero_ps()),
                                      _mm_set1_ps(255.0f));
    const __m128i words = _mm_cvttps_epi32(rounded);
    const int packed =
        _mm_cvtsi128_si32(_mm_packus_epi16(_mm_packs_epi32(words, words), _mm_setzero_si128()));
    Rgba8 color;
    std::memcpy(static_cast<void*>(&color), &packed, sizeof packed);
    return color;
#else
    return evaluate_plain(pos);
#endif
  }

  [[nodiscard]] Rgba8 evaluate_plain(std::int64_t pos) const noexcept {
    const float y = static_cast<float>(pos) * (1.0f / 65536.0f);
    const float a = 255.0f * (slopes_[kAlpha] * y + intercepts_[kAlpha]);
    const float r = a * (slopes_[kRed] * y + intercepts_[kRed]);
    const float g = a * (slopes_[kGreen] * y + intercepts_[kGreen]);
    const float b = a * (slopes_[kBlue] * y + intercepts_[kBlue]);
    return {to_byte(r), to_byte(g), to_byte(b), to_byte(a)};
  }

  static std::uint8_t to_byte(float v) noexcept {
    const float rounded = std::min(std::max(v + 0.5f, 0.0f), 255.0f);
    return static_cast<std::uint8_t>(static_cast<int>(rounded));
  }

  void reset(std::int64_t pos) noexcept {
    std::int64_t x = pos;
    if (spread_ == SpreadMethod::kRepeat) {
      x = pos & 0xffff;
    } else if (spread_ == SpreadMethod::kReflect) {
      x = pos & 0xffff;
      if ((pos & 0x10000) != 0) x = kFixedOne - x;
    }
    // stops_[0] and stops_.back() are sentinels; find the first real-or-sentinel stop beyond x.
    std::size_t n = 1;
    const std::size_t end = stops_.size() - 1;
    while (n < end && !(x < stops_[n].x)) ++n;
    const GradientShader::WalkerStop* left = &stops_[n - 1];
    const GradientShader::WalkerStop* right = &stops_[n];
    std::int64_t left_x = left->x, right_x = right->x;
    if (spread_ == SpreadMethod::kRepeat) {
      left_x += pos - x;
      right_x += pos - x;
    } else if (spread_ == SpreadMethod::kReflect) {
      if ((pos & 0x10000) != 0) {
        const std::int64_t mirrored_left = kFixedOne - right_x;
        right_x = kFixedOne - left_x;
        left_x = mirrored_left;
        std::swap(left, right);
        x = kFixedOne - x;
      }
      left_x += pos - x;
      right_x += pos - x;
    }

    const float la = left->a * (1.0f / 257.0f), lr = left->r * (1.0f / 257.0f);
    const float lg = left->g * (1.0f / 257.0f), lb = left->b * (1.0f / 257.0f);
    const float ra = right->a * (1.0f / 257.0f), rr = right->r * (1.0f / 257.0f);
    const float rg = right->g * (1.0f / 257.0f), rb = right->b * (1.0f / 257.0f);
    const float lx = static_cast<float>(left_x) * (1.0f / 65536.0f);
    const float rx = static_cast<float>(right_x) * (1.0f / 65536.0f);
    const float width = rx - lx;
    if ((width > -kFloatMin && width < kFloatMin) || left_x == kPadSentinelLow ||
        right_x == kPadSentinelHigh) {
      slopes_[kRed] = slopes_[kGreen] = slopes_[kBlue] = slopes_[kAlpha] = 0.0f;
      intercepts_[kAlpha] = (la + ra) / 510.0f;
      intercepts_[kRed] = (lr + rr) / 510.0f;
      intercepts_[kGreen] = (lg + rg) / 510.0f;
      intercepts_[kBlue] = (lb + rb) / 510.0f;
    } else {
      const float inverse_width = 1.0f / width;
      intercepts_[kAlpha] = (la * rx - ra * lx) * inverse_width * (1.0f / 255.0f);
      intercepts_[kRed] = (lr * rx - rr * lx) * inverse_width * (1.0f / 255.0f);
      intercepts_[kGreen] = (lg * rx - rg * lx) * inverse_width * (1.0f / 255.0f);
      intercepts_[kBlue] = (lb * rx - rb * lx) * inverse_width * (1.0f / 255.0f);
      slopes_[kAlpha] = (ra - la) * inverse_width * (1.0f / 255.0f);
      slopes_[kRed] = (rr - lr) * inverse_width * (1.0f / 255.0f);
      slopes_[kGreen] = (rg - lg) * inverse_width * (1.0f / 255.0f);
      slopes_[kBlue] = (rb - lb) * inverse_width * (1.0f / 255.0f);
    }
    left_x_ = left_x;
    right_x_ = right_x;
    need_reset_ = false;
  }

  static constexpr float kFloatMin = 1.17549435e-38f;  // FLT_MIN: pixman's FLOAT_IS_ZERO bound

  const std::vector<GradientShader::WalkerStop>& stops_;
  SpreadMethod spread_;
  bool need_reset_ = true;
  std::int64_t left_x_ = 0, right_x_ = 0;
  alignas(16) float slopes_[4] = {};  // per channel, in Rgba8 order (kRed .. kAlpha)
  alignas(16) float intercepts_[4] = {};
};

}  // namespace curvescan::detail
