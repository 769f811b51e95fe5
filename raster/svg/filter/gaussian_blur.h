// feGaussianBlur (Filter Effects 1, section 9.13): a separable Gaussian of standard deviation (σx, σy)
// in filter pixels.
//
// The specification allows two computations, and this follows it:
//  - σ < 2.0: the exact Gaussian kernel, sampled at whole pixels over ±ceil(3σ) and normalized to sum 1;
//  - σ >= 2.0: three successive box blurs of size d = floor(σ · 3 · sqrt(2π) / 4 + 0.5). For odd d, each box
//    is centred on the output pixel; for even d, the first box is centred on the boundary between the
//    output pixel and the one to its left, the second on the boundary to its right, and the third has size
//    d + 1 and is centred (the spec's words, so that the three add up to an unbiased blur). Each box is a
//    difference of two prefix sums, so the cost is independent of σ: a huge stdDeviation cannot hang.
// Separable, on premultiplied channels. The blur reads only its input inside the primitive's subregion,
// and pixels beyond it per edgeMode (the default for feGaussianBlur is none).
//
// Two implementations. gaussian_blur_reference is the plain one: per channel, every row blurred as a line
// (prefix sums for the boxes), then the plane transposed so that the columns are lines too. gaussian_blur
// turns a band of 32 rows so that they run down the columns of a small buffer and blurs them with one
// running sum per column, all columns side by side (SSE2), turns them back into a plane of the needed
// columns, then blurs that plane's columns the same way, a strip of 64 at a time: one plane of the
// rectangle, the rest in buffers that stay in the cache. Every edge mode takes that path, the edge handled
// in each box pass (a row beyond the line is folded back into it; the first window of a box wider than
// the line is summed in closed form), so its cost is the rectangle's size whatever σ. With duplicate or
// wrap and a box at least 2^26 times the line's length, the line becomes one value to float precision
// (wrap: its mean; duplicate: a weighted mean of its two end samples; gaussian_blur.cpp gives the
// derivation), and that is computed directly from the ends or the ink: a huge stdDeviation costs a pass
// over the needed pixels, not over the region. The tests hold the two implementations to the same output.
// σ = 0 along an axis leaves that axis alone; the caller treats σ = 0 on both as "the result is the input"
// (Filter Effects 1) and a negative σ as an error.
#pragma once

#include <optional>

#include "edge_mode.h"
#include "filter_image.h"

namespace curvescan::svg::detail::filter {

/// The box sizes the three-box approximation uses for `sigma` (>= 2.0): floor(σ · 3 · sqrt(2π) / 4 + 0.5).
[[nodiscard]] long long box_blur_size(double sigma) noexcept;

/// How many pixels the blur of `sigma` carries content along its axis, at most: ceil(3σ) for the exact
/// kernel, the three boxes' half-widths for the larger σ (0 for σ <= 0 or NaN).
[[nodiscard]] long long blur_reach(double sigma) noexcept;

/// Blurs `in` inside `subregion` into `out` (same size as `in`; pixels outside `subregion` are left as they
/// are). `sigma_x`, `sigma_y` >= 0 in pixels (NaN and negatives count as 0). With `alpha_only`, the colour
/// channels of `in` count as zero (SourceAlpha read from SourceGraphic without a copy). With `written`,
/// only the pixels of the subregion inside it are written (the blur still reads the whole subregion).
void gaussian_blur(const FilterImage& in, PixelRect subregion, double sigma_x, double sigma_y,
                   EdgeMode edge_mode, FilterImage& out, bool alpha_only = false,
                   std::optional<PixelRect> written = std::nullopt);

/// The same result by the plain method (above), for every edge mode.
void gaussian_blur_reference(const FilterImage& in, PixelRect subregion, double sigma_x, double sigma_y,
                             EdgeMode edge_mode, FilterImage& out, bool alpha_only = false);

}  // namespace curvescan::svg::detail::filter
