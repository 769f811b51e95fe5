// The filter image's placement (filter_surface.h).
#include "filter_surface.h"

#include <algorithm>
#include <cmath>

#include "curvescan/raster/limits.h"

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
    warning = "a filter region is beyond the pixel and memory limits; it is filtered at " +
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

FilterImage to_filter_image(const Image& image) {
  FilterImage out(image.width(), image.height());
  const std::vector<Rgba8>& pixels = image.pixels();
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    out.rgba[4 * i] = pixels[i].r / 255.0f;
    out.rgba[4 * i + 1] = pixels[i].g / 255.0f;
    out.rgba[4 * i + 2] = pixels[i].b / 255.0f;
    out.rgba[4 * i + 3] = pixels[i].a / 255.0f;
  }
  return out;
}

Image to_image(const FilterImage& image) {
  Image out(image.width, image.height);
  std::vector<Rgba8>& pixels = out.pixels();
  const auto level = [](float v) {
    return static_cast<std::uint8_t>(v > 0.0f ? std::min(255.0f, std::floor(v * 255.0f + 0.5f)) : 0.0f);
  };
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const std::uint8_t a = level(image.rgba[4 * i + 3]);
    pixels[i] = Rgba8{std::min(level(image.rgba[4 * i]), a), std::min(level(image.rgba[4 * i + 1]), a),
                      std::min(level(image.rgba[4 * i + 2]), a), a};
  }
  return out;
}

}  // namespace curvescan::svg::detail::filter
