// Where a filtered element is drawn (Filter Effects 1, section 8 "filter region" and the note on filter
// space): the filter image, whose pixels are the element's user space scaled to device resolution, and
// the transforms in and out of it.
//
// An element's transform to device pixels, ctm, is split as ctm = R · S with S = scale(sx, sy), sx and sy
// the lengths of ctm's columns. The element is drawn into the filter image under F = translate(-S·o) · S
// (o: the user point at the image's top-left corner), the primitives run on those axis-aligned pixels,
// and the result is drawn under R · translate(S·o). Without rotation or skew R is a translation and o is
// chosen so that the image's pixels fall exactly on device pixels: the result is copied, not resampled.
//
// Size bound: the filter image holds the union of the filter regions. When that is more pixels than the
// caller allows (the canvas pixel limit, and the memory the primitives' images would take under the
// render's memory limit), the filter space is scaled down uniformly until it fits -- a documented clamp:
// the filter then runs at reduced resolution, with a warning, and memory stays bounded.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "curvescan/curves/affine.h"
#include "curvescan/curves/rect.h"
#include "curvescan/raster/image.h"
#include "color_space.h"
#include "filter_image.h"
#include "filter_space.h"

namespace curvescan::svg::detail::filter {

/// The work one filtered element may cost: the filter image's pixels times its number of primitives (each
/// filter function counts one, an feMerge one more for each node) is at most this, 2^28 (16 primitives
/// over a 4096 x 4096 image, about a second). A longer chain runs at a reduced resolution, as a region
/// beyond the pixel limit does, so that a thousand primitives over a large region cannot take minutes.
inline constexpr std::int64_t kFilterWorkPixels = std::int64_t{1} << 28;

struct FilterSurface {
  FilterSpace space;  ///< scale and origin (bounding-box fields left to the caller)
  int width = 0, height = 0;
  Affine user_to_pixels;    ///< F above: the element's user space -> filter image pixels
  Affine pixels_to_device;  ///< R · translate(S·o): filter image pixels -> device
};

/// The filter image for `region` (user space) under `ctm`, at most `max_pixels` pixels (>= 1). nullopt when
/// ctm is singular or not finite, or the region is empty; `warning` is set when the resolution was reduced.
[[nodiscard]] std::optional<FilterSurface> plan_filter_surface(const Affine& ctm, const Rect& region,
                                                               std::int64_t max_pixels, std::string& warning);

/// The pixels of the filter image that land on a canvas of `width` x `height` device pixels when the
/// result is drawn under `surface.pixels_to_device` (the box of the canvas mapped back, grown by one pixel
/// for bilinear sampling): what the filter graph must compute (FilterSources::needed). The whole image when
/// the placement cannot be inverted.
[[nodiscard]] PixelRect pixels_on_canvas(const FilterSurface& surface, int width, int height) noexcept;

/// Premultiplied RGBA8 -> float, and back (rounded to nearest, colour clamped to alpha). `image` in `space`
/// is converted to sRGB a row at a time on the way (the same values as convert_color_space, then to_image).
[[nodiscard]] FilterImage to_filter_image(const Image& image);
[[nodiscard]] Image to_image(const FilterImage& image, ColorSpace space = ColorSpace::kSrgb);

}  // namespace curvescan::svg::detail::filter
