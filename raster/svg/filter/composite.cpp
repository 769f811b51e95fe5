// feComposite and feMerge (composite.h).
#include "composite.h"

#include <algorithm>

namespace curvescan::svg::detail::filter {

void composite(const FilterImage& in, const FilterImage& in2, const CompositeParams& params,
               PixelRect subregion, FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds()).intersect(in.bounds()).intersect(in2.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      const float* a = in.pixel(x, y);
      const float* b = in2.pixel(x, y);
      float* o = out.pixel(x, y);
      const float aa = a[3], ba = b[3];
      switch (params.op) {
        case CompositeOperator::kOver:
          for (int c = 0; c < 4; ++c) o[c] = a[c] + b[c] * (1.0f - aa);
          break;
        case CompositeOperator::kIn:
          for (int c = 0; c < 4; ++c) o[c] = a[c] * ba;
          break;
        case CompositeOperator::kOut:
          for (int c = 0; c < 4; ++c) o[c] = a[c] * (1.0f - ba);
          break;
        case CompositeOperator::kAtop:
          for (int c = 0; c < 4; ++c) o[c] = a[c] * ba + b[c] * (1.0f - aa);
          break;
        case CompositeOperator::kXor:
          for (int c = 0; c < 4; ++c) o[c] = a[c] * (1.0f - ba) + b[c] * (1.0f - aa);
          break;
        case CompositeOperator::kLighter:
          for (int c = 0; c < 4; ++c) o[c] = std::min(1.0f, a[c] + b[c]);
          break;
        case CompositeOperator::kArithmetic: {
          float v[4];
          for (int c = 0; c < 4; ++c) {
            const double value = params.k1 * a[c] * b[c] + params.k2 * a[c] + params.k3 * b[c] + params.k4;
            v[c] = static_cast<float>(std::clamp(value, 0.0, 1.0));  // NaN k: clamp keeps NaN; fixed below
            if (!(v[c] >= 0.0f)) v[c] = 0.0f;
          }
          for (int c = 0; c < 3; ++c) v[c] = std::min(v[c], v[3]);
          std::copy(v, v + 4, o);
          break;
        }
      }
    }
  }
}

void merge(const std::vector<const FilterImage*>& inputs, PixelRect subregion, FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds());
  for (int y = r.y0; y < r.y1; ++y) {
    for (int x = r.x0; x < r.x1; ++x) {
      float v[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      for (const FilterImage* image : inputs) {
        if (!image->bounds().contains(x, y)) continue;
        const float* s = image->pixel(x, y);
        for (int c = 0; c < 4; ++c) v[c] = s[c] + v[c] * (1.0f - s[3]);
      }
      std::copy(v, v + 4, out.pixel(x, y));
    }
  }
}

}  // namespace curvescan::svg::detail::filter
