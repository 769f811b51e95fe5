// Paint: what a fill puts on the canvas (a solid colour or a gradient), and the compositing of one pixel.
//
// A Paint is a small variant: solid when `gradient` and `pattern` are null (then `color` is the colour),
// otherwise a linear or radial gradient (gradient.h builds those) or an image (image_pattern.h); `color`
// is then unused. Copies share the immutable gradient or image.
//
// Colours are stored premultiplied (Image's encoding), built from either of two straight-alpha inputs:
//  - StraightRgba8: 8-bit channels, premultiplied by pixman's MUL_UN8 (c·a/255 rounded to nearest);
//  - four doubles in [0, 1] (values outside are clamped, NaN counts as 0), converted exactly as
//    cairo_set_source_rgba does: each channel times alpha to 16 bits, c16 = ⌊c·a·65535 + 0.5⌋, then its
//    high byte c16 >> 8 as pixman takes it for an 8-bit surface. So a colour given as doubles paints the
//    same bytes in curvescan and in Cairo.
#pragma once

#include <cstdint>
#include <memory>

#include "curvescan/raster/image.h"
#include "curvescan/raster/pixel_format.h"

namespace curvescan {

class GradientShader;  // gradient.h
struct ImagePattern;   // image_pattern.h

enum class PaintKind : std::uint8_t { kSolid, kLinearGradient, kRadialGradient, kImagePattern };

struct Paint {
  /// The premultiplied colour (r, g, b <= a).
  Rgba8 color{0, 0, 0, 255};

  [[nodiscard]] static Paint solid(StraightRgba8 straight) noexcept {
    return {premultiply(straight), nullptr, nullptr};
  }
  /// Straight-alpha doubles in [0, 1] (clamped; NaN -> 0), converted as Cairo converts them.
  [[nodiscard]] static Paint solid_rgba(double r, double g, double b, double a) noexcept;
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
