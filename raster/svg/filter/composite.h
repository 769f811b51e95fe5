// feComposite (Filter Effects 1, section 9.9) and feMerge (9.16): Porter-Duff compositing of premultiplied
// images, `in` (A) over, in, out, atop or xor `in2` (B), lighter (A + B, clamped), and arithmetic
// result = k1·A·B + k2·A + k3·B + k4 per premultiplied channel, clamped to [0, 1] and colour to alpha.
#pragma once

#include <vector>

#include "color_space.h"
#include "filter_image.h"

namespace curvescan::svg::detail::filter {

enum class CompositeOperator { kOver, kIn, kOut, kAtop, kXor, kLighter, kArithmetic };

struct CompositeParams {
  CompositeOperator op = CompositeOperator::kOver;
  double k1 = 0.0, k2 = 0.0, k3 = 0.0, k4 = 0.0;
};

/// An input of feComposite: an image, or one premultiplied colour at every pixel (an feFlood the filter
/// graph has not drawn: the same values without the memory and the pass of the flood).
struct CompositeInput {
  const FilterImage* image = nullptr;
  const float* constant = nullptr;  ///< 4 floats, when `image` is null
};

/// out = in op in2 inside `subregion`.
void composite(const FilterImage& in, const FilterImage& in2, const CompositeParams& params,
               PixelRect subregion, FilterImage& out) noexcept;
/// The same with either input a constant colour; `out` gives the size.
void composite(CompositeInput in, CompositeInput in2, const CompositeParams& params, PixelRect subregion,
               FilterImage& out) noexcept;

/// feMerge: the inputs composited source-over in order, the first at the bottom, inside `subregion`.
void merge(const std::vector<const FilterImage*>& inputs, PixelRect subregion, FilterImage& out) noexcept;
/// The same where the inputs flagged in `other_space` are in the colour space other than `space` (the
/// merge's): they are converted a row at a time as they are merged (convert_pixels), without an image of
/// their own. `out` may be an input that is not flagged.
void merge(const std::vector<const FilterImage*>& inputs, const std::vector<bool>& other_space,
           ColorSpace space, PixelRect subregion, FilterImage& out) noexcept;

}  // namespace curvescan::svg::detail::filter
