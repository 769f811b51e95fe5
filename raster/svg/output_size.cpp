// The output size rules of rsvg-convert 2.54 (output_size.h).
#include "output_size.h"

#include <algorithm>

namespace curvescan::svg::detail {

std::optional<OutputSize> output_size(const OutputSizeRequest& r) noexcept {
  if (r.natural_width == 0.0 || r.natural_height == 0.0) return std::nullopt;
  const OutputSize scaled{r.natural_width * r.zoom_x, r.natural_height * r.zoom_y};
  if (!r.width && !r.height) return scaled;
  const bool zoomed = r.zoom_x != 1.0 || r.zoom_y != 1.0;
  if (!zoomed) {
    if (r.width && r.height) {
      if (!r.keep_aspect_ratio) return OutputSize{*r.width, *r.height};
      // xMinYMin meet: the natural size scaled by the smaller of the two ratios.
      const double scale = std::min(*r.width / r.natural_width, *r.height / r.natural_height);
      return OutputSize{r.natural_width * scale, r.natural_height * scale};
    }
    if (r.width) return OutputSize{*r.width, r.natural_height * *r.width / r.natural_width};
    return OutputSize{r.natural_width * *r.height / r.natural_height, *r.height};
  }
  // A zoom capped by -w / -h.
  const bool too_wide = r.width && *r.width < scaled.width;
  const bool too_tall = r.height && *r.height < scaled.height;
  if (!too_wide && !too_tall) return scaled;
  if (!r.keep_aspect_ratio) return OutputSize{r.width.value_or(scaled.width), r.height.value_or(scaled.height)};
  double factor = 1.0;
  if (r.width && r.height) {
    factor = std::min(*r.width / scaled.width, *r.height / scaled.height);
  } else if (r.width) {
    factor = *r.width / scaled.width;
  } else {
    factor = *r.height / scaled.height;
  }
  return OutputSize{scaled.width * factor, scaled.height * factor};
}

}  // namespace curvescan::svg::detail
