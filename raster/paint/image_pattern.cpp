// Image paints (image_pattern.h): the factory and the sampler.
#include "curvescan/raster/image_pattern.h"

#include <algorithm>
#include <cmath>

#include "curvescan/raster/layer.h"
#include "curvescan/raster/mask.h"

namespace curvescan {
namespace {

// Index `i` wrapped into [0, n) for repeat, clamped for pad; -1 (outside, transparent) for none.
int wrap(long long i, int n, PatternExtend extend) noexcept {
  if (extend == PatternExtend::kRepeat) {
    const long long m = i % n;
    return static_cast<int>(m < 0 ? m + n : m);
  }
  if (extend == PatternExtend::kPad) return static_cast<int>(std::clamp<long long>(i, 0, n - 1));
  return i >= 0 && i < n ? static_cast<int>(i) : -1;
}

}  // namespace

Rgba8 ImagePattern::sample(Point p) const noexcept {
  const int w = image.width(), h = image.height();
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::abs(p.x) > 1e15 || std::abs(p.y) > 1e15)
    return Rgba8{};
  const auto at = [&](long long x, long long y) -> Rgba8 {
    const int i = wrap(x, w, extend), j = wrap(y, h, extend);
    return i < 0 || j < 0 ? Rgba8{} : image.at(i, j);
  };
  if (filter == PatternFilter::kNearest) {
    return at(static_cast<long long>(std::floor(p.x)), static_cast<long long>(std::floor(p.y)));
  }
  // Pixel centres are at i + 0.5: the four around p, with weights (1 - fx, fx) x (1 - fy, fy).
  const double u = p.x - 0.5, v = p.y - 0.5;
  const double x0 = std::floor(u), y0 = std::floor(v);
  const double fx = u - x0, fy = v - y0;
  const auto ix = static_cast<long long>(x0), iy = static_cast<long long>(y0);
  const Rgba8 c00 = at(ix, iy), c10 = at(ix + 1, iy), c01 = at(ix, iy + 1), c11 = at(ix + 1, iy + 1);
  const auto mix = [&](std::uint8_t a, std::uint8_t b, std::uint8_t c, std::uint8_t d) {
    const double top = a + (b - a) * fx, bottom = c + (d - c) * fx;
    return static_cast<std::uint8_t>(std::floor(top + (bottom - top) * fy + 0.5));
  };
  return Rgba8{mix(c00.r, c10.r, c01.r, c11.r), mix(c00.g, c10.g, c01.g, c11.g),
               mix(c00.b, c10.b, c01.b, c11.b), mix(c00.a, c10.a, c01.a, c11.a)};
}

Paint image_pattern_paint(Image image, const Affine& image_to_user, PatternExtend extend,
                          PatternFilter filter, double opacity) {
  const std::uint8_t alpha = layer_alpha(opacity);
  if (image.empty() || alpha == 0 || !image_to_user.is_finite() || !image_to_user.inverse())
    return Paint::none();
  Paint paint = Paint::none();
  paint.pattern = std::make_shared<const ImagePattern>(
      ImagePattern{std::move(image), image_to_user, extend, filter, alpha});
  return paint;
}

}  // namespace curvescan
