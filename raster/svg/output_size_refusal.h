// The canvas an output size rounds to, or its refusal in words a user can act on: the size the output
// would be, what made it (the document's size and the options given, as numbers), which limit it passes
// and the option that changes it. Every number in the message is finite: a side that overflows a double
// (-w 1e308 on a document twice as tall as wide) is taken from output_size_scaled and printed in exponent
// form.
#pragma once

#include <cstdint>
#include <optional>

#include "curvescan/status.h"
#include "output_size.h"

namespace curvescan::svg::detail {

struct OutputSizeAsked {
  OutputSizeRequest request;                      ///< natural size (px), -w, -h, the zoom product, -a
  double zoom = 1.0, x_zoom = 1.0, y_zoom = 1.0;  ///< -z, -x, -y as given
  std::optional<double> page_width, page_height;  ///< --page-width / --page-height, px
  double dpi_x = 96.0, dpi_y = 96.0;
  bool exported = false;        ///< the natural size is the --export-id element's, not the document's
  std::int64_t max_pixels = 0;  ///< --max-pixels
};

struct OutputPixels {
  int width = 0;
  int height = 0;
};

/// The canvas of `drawn` (output_size of asked.request), each side rounded up as rsvg-convert does, or the
/// page's: each side 1 to kMaxImageDimension pixels, the two together at most max_pixels; otherwise a
/// kLimitExceeded error saying so.
[[nodiscard]] Result<OutputPixels> output_pixels(const OutputSizeAsked& asked, const OutputSize& drawn);

}  // namespace curvescan::svg::detail
