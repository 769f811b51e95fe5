// ImagePattern: an image as a paint -- the tile of an SVG <pattern> (SVG 1.1 section 13.3) repeated over
// the plane, or an SVG <image> drawn once -- as cairo_pattern_create_for_surface paints a surface.
//
// Spaces. Image pixel (i, j) covers [i, i+1) x [j, j+1) of image space; `image_to_user` maps image space
// to user space and the fill's transform maps user space to device pixels. Each device pixel is sampled
// at its centre, mapped back through the inverse of the composed transform, as gradients are (gradient.h).
//
// Sampling (premultiplied RGBA8, the image's encoding):
//  - kNearest: the pixel whose square holds the point (Cairo's CAIRO_FILTER_NEAREST);
//  - kBilinear: the four pixels whose centres surround the point, weighted by distance, rounded to
//    nearest (Cairo's CAIRO_FILTER_BILINEAR, up to pixman's 7-bit weights: within one level).
// Extend: kRepeat tiles the plane (CAIRO_EXTEND_REPEAT; bilinear samples wrap across the seam, so a tile
// joins its neighbour without a dark line), kNone leaves everything outside the image transparent
// (CAIRO_EXTEND_NONE, bilinear fades over the half pixel at the border), kPad continues the edge pixels
// (CAIRO_EXTEND_PAD: an image filling exactly its rectangle keeps full-strength edges).
// The sampled colour is multiplied by `opacity` (fill-opacity, group opacity) converted as Cairo converts
// an alpha (layer_alpha, layer.h), then composited source-over with the span's coverage (paint.h).
#pragma once

#include <cstdint>
#include <memory>

#include "curvescan/curves/affine.h"
#include "curvescan/raster/image.h"
#include "curvescan/raster/paint.h"

namespace curvescan {

enum class PatternExtend : std::uint8_t { kNone, kRepeat, kPad };
enum class PatternFilter : std::uint8_t { kNearest, kBilinear };

/// A prepared image paint; immutable once built and shared between Paints. image_pattern_paint makes
/// one only for a non-empty image and a finite invertible transform.
struct ImagePattern {
  Image image;
  Affine image_to_user;
  PatternExtend extend = PatternExtend::kRepeat;
  PatternFilter filter = PatternFilter::kBilinear;
  std::uint8_t alpha = 255;  ///< the opacity as an 8-bit alpha

  /// The premultiplied colour at image-space point `p` (before `alpha`), per the rules above.
  [[nodiscard]] Rgba8 sample(Point p) const noexcept;
};

/// A paint of `image` placed by `image_to_user`, or Paint::none() for an empty image, a singular or
/// non-finite transform, or an opacity of 0 (NaN counts as 0).
[[nodiscard]] Paint image_pattern_paint(Image image, const Affine& image_to_user, PatternExtend extend,
                                        PatternFilter filter, double opacity = 1.0);

}  // namespace curvescan
