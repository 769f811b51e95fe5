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
#include <vector>

#include "curvescan/raster/gradient.h"
#include "curvescan/raster/image.h"

namespace curvescan::detail {

inline constexpr std::int64_t kFixedOne = 0x10000;  // 1.0 in 16.16
inline constexpr std::int64_t kPadSentinelLow = -(std::int64_t{1} << 31);
inline constexpr std::int64_t kPadSentinelHigh = (std::int64_t{1} << 31) - 1;
/// |t| is clamped to this before conversion to fixed point, so that the conversion is defined; the
/// colour there is already the spread's (pad: an end colour; repeat/reflect: float y has no fraction left).
inline constexpr double kMaxGradientParameter = 1u << 30;

/// t -> pixman's 16.16 position (truncation towards zero); NaN must be handled by the caller.
/// A position within 2^-16 of a fixed-point step is first snapped to it: pixman computes t from exact
/// fixed-point inputs, so a t that is mathematically on the grid (integer end points, pixel-aligned
/// stops) lands on it there, while our double evaluation may fall 1 ulp short and truncate to the step
/// below — the other side of a hard stop.
[[nodiscard]] inline std::int64_t fixed_position(double t) noexcept {
  const double fixed = std::clamp(t, -kMaxGradientParameter, kMaxGradientParameter) * 65536.0;
  std::int64_t truncated = static_cast<std::int64_t>(fixed);  // towards zero, as pixman's cast
  const double fraction = fixed - static_cast<double>(truncated);  // in (-1, 1), exact
  constexpr double kSnap = 1.0 - 1.0 / 65536.0;
  if (fraction > kSnap) ++truncated;   // just below the next step up
  if (fraction < -kSnap) --truncated;  // just above the next step down
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
    const float y = static_cast<float>(pos) * (1.0f / 65536.0f);
    const float a = 255.0f * (alpha_slope_ * y + alpha_intercept_);
    const float r = a * (red_slope_ * y + red_intercept_);
    const float g = a * (green_slope_ * y + green_intercept_);
    const float b = a * (blue_slope_ * y + blue_intercept_);
    return {to_byte(r), to_byte(g), to_byte(b), to_byte(a)};
  }

 private:
  // pixman writes (int32_t)(v + .5f) & 0xff; v stays within [0, 255] up to float error, and clamping
  // keeps a value a hair above 255.5 at 255 instead of wrapping it to 0.
  static std::uint8_t to_byte(float v) noexcept {
    const float rounded = v + 0.5f;
    return static_cast<std::uint8_t>(rounded <= 0.0f ? 0
                                                     : (rounded >= 255.0f ? 255 : static_cast<int>(rounded)));
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
      alpha_slope_ = red_slope_ = green_slope_ = blue_slope_ = 0.0f;
      alpha_intercept_ = (la + ra) / 510.0f;
      red_intercept_ = (lr + rr) / 510.0f;
      green_intercept_ = (lg + rg) / 510.0f;
      blue_intercept_ = (lb + rb) / 510.0f;
    } else {
      const float inverse_width = 1.0f / width;
      alpha_intercept_ = (la * rx - ra * lx) * inverse_width * (1.0f / 255.0f);
      red_intercept_ = (lr * rx - rr * lx) * inverse_width * (1.0f / 255.0f);
      green_intercept_ = (lg * rx - rg * lx) * inverse_width * (1.0f / 255.0f);
      blue_intercept_ = (lb * rx - rb * lx) * inverse_width * (1.0f / 255.0f);
      alpha_slope_ = (ra - la) * inverse_width * (1.0f / 255.0f);
      red_slope_ = (rr - lr) * inverse_width * (1.0f / 255.0f);
      green_slope_ = (rg - lg) * inverse_width * (1.0f / 255.0f);
      blue_slope_ = (rb - lb) * inverse_width * (1.0f / 255.0f);
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
  float alpha_slope_ = 0, alpha_intercept_ = 0, red_slope_ = 0, red_intercept_ = 0;
  float green_slope_ = 0, green_intercept_ = 0, blue_slope_ = 0, blue_intercept_ = 0;
};

}  // namespace curvescan::detail
