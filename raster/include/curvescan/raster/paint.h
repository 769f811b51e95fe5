// Paint: what a fill puts on the canvas (a solid colour or a gradient), and the compositing of one pixel.
//
// A Paint is a small variant: solid when `gradient` and `pattern` are null (then `color` is the colour),
// otherwise a linear or radial gradient (gradient.h builds those) or an image (image_pattern.h); `color`
// is then unused. Copies share the immutable gradient or image.
//
// A colour is made one way: a `Color` (straight alpha, four doubles in [0, 1]; the SVG library's CSS
// parser returns the same type), painted with `Paint::solid(color)`. The paint stores it premultiplied
// (Image's encoding), converted exactly as cairo_set_source_rgba does: values outside [0, 1] clamped, NaN
// counted as 0, each channel times alpha to 16 bits, c16 = ⌊c·a·65535 + 0.5⌋, then its high byte c16 >> 8
// as pixman takes it for an 8-bit surface. So a colour paints the same bytes in curvescan and in Cairo.
#pragma once

#include <concepts>
#include <cstdint>
#include <memory>

#include "curvescan/raster/image.h"
#include "curvescan/raster/pixel_format.h"

namespace curvescan {

class GradientShader;  // gradient.h
struct ImagePattern;   // image_pattern.h

/// A straight-alpha colour, every channel in [0, 1] (sRGB, as CSS and PNG use it).
struct Color {
  double r = 0.0, g = 0.0, b = 0.0, a = 1.0;

  constexpr Color() noexcept = default;
  constexpr Color(double red, double green, double blue, double alpha = 1.0) noexcept
      : r(red), g(green), b(blue), a(alpha) {}
  /// Whole-number channels must be the constants 0 or 1 (checked at compile time): {255, 0, 0} would
  /// otherwise clamp to white without a word. 8-bit values go through from_rgba8.
  template <std::integral R, std::integral G, std::integral B, std::integral A = int>
  consteval Color(R red, G green, B blue, A alpha = 1)
      : r(zero_or_one(red)), g(zero_or_one(green)), b(zero_or_one(blue)), a(zero_or_one(alpha)) {}

  bool operator==(const Color&) const = default;

 private:
  static consteval double zero_or_one(long long channel) {
    if (channel != 0 && channel != 1)
      throw "a whole-number colour channel must be 0 or 1: use Color::from_rgba8";
    return static_cast<double>(channel);
  }

 public:
  /// The colour of 8-bit straight channels, as written in #rrggbbaa: each channel / 255.
  [[nodiscard]] static constexpr Color from_rgba8(std::uint8_t r, std::uint8_t g, std::uint8_t b,
                                                  std::uint8_t a = 255) noexcept {
    return {r / 255.0, g / 255.0, b / 255.0, a / 255.0};
  }
};

enum class PaintKind : std::uint8_t { kSolid, kLinearGradient, kRadialGradient, kImagePattern };

struct Paint {
  /// The premultiplied colour (r, g, b <= a).
  Rgba8 color{0, 0, 0, 255};

  /// A solid colour (channels clamped to [0, 1], NaN -> 0), converted to bytes as Cairo converts it.
  [[nodiscard]] static Paint solid(Color color) noexcept;
  /// The gradient, or null for a solid paint.
  std::shared_ptr<const GradientShader> gradient;
  /// An image paint (image_pattern.h), or null. At most one of gradient and pattern is set.
  std::shared_ptr<const ImagePattern> pattern = nullptr;

  /// The paint SVG calls "none": transparent, so a fill with it changes no pixel.
  [[nodiscard]] static Paint none() noexcept { return {Rgba8{0, 0, 0, 0}, nullptr, nullptr}; }
  [[nodiscard]] PaintKind kind() const noexcept;
  /// True for a solid opaque colour (gradients answer false, even when every stop is opaque).
  [[nodiscard]] bool is_opaque() const noexcept {
    return gradient == nullptr && pattern == nullptr && color.a == 255;
  }
};

/// Source-over of the premultiplied colour `source` seen through `coverage` (0..255) onto `destination`,
/// in premultiplied 8-bit space with pixman's rounding (pixman-combine32.h, combine_over_u with a mask):
///   s' = MUL_UN8(s, coverage) per channel, result = s' + MUL_UN8(d, 255 - s'.a) per channel,
/// where MUL_UN8(x, a) = x·a/255 rounded to nearest. This is what Cairo's image backend computes when it
/// fills with a solid colour and an A8 coverage mask, bit for bit (tests/oracle/compositing_test.cpp).
[[nodiscard]] Rgba8 composite_source_over(Rgba8 destination, Rgba8 source, std::uint8_t coverage) noexcept;

/// The same blend computed the obvious way, with integer division for each rounding: the reference that
/// composite_source_over is held to (tests/unit/raster/composite_test.cpp).
[[nodiscard]] Rgba8 composite_source_over_reference(Rgba8 destination, Rgba8 source,
                                                    std::uint8_t coverage) noexcept;

}  // namespace curvescan
