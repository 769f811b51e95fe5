// feComposite and feMerge (composite.h).
#include "composite.h"

#include <algorithm>

namespace curvescan::svg::detail::filter {

namespace {

// The pixel (x, y) of an input, and how far the next pixel of the row is (0 for a constant).
const float* input_pixel(CompositeInput input, int x, int y) noexcept {
  return input.image != nullptr ? input.image->pixel(x, y) : input.constant;
}
int pixel_step(CompositeInput input) noexcept {
  return input.image != nullptr ? 4 : 0;
}

// Applies `op(a, b, o)` to every pixel of `r`: the operator chosen once, outside the loops.
template <class Op>
void each_pixel(CompositeInput in, CompositeInput in2, PixelRect r, FilterImage& out, Op op) noexcept {
  const int step_a = pixel_step(in), step_b = pixel_step(in2);
  for (int y = r.y0; y < r.y1; ++y) {
    const float* a = input_pixel(in, r.x0, y);
    const float* b = input_pixel(in2, r.x0, y);
    float* o = out.pixel(r.x0, y);
    for (int x = r.x0; x < r.x1; ++x, a += step_a, b += step_b, o += 4) op(a, b, o);
  }
}

}  // namespace

void composite(const FilterImage& in, const FilterImage& in2, const CompositeParams& params,
               PixelRect subregion, FilterImage& out) noexcept {
  composite(CompositeInput{&in}, CompositeInput{&in2}, params,
            subregion.intersect(in.bounds()).intersect(in2.bounds()), out);
}

void composite(CompositeInput in, CompositeInput in2, const CompositeParams& params, PixelRect subregion,
               FilterImage& out) noexcept {
  PixelRect r = subregion.intersect(out.bounds());
  if (in.image != nullptr) r = r.intersect(in.image->bounds());
  if (in2.image != nullptr) r = r.intersect(in2.image->bounds());
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
  merge(inputs, std::vector<bool>(inputs.size(), false), ColorSpace::kSrgb, subregion, out);
}

void merge(const std::vector<const FilterImage*>& inputs, const std::vector<bool>& other_space,
           ColorSpace space, PixelRect subregion, FilterImage& out) noexcept {
  const PixelRect r = subregion.intersect(out.bounds());
  const ColorSpace other = space == ColorSpace::kSrgb ? ColorSpace::kLinearRgb : ColorSpace::kSrgb;
  std::vector<const float*> rows(inputs.size());
  // A row of each input to convert, in `space`.
  std::vector<std::vector<float>> converted(inputs.size());
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    if (other_space[k]) converted[k].resize(4 * static_cast<std::size_t>(r.width()));
  }
  for (int y = r.y0; y < r.y1; ++y) {
    // Each input's pixel at (r.x0, y), or null when the row is outside it (it reads transparent there).
    for (std::size_t k = 0; k < inputs.size(); ++k) {
      const FilterImage& image = *inputs[k];
      rows[k] = y < image.height && image.width == out.width ? image.pixel(r.x0, y) : nullptr;
      if (rows[k] != nullptr && other_space[k]) {
        // Only the part of the row inside the input's extent holds colour; the rest is transparent in
        // both spaces and is copied as it is.
        float* row = converted[k].data();
        const PixelRect ink = image.extent.intersect(image.bounds()).intersect(r);
        if (y < ink.y0 || y >= ink.y1 || ink.empty()) {
          std::fill(converted[k].begin(), converted[k].end(), 0.0f);
        } else {
          std::fill(row, row + 4 * (ink.x0 - r.x0), 0.0f);
          convert_pixels(rows[k] + 4 * (ink.x0 - r.x0), row + 4 * (ink.x0 - r.x0), ink.width(), other, space);
          std::fill(row + 4 * (ink.x1 - r.x0), row + 4 * r.width(), 0.0f);
        }
        rows[k] = row;
      }
    }
    float* o = out.pixel(r.x0, y);
    for (int x = r.x0; x < r.x1; ++x, o += 4) {
      const std::size_t offset = 4 * static_cast<std::size_t>(x - r.x0);
      float v[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      for (std::size_t k = 0; k < rows.size(); ++k) {
        float pixel[4];
        const float* s = rows[k] != nullptr
                             ? rows[k] + offset
                             : (inputs[k]->bounds().contains(x, y) ? inputs[k]->pixel(x, y) : nullptr);
        if (s == nullptr) continue;
        if (rows[k] == nullptr && other_space[k]) {
          convert_pixels(s, pixel, 1, other, space);
          s = pixel;
        }
        const float keep = 1.0f - s[3];
        for (int c = 0; c < 4; ++c) v[c] = s[c] + v[c] * keep;
      }
      std::copy(v, v + 4, o);
    }
  }
}

}  // namespace curvescan::svg::detail::filter
