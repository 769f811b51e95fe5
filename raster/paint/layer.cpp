// Layer compositing for group opacity: a layer's pixels source-over onto what lies under it, seen
// through a constant alpha (and a clip mask), with the pixman rounding of composite_source_over.
#include "curvescan/raster/layer.h"

#include <algorithm>

#include "curvescan/raster/paint.h"

namespace curvescan {

std::uint8_t layer_alpha(double opacity) noexcept {
  const double unit = opacity > 0.0 ? (opacity < 1.0 ? opacity : 1.0) : 0.0;  // NaN -> 0
  const auto alpha16 = static_cast<unsigned>(unit * 65535.0 + 0.5);
  return static_cast<std::uint8_t>(alpha16 >> 8);
}

void composite_layer(Image& target, int target_origin_x, int target_origin_y, const Layer& layer,
                     std::uint8_t alpha, const ClipMask* mask, BlendMode mode) noexcept {
  if (alpha == 0 || layer.bounds.empty()) return;
  const int x0 = std::max(layer.bounds.x0, target_origin_x);
  const int y0 = std::max(layer.bounds.y0, target_origin_y);
  const int x1 = std::min(layer.bounds.x1, target_origin_x + target.width());
  const int y1 = std::min(layer.bounds.y1, target_origin_y + target.height());
  for (int y = y0; y < y1; ++y) {
    const Rgba8* source = layer.pixels.row(y - layer.bounds.y0);
    Rgba8* destination = target.row(y - target_origin_y);
    const std::uint8_t* mask_row = mask != nullptr ? mask->row(y) : nullptr;
    for (int x = x0; x < x1; ++x) {
      const Rgba8 s = source[x - layer.bounds.x0];
      if (s.a == 0) continue;  // nothing drawn here (premultiplied: the colour is 0 too)
      const std::uint8_t coverage = mask_row == nullptr ? alpha : multiply_coverage(mask_row[x], alpha);
      if (coverage == 0) continue;
      Rgba8& d = destination[x - target_origin_x];
      if (mode != BlendMode::kNormal) {
        d = blend_source_over(d, s, coverage, mode);
      } else {
        d = (coverage == 255 && s.a == 255) ? s : composite_source_over(d, s, coverage);
      }
    }
  }
}

}  // namespace curvescan
