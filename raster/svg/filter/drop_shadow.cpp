// feDropShadow (drop_shadow.h).
#include "drop_shadow.h"

#include <algorithm>
#include <cmath>

#include "gaussian_blur.h"
#include "offset.h"

namespace curvescan::svg::detail::filter {

void drop_shadow(const FilterImage& in, const DropShadowParams& params, PixelRect subregion, FilterImage& out,
                 PixelRect needed) {
  const PixelRect area = subregion.intersect(in.bounds()).intersect(out.bounds());
  const PixelRect keep = area.intersect(needed);    // the pixels asked for
  const PixelRect ink = in.extent.intersect(area);  // the input outside it is transparent
  const long long shift_x = whole_pixel_offset(params.dx), shift_y = whole_pixel_offset(params.dy);
  const long long reach_x = blur_reach(params.sigma_x), reach_y = blur_reach(params.sigma_y);
  // The blurred alpha at the pixels that the offset brings into `keep`; it is zero beyond the ink's reach,
  // and the blur's result is clipped to the subregion (feGaussianBlur's result is transparent outside it).
  const PixelRect shadow =
      keep.moved(-shift_x, -shift_y).intersect(area).intersect(ink.grown(reach_x, reach_y));
  FilterImage blurred(in.width, in.height);  // zero memory: only the pixels written are touched
  if (!shadow.empty()) {
    // The input outside `read` adds nothing to `shadow` (it is beyond the ink or the reach), and `read` is
    // grown again so that the blur writes every pixel of `shadow` (gaussian_blur writes inside what it
    // reads).
    const PixelRect around = shadow.grown(reach_x, reach_y);
    const PixelRect read = ink.intersect(around).grown(reach_x, reach_y).intersect(around);
    gaussian_blur(in, read, params.sigma_x, params.sigma_y, EdgeMode::kNone, blurred, /*alpha_only=*/true,
                  shadow);
  }
  const float a = std::clamp(params.color.a, 0.0f, 1.0f);
  const float colour[4] = {std::clamp(params.color.r, 0.0f, 1.0f) * a,
                           std::clamp(params.color.g, 0.0f, 1.0f) * a,
                           std::clamp(params.color.b, 0.0f, 1.0f) * a, a};
  // The flood "in" the moved shadow, with the input merged over it (source-over).
  const PixelRect written = keep.intersect(ink.unite(shadow.moved(shift_x, shift_y)));
  for (int y = written.y0; y < written.y1; ++y) {
    const long long from_y = y - shift_y;
    for (int x = written.x0; x < written.x1; ++x) {
      const long long from_x = x - shift_x;
      const bool in_shadow =
          from_x >= shadow.x0 && from_x < shadow.x1 && from_y >= shadow.y0 && from_y < shadow.y1;
      const float coverage =
          in_shadow ? blurred.pixel(static_cast<int>(from_x), static_cast<int>(from_y))[3] : 0.0f;
      const float* source = ink.contains(x, y) ? in.pixel(x, y) : nullptr;
      const float source_alpha = source != nullptr ? source[3] : 0.0f;
      float* p = out.pixel(x, y);
      for (int c = 0; c < 4; ++c)
        p[c] = (source != nullptr ? source[c] : 0.0f) + colour[c] * coverage * (1.0f - source_alpha);
    }
  }
  out.extent = written;
}

}  // namespace curvescan::svg::detail::filter
