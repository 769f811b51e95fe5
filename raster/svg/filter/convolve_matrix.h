// feConvolveMatrix (Filter Effects 1, section 15.10; SVG 1.1, 15.10):
//   RESULT(X, Y) = (sum over I < orderY, J < orderX of
//                   SOURCE(X - targetX + J, Y - targetY + I) * kernelMatrix(orderX - J - 1, orderY - I - 1))
//                  / divisor + bias * ALPHA(X, Y)
// The kernel is applied rotated by 180 degrees (a true convolution). Without preserveAlpha the four
// premultiplied channels are convolved; bias is added to the colour as bias * ALPHA (Filter Effects 1),
// ALPHA being the result's alpha sum / divisor + bias before clamping (as librsvg and resvg read it; on
// premultiplied values this is bias added to the unpremultiplied colour); then alpha is clamped to [0, 1]
// and the colour to [0, alpha]. With preserveAlpha the unpremultiplied colour is convolved,
// bias is added, the result is clamped to [0, 1] and multiplied by the source pixel's alpha, which is kept.
//
// The input image is the input as its own primitive made it: it exists inside the input's subregion, which
// may reach beyond this primitive's subregion (that only clips the result, Filter Effects 1, 9.7, as for
// the blur), and edgeMode extends it at the input's edge: duplicate repeats the edge pixels, wrap takes
// pixels from the opposite edge, none reads transparent black.
#pragma once

#include <optional>
#include <pugixml.hpp>
#include <string>
#include <vector>

#include "edge_mode.h"
#include "filter_image.h"
#include "filter_space.h"
#include "primitive_numbers.h"

namespace curvescan::svg::detail::filter {

/// The largest orderX or orderY accepted; a larger order is reported as an error (the primitive renders
/// transparent black). The cost is orderX * orderY multiplications per channel and pixel, so 32 x 32 already
/// costs 4096 operations a pixel; real files use 3 x 3 and 5 x 5.
inline constexpr int kMaxConvolveOrder = 32;

struct ConvolveMatrixParams {
  int order_x = 3;
  int order_y = 3;
  std::vector<double> kernel;  ///< order_x * order_y values, row by row as written
  double divisor = 1.0;        ///< never 0
  double bias = 0.0;
  int target_x = 1;  ///< 0 <= target_x < order_x
  int target_y = 1;  ///< 0 <= target_y < order_y
  EdgeMode edge_mode = EdgeMode::kDuplicate;
  bool preserve_alpha = false;
  std::optional<NumberPair> kernel_unit_length;  ///< given and > 0: approximated at device resolution
};

/// Reads order, kernelMatrix, divisor, bias, targetX, targetY, edgeMode, preserveAlpha and
/// kernelUnitLength. nullopt and `error` when: order is not one or two numbers >= 1 once truncated towards
/// zero (Filter Effects 1) or exceeds kMaxConvolveOrder, kernelMatrix is missing or does not hold exactly
/// orderX * orderY numbers, targetX or targetY is outside [0, order), or kernelUnitLength is not positive. A
/// divisor of 0 (or absent) becomes the sum of the kernel, or 1 when that sum is 0.
[[nodiscard]] std::optional<ConvolveMatrixParams> read_convolve_matrix(const pugi::xml_node& primitive,
                                                                       std::string& error);

/// Convolves `in` into `out` inside `subregion`; only the pixels of the subregion inside `written` are
/// computed and written. `input_area` is where the input exists, whose edge edgeMode extends (the input's
/// subregion); `subregion` when not given.
void render_convolve_matrix(const ConvolveMatrixParams& params, const FilterSpace& space, PixelRect subregion,
                            const FilterImage& in, FilterImage& out,
                            std::optional<PixelRect> written = std::nullopt,
                            std::optional<PixelRect> input_area = std::nullopt);

}  // namespace curvescan::svg::detail::filter
