// The filter image's placement (filter_surface.h).
#include "filter_surface.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "curvescan/raster/limits.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace curvescan::svg::detail::filter {
namespace {

struct Grid {
  double origin_x, origin_y;
  double width, height;  // whole pixels, as doubles (possibly huge)
};

// The image grid for `region` at scale (sx, sy), aligned to device pixels through the translation e, f.
Grid grid_for(const Rect& region, double sx, double sy, double e, double f) {
  const double left = std::floor(sx * region.x0 + e + 1e-4), top = std::floor(sy * region.y0 + f + 1e-4);
  const double right = std::ceil(sx * region.x1 + e - 1e-4), bottom = std::ceil(sy * region.y1 + f - 1e-4);
  return Grid{(left - e) / sx, (top - f) / sy, right - left, bottom - top};
}

}  // namespace

std::optional<FilterSurface> plan_filter_surface(const Affine& ctm, const Rect& region,
                                                 std::int64_t max_pixels, std::string& warning) {
  double sx = std::hypot(ctm.a, ctm.b), sy = std::hypot(ctm.c, ctm.d);
  if (!(sx > 0.0) || !(sy > 0.0) || !std::isfinite(sx) || !std::isfinite(sy) || !std::isfinite(ctm.e) ||
      !std::isfinite(ctm.f) || !region.is_finite() || !(region.width() > 0.0) || !(region.height() > 0.0)) {
    return std::nullopt;
  }
  const Affine rest{ctm.a / sx, ctm.b / sx, ctm.c / sy, ctm.d / sy, ctm.e, ctm.f};
  // Aligning to device pixels only means something when `rest` is a translation; otherwise any origin is
  // as good, and this one is harmless.
  Grid grid = grid_for(region, sx, sy, ctm.e, ctm.f);
  const double limit = static_cast<double>(std::max<std::int64_t>(1, max_pixels));
  const double dimension = static_cast<double>(kMaxImageDimension);
  if (grid.width * grid.height > limit || grid.width > dimension || grid.height > dimension) {
    const double wide = region.width() * sx, tall = region.height() * sy;
    double factor = std::sqrt(limit / ((wide + 2.0) * (tall + 2.0)));
    factor = std::min({factor, (dimension - 2.0) / (wide + 2.0), (dimension - 2.0) / (tall + 2.0)});
    sx *= factor;
    sy *= factor;
    if (!(sx > 0.0) || !(sy > 0.0)) return std::nullopt;
    grid = grid_for(region, sx, sy, ctm.e, ctm.f);
    warning = "a filter region is beyond the pixel, memory and work limits; it is filtered at " +
              std::to_string(static_cast<int>(std::ceil(factor * 100.0))) + " % of the resolution";
  }
  if (!(grid.width >= 1.0) || !(grid.height >= 1.0)) return std::nullopt;
  FilterSurface surface;
  surface.space.scale_x = sx;
  surface.space.scale_y = sy;
  surface.space.origin_x = grid.origin_x;
  surface.space.origin_y = grid.origin_y;
  surface.width = static_cast<int>(grid.width);
  surface.height = static_cast<int>(grid.height);
  surface.user_to_pixels =
      Affine::translate(-sx * grid.origin_x, -sy * grid.origin_y) * Affine::scale(sx, sy);
  // The scale the image's pixels have in device space: the original ctm's over the (possibly reduced) one.
  const double back_x = std::hypot(ctm.a, ctm.b) / sx, back_y = std::hypot(ctm.c, ctm.d) / sy;
  surface.pixels_to_device =
      rest * Affine::scale(back_x, back_y) * Affine::translate(sx * grid.origin_x, sy * grid.origin_y);
  return surface;
}

PixelRect pixels_on_canvas(const FilterSurface& surface, int width, int height) noexcept {
  const PixelRect whole{0, 0, surface.width, surface.height};
  const std::optional<Affine> back = surface.pixels_to_device.inverse();
  if (!back) return whole;
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  for (const Point corner :
       {Point{0.0, 0.0}, Point{static_cast<double>(width), 0.0}, Point{0.0, static_cast<double>(height)},
        Point{static_cast<double>(width), static_cast<double>(height)}}) {
    const Point p = back->apply(corner);
    x0 = std::min(x0, p.x);
    y0 = std::min(y0, p.y);
    x1 = std::max(x1, p.x);
    y1 = std::max(y1, p.y);
  }
  if (!std::isfinite(x0) || !std::isfinite(y0) || !std::isfinite(x1) || !std::isfinite(y1)) return whole;
  const auto whole_pixel = [](double v) { return static_cast<int>(std::clamp(v, -1e9, 1e9)); };
  return PixelRect{whole_pixel(std::floor(x0) - 1.0), whole_pixel(std::floor(y0) - 1.0),
                   whole_pixel(std::ceil(x1) + 1.0), whole_pixel(std::ceil(y1) + 1.0)}
      .intersect(whole);
}

FilterImage to_filter_image(const Image& image) {
  FilterImage out(image.width(), image.height());
  static const std::array<float, 256> kLevels = [] {
    std::array<float, 256> levels{};
    for (int i = 0; i < 256; ++i) levels[static_cast<std::size_t>(i)] = static_cast<float>(i) / 255.0f;
    return levels;
  }();
  // Only pixels with alpha are written (the rest are the image's zeros), and their bounding box is the
  // image's extent: what the filter graph computes on.
  PixelRect ink;
  const PixelVector& pixels = image.pixels();
  const int w = image.width();
  for (int y = 0; y < image.height(); ++y) {
    const Rgba8* row = pixels.data() + static_cast<std::size_t>(y) * w;
    float* target = out.pixel(0, y);
    int first = w, last = -1;
    for (int x = 0; x < w; ++x) {
      const Rgba8 p = row[x];
      if (p.a == 0) continue;
      first = std::min(first, x);
      last = x;
      float* t = target + 4 * x;
      t[0] = kLevels[p.r];
      t[1] = kLevels[p.g];
      t[2] = kLevels[p.b];
      t[3] = kLevels[p.a];
    }
    if (last >= 0) ink = ink.unite(PixelRect{first, y, last + 1, y + 1});
  }
  out.extent = ink;
  return out;
}

Image to_image(const FilterImage& image, ColorSpace space) {
  Image out(image.width, image.height);
  PixelVector& pixels = out.pixels();
  // Outside the extent every pixel is transparent, as the new image already is. Each channel is
  // floor(v * 255 + 0.5) clamped to [0, 255] (NaN and negatives give 0), colour at most alpha: since the
  // rounding is monotonic, that is the colour clamped to alpha before rounding.
  const PixelRect r = image.extent.intersect(image.bounds());
  std::vector<float> converted(space == ColorSpace::kSrgb ? 0 : 4 * static_cast<std::size_t>(r.width()));
  for (int y = r.y0; y < r.y1; ++y) {
    const float* p = image.pixel(r.x0, y);
    if (!converted.empty()) {
      // The row in sRGB, while it is in the cache.
      convert_pixels(p, converted.data(), r.width(), space, ColorSpace::kSrgb);
      p = converted.data();
    }
    Rgba8* target = pixels.data() + static_cast<std::size_t>(y) * image.width + r.x0;
    int x = r.x0;
#if defined(__SSE2__)
    const __m128 scale = _mm_set1_ps(255.0f), half = _mm_set1_ps(0.5f), zero = _mm_setzero_ps(),
                 top = _mm_set1_ps(255.0f);
    for (; x + 2 <= r.x1; x += 2, p += 8, target += 2) {
      // max(v, 0) with v first gives 0 for NaN; then colour <= alpha; truncation of a non-negative value
      // is floor.
      __m128 a = _mm_max_ps(_mm_loadu_ps(p), zero), b = _mm_max_ps(_mm_loadu_ps(p + 4), zero);
      a = _mm_min_ps(a, _mm_shuffle_ps(a, a, _MM_SHUFFLE(3, 3, 3, 3)));
      b = _mm_min_ps(b, _mm_shuffle_ps(b, b, _MM_SHUFFLE(3, 3, 3, 3)));
      a = _mm_min_ps(_mm_add_ps(_mm_mul_ps(a, scale), half), top);
      b = _mm_min_ps(_mm_add_ps(_mm_mul_ps(b, scale), half), top);
      const __m128i words = _mm_packs_epi32(_mm_cvttps_epi32(a), _mm_cvttps_epi32(b));
      _mm_storel_epi64(reinterpret_cast<__m128i*>(target), _mm_packus_epi16(words, words));
    }
#endif
    // The remaining pixel (or every pixel without SSE2), the same arithmetic.
    for (; x < r.x1; ++x, p += 4, ++target) {
      const auto positive = [](float v) { return v > 0.0f ? v : 0.0f; };  // NaN -> 0
      const auto level = [](float v) {
        return static_cast<std::uint8_t>(std::min(255.0f, v * 255.0f + 0.5f));
      };
      const float alpha = positive(p[3]);
      *target = Rgba8{level(std::min(positive(p[0]), alpha)), level(std::min(positive(p[1]), alpha)),
                      level(std::min(positive(p[2]), alpha)), level(alpha)};
    }
  }
  return out;
}

}  // namespace curvescan::svg::detail::filter
