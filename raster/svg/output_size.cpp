// The output size rules of rsvg-convert 2.54 (output_size.h).
#include "output_size.h"

#include <algorithm>
#include <cmath>

namespace curvescan::svg::detail {
namespace {

// The rules, in double arithmetic.
std::optional<OutputSize> sized(const OutputSizeRequest& r) noexcept {
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

}  // namespace

std::optional<ScaledOutputSize> output_size_scaled(const OutputSizeRequest& r) noexcept {
  double largest = std::max(std::fabs(r.natural_width), std::fabs(r.natural_height));
  if (r.width) largest = std::max(largest, std::fabs(*r.width));
  if (r.height) largest = std::max(largest, std::fabs(*r.height));
  if (!std::isfinite(largest) || largest == 0.0) return std::nullopt;
  // Every rule is a product of one length and ratios of lengths and zooms, so scaling all lengths by
  // 2^-exponent (exactly) scales the result by the same; the largest length becomes about 1 and a product
  // with a zoom (at most 1e18 from the command line) stays finite.
  const int exponent = std::ilogb(largest);
  OutputSizeRequest scaled = r;
  scaled.natural_width = std::ldexp(r.natural_width, -exponent);
  scaled.natural_height = std::ldexp(r.natural_height, -exponent);
  if (r.width) scaled.width = std::ldexp(*r.width, -exponent);
  if (r.height) scaled.height = std::ldexp(*r.height, -exponent);
  const std::optional<OutputSize> size = sized(scaled);
  if (!size) return std::nullopt;
  return ScaledOutputSize{*size, exponent};
}

std::optional<OutputSize> output_size(const OutputSizeRequest& r) noexcept {
  const std::optional<OutputSize> size = sized(r);
  if (!size || (std::isfinite(size->width) && std::isfinite(size->height))) return size;
  // A product overflowed on the way: a 1e300-wide document zoomed 1e9 times, then capped by -w 100, is
  // inf * (100 / inf) = NaN in plain arithmetic but 100 wide.
  const std::optional<ScaledOutputSize> scaled = output_size_scaled(r);
  if (!scaled) return size;
  return OutputSize{std::ldexp(scaled->size.width, scaled->exponent),
                    std::ldexp(scaled->size.height, scaled->exponent)};
}

}  // namespace curvescan::svg::detail
