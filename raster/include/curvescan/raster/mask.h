// ClipMask: an 8-bit coverage mask the size of a canvas, the clip of an SVG clipPath (SVG 1.1 section
// 14.3.5: a clipping path may be antialiased, and its coverage acts like an alpha mask).
//
// A mask is made by filling a path (any fill rule, any transform, antialiased as Canvas::fill), so each
// value is the exact-area coverage of that pixel by the clip shape, 0..255. Nested clips intersect: the
// masks multiply, with pixman's MUL_UN8 rounding (x·y/255 to nearest, as an IN of two A8 masks).
// Applying a mask to a span multiplies its coverage the same way (canvas.h).
//
// bounds() is a rectangle outside which every value is 0 (tight to the rows and columns the filling
// touched), so drawing through a mask can skip everything outside it.
#pragma once

#include <cstdint>
#include <vector>

#include "curvescan/raster/rasterizer.h"

namespace curvescan {

class ClipMask {
 public:
  ClipMask() = default;
  /// A width x height mask that lets nothing through (all 0). Callers check sizes first (limits.h).
  ClipMask(int width, int height)
      : width_(width),
        height_(height),
        values_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {}

  [[nodiscard]] int width() const noexcept { return width_; }
  [[nodiscard]] int height() const noexcept { return height_; }
  [[nodiscard]] std::uint8_t at(int x, int y) const noexcept { return values_[index(x, y)]; }
  [[nodiscard]] const std::uint8_t* row(int y) const noexcept { return values_.data() + index(0, y); }
  /// A rectangle outside which every value is 0 (empty when the mask is all 0).
  [[nodiscard]] IntRect bounds() const noexcept { return bounds_; }

  /// A width x height mask holding `values` (row-major, width·height of them; a mismatch gives an empty
  /// mask that lets nothing through), with tight bounds: an SVG <mask>'s luminance or alpha, computed by
  /// the caller from an image of the mask's content.
  [[nodiscard]] static ClipMask from_values(int width, int height, std::vector<std::uint8_t> values);

  /// Stores the coverage of each span (which must lie inside the mask) and grows bounds() to cover it.
  /// Spans come from a Rasterizer, so they never overlap.
  void write_spans(std::span<const Span> spans) noexcept;
  /// Multiplies every value by the other mask's (same size), x·y/255 rounded to nearest; bounds() becomes
  /// the intersection of both.
  void intersect(const ClipMask& other) noexcept;

 private:
  [[nodiscard]] std::size_t index(int x, int y) const noexcept {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x);
  }
  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> values_;
  IntRect bounds_{};
};

/// x·a/255 rounded to nearest for x, a in [0, 255] (pixman's MUL_UN8, as in composite.cpp).
[[nodiscard]] constexpr std::uint8_t multiply_coverage(unsigned x, unsigned a) noexcept {
  const unsigned t = x * a + 0x80u;
  return static_cast<std::uint8_t>((t + (t >> 8)) >> 8);
}

}  // namespace curvescan
