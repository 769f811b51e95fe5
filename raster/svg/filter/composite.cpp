// feComposite and feMerge (composite.h).
#include "composite.h"

#include <algorithm>

namespace curvescan::svg::detail::filter {

namespace {

// Applies `op(a, b, o)` to every pixel of `r`: the operator chosen once, outside the loops.
template <class Op>
void each_pixel(const FilterImage& in, const FilterImage& in2, PixelRect r, FilterImage& out,
                Op op) noexcept {
  for (int y = r.y0; y < r.y1; ++y) {
    const float* a = in.pixel(r.x0, y);
    const float* b = in2.pixel(r.x0, y);
    float* o = out.pixel(r.x0, y);
    for (int x = r.x0; x < r.x1; ++x, a += 4, b += 4, o += 4) op(a, b, o);
  }
}

}  // namespace

void composite(const FilterImage& in, const FilterImage& in2, const CompositeParams& params,
               PixelRect subregion, FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds()).intersect(in.bounds()).intersect(in2.bounds());
  switch (params.op) {
    case CompositeOperator::kOver:
      each_pixel(in, in2, r, out, [](const float* a, const float* b, float* o) {
        const float aa = a[3];
        for (int c = 0; c < 4; ++c) o[c] = a[c] + b[c] * (1.0f - aa);
      });
      break;
    case CompositeOperator::kIn:
      each_pixel(in, in2, r, out, [](const float* a, const float* b, float* o) {
        const float ba = b[3];
        for (int c = 0; c < 4; ++c) o[c] = a[c] * ba;
      });
      break;
    case CompositeOperator::kOut:
      each_pixel(in, in2, r, out, [](const float* a, const float* b, float* o) {
        const float ba = b[3];
        for (int c = 0; c < 4; ++c) o[c] = a[c] * (1.0f - ba);
      });
      break;
    case CompositeOperator::kAtop:
      each_pixel(in, in2, r, out, [](const float* a, const float* b, float* o) {
        const float aa = a[3], ba = b[3];
        for (int c = 0; c < 4; ++c) o[c] = a[c] * ba + b[c] * (1.0f - aa);
      });
      break;
    case CompositeOperator::kXor:
      each_pixel(in, in2, r, out, [](const float* a, const float* b, float* o) {
        const float aa = a[3], ba = b[3];
        for (int c = 0; c < 4; ++c) o[c] = a[c] * (1.0f - ba) + b[c] * (1.0f - aa);
      });
      break;
    case CompositeOperator::kLighter:
      each_pixel(in, in2, r, out, [](const float* a, const float* b, float* o) {
        for (int c = 0; c < 4; ++c) o[c] = std::min(1.0f, a[c] + b[c]);
      });
      break;
    case CompositeOperator::kArithmetic:
      each_pixel(in, in2, r, out, [&params](const float* a, const float* b, float* o) {
        float v[4];
        for (int c = 0; c < 4; ++c) {
          const double value = params.k1 * a[c] * b[c] + params.k2 * a[c] + params.k3 * b[c] + params.k4;
          v[c] = static_cast<float>(std::clamp(value, 0.0, 1.0));  // NaN k: clamp keeps NaN; fixed below
          if (!(v[c] >= 0.0f)) v[c] = 0.0f;
        }
        for (int c = 0; c < 3; ++c) v[c] = std::min(v[c], v[3]);
        std::copy(v, v + 4, o);
      });
      break;
  }
}

void merge(const std::vector<const FilterImage*>& inputs, PixelRect subregion, FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds());
  std::vector<const float*> rows(inputs.size());
  for (int y = r.y0; y < r.y1; ++y) {
    // Each input's pixel at (r.x0, y), or null when the row is outside it (it reads transparent there).
    for (std::size_t k = 0; k < inputs.size(); ++k) {
      const FilterImage& image = *inputs[k];
      rows[k] = y < image.height && image.width == out.width ? image.pixel(r.x0, y) : nullptr;
    }
    float* o = out.pixel(r.x0, y);
    for (int x = r.x0; x < r.x1; ++x, o += 4) {
      const std::size_t offset = 4 * static_cast<std::size_t>(x - r.x0);
      float v[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      for (std::size_t k = 0; k < rows.size(); ++k) {
        const float* s = rows[k] != nullptr
                             ? rows[k] + offset
                             : (inputs[k]->bounds().contains(x, y) ? inputs[k]->pixel(x, y) : nullptr);
        if (s == nullptr) continue;
        const float keep = 1.0f - s[3];
        for (int c = 0; c < 4; ++c) v[c] = s[c] + v[c] * keep;
      }
      std::copy(v, v + 4, o);
    }
  }
}

}  // namespace curvescan::svg::detail::filter
