// Image comparison: metrics, per-pixel metrics, anti-aliasing detection, ignore regions, diff image
// (contract in image_diff.h).
//
// The perceptual metric and the anti-aliasing detector follow pixelmatch (mapbox/pixelmatch, index.js,
// ISC licence; re-derived here, not copied):
// - colorDelta: both pixels are blended over white, converted to YIQ (NTSC) and their difference is
//   weighted 0.5053·ΔY² + 0.299·ΔI² + 0.1957·ΔQ² (Kotsarenko and Ramos 2010). The largest value, black
//   against white, is 35215, so the user's threshold t in [0, 1] becomes the bound 35215·t².
// - Blending a straight colour c with alpha α over white gives 255 + (c − 255)·α. With our premultiplied
//   bytes c_p = c·α this is exactly c_p + (255 − a): no unpremultiplication, no extra rounding.
// - antialiased(): a pixel is anti-aliasing when it has at most two equal neighbours among its 8 (a pixel
//   on the image border counts one extra equal neighbour, as pixelmatch does), has both a darker and a
//   brighter neighbour by the luma difference, and the darkest or the brightest of them has three or
//   more equal neighbours ("is flat") in both images. The detector runs on A against B and on B
//   against A; either classes the pixel as AA.
// - The diff image draws each pixel of A as the grey 255 + (Y − 255)·0.1·α over white, Y the luma of the
//   straight colour; with premultiplied bytes this is 255 − 0.1·(a − Y(c_p)) since Y is linear.
#include "curvescan/diff/image_diff.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>

namespace curvescan {
namespace {

/// Squared YIQ distance of black against white: the scale of pixelmatch's threshold.
constexpr double kMaxYiqDelta = 35215.0;
/// pixelmatch's `alpha` option: how strongly A shows through the diff image (0 = white, 1 = full grey).
constexpr double kDiffImageFade = 0.1;
constexpr Rgba8 kDifferentColour{255, 0, 0, 255};
constexpr Rgba8 kAntialiasedColour{255, 255, 0, 255};

/// All fully transparent pixels are one pixel (image_diff.h, conventions).
constexpr Rgba8 canonical(Rgba8 p) noexcept {
  return p.a == 0 ? Rgba8{} : p;
}

struct Rgb {
  double r, g, b;
};

constexpr Rgb over_white(Rgba8 p) noexcept {
  const double uncovered = 255.0 - p.a;
  return {p.r + uncovered, p.g + uncovered, p.b + uncovered};
}

// The YIQ coefficients pixelmatch uses (NTSC 1953 matrix, as in Kotsarenko and Ramos 2010).
constexpr double luma(Rgb c) noexcept {
  return c.r * 0.29889531 + c.g * 0.58662247 + c.b * 0.11448223;
}
constexpr double in_phase(Rgb c) noexcept {
  return c.r * 0.59597799 - c.g * 0.27417610 - c.b * 0.32180189;
}
constexpr double quadrature(Rgb c) noexcept {
  return c.r * 0.21147017 - c.g * 0.52261711 + c.b * 0.31114694;
}

/// pixelmatch's colorDelta(..., yOnly = true): luma of a minus luma of b, both over white.
double luma_delta(Rgba8 a, Rgba8 b) noexcept {
  a = canonical(a);
  b = canonical(b);
  if (a == b) return 0.0;
  return luma(over_white(a)) - luma(over_white(b));
}

/// pixelmatch's hasManySiblings: three or more of the 8 neighbours equal the pixel (border counts one).
bool has_many_equal_neighbours(const Image& image, int x, int y) noexcept {
  const int x0 = std::max(x - 1, 0), y0 = std::max(y - 1, 0);
  const int x2 = std::min(x + 1, image.width() - 1), y2 = std::min(y + 1, image.height() - 1);
  const Rgba8 centre = canonical(image.at(x, y));
  int equal = (x == x0 || x == x2 || y == y0 || y == y2) ? 1 : 0;
  for (int nx = x0; nx <= x2; ++nx) {
    for (int ny = y0; ny <= y2; ++ny) {
      if (nx == x && ny == y) continue;
      if (canonical(image.at(nx, ny)) == centre) ++equal;
      if (equal > 2) return true;
    }
  }
  return false;
}

std::uint8_t to_byte(double value) noexcept {
  return static_cast<std::uint8_t>(std::clamp(std::lround(value), 0L, 255L));
}

Rgba8 faded_grey(Rgba8 p) noexcept {
  const double grey =
      255.0 - kDiffImageFade * (p.a - luma({static_cast<double>(p.r), static_cast<double>(p.g),
                                            static_cast<double>(p.b)}));
  const std::uint8_t v = to_byte(grey);
  return {v, v, v, 255};
}

/// Ignored pixels keep A's faded grey, tinted blue so the region stays visible.
Rgba8 ignored_tint(Rgba8 p) noexcept {
  const double grey = faded_grey(p).r;
  return {to_byte(grey * 0.80), to_byte(grey * 0.88), 255, 255};
}

/// One byte per pixel, 1 inside some ignore region; empty when there are no regions.
std::vector<std::uint8_t> ignore_mask(const std::vector<PixelBox>& regions, int width, int height) {
  std::vector<std::uint8_t> mask;
  if (regions.empty()) return mask;
  mask.assign(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0);
  for (const PixelBox& region : regions) {
    // 64-bit ends: x + width may overflow int for a region given as "2000000000,0,2000000000,1".
    const std::int64_t x0 = std::max<std::int64_t>(region.x, 0);
    const std::int64_t y0 = std::max<std::int64_t>(region.y, 0);
    const std::int64_t x1 = std::min<std::int64_t>(std::int64_t{region.x} + region.width, width);
    const std::int64_t y1 = std::min<std::int64_t>(std::int64_t{region.y} + region.height, height);
    for (std::int64_t y = y0; y < y1; ++y) {
      for (std::int64_t x = x0; x < x1; ++x) mask[static_cast<std::size_t>(y * width + x)] = 1;
    }
  }
  return mask;
}

bool within_tolerance(const DiffMetrics& m, const DiffOptions& options) noexcept {
  if (options.max_different_pixels || options.max_different_percent) {
    if (options.max_different_pixels && m.different_pixels > *options.max_different_pixels) return false;
    if (options.max_different_percent && m.different_percent > *options.max_different_percent) return false;
    return true;
  }
  return m.different_pixels == 0;
}

}  // namespace

Status validate_diff_options(const DiffOptions& options) {
  if (!(options.yiq_threshold >= 0.0 && options.yiq_threshold <= 1.0)) {
    return Status::invalid("the perceptual threshold must be a number in [0, 1] (pixelmatch's scale)");
  }
  if (options.channel_tolerance < 0 || options.channel_tolerance > 255) {
    return Status::invalid("the per-channel tolerance must be an integer in [0, 255]");
  }
  if (options.max_different_percent &&
      !(*options.max_different_percent >= 0.0 && *options.max_different_percent <= 100.0)) {
    return Status::invalid("the largest percentage of differing pixels must be a number in [0, 100]");
  }
  for (const PixelBox& region : options.ignore_regions) {
    if (region.width < 0 || region.height < 0) {
      return Status::invalid("an ignore region has a negative width or height");
    }
  }
  if (options.region_gap < 0 || options.region_gap > 64) {
    return Status::invalid("the region gap must be an integer in [0, 64] pixels");
  }
  if (options.max_regions > 10000) {
    return Status::invalid("the number of listed regions must be an integer in [0, 10000]");
  }
  return Status::ok();
}

double perceptual_delta(Rgba8 a, Rgba8 b) noexcept {
  a = canonical(a);
  b = canonical(b);
  if (a == b) return 0.0;
  const Rgb ca = over_white(a), cb = over_white(b);
  const double ya = luma(ca), yb = luma(cb);
  const double dy = ya - yb, di = in_phase(ca) - in_phase(cb), dq = quadrature(ca) - quadrature(cb);
  const double delta = 0.5053 * dy * dy + 0.299 * di * di + 0.1957 * dq * dq;
  return ya > yb ? -delta : delta;
}

bool is_antialiased_pixel(const Image& image, const Image& other, int x, int y) noexcept {
  const int x0 = std::max(x - 1, 0), y0 = std::max(y - 1, 0);
  const int x2 = std::min(x + 1, image.width() - 1), y2 = std::min(y + 1, image.height() - 1);
  const Rgba8 centre = image.at(x, y);
  int equal = (x == x0 || x == x2 || y == y0 || y == y2) ? 1 : 0;
  double darkest = 0.0, brightest = 0.0;
  int darkest_x = 0, darkest_y = 0, brightest_x = 0, brightest_y = 0;
  // Same visiting order as pixelmatch (x outer, y inner), so ties pick the same neighbour.
  for (int nx = x0; nx <= x2; ++nx) {
    for (int ny = y0; ny <= y2; ++ny) {
      if (nx == x && ny == y) continue;
      const double delta = luma_delta(centre, image.at(nx, ny));
      if (delta == 0.0) {
        if (++equal > 2) return false;  // three equal neighbours: inside a flat area, not an edge
      } else if (delta < darkest) {
        darkest = delta;
        darkest_x = nx;
        darkest_y = ny;
      } else if (delta > brightest) {
        brightest = delta;
        brightest_x = nx;
        brightest_y = ny;
      }
    }
  }
  if (darkest == 0.0 || brightest == 0.0) return false;  // not between a darker and a brighter neighbour
  return (has_many_equal_neighbours(image, darkest_x, darkest_y) &&
          has_many_equal_neighbours(other, darkest_x, darkest_y)) ||
         (has_many_equal_neighbours(image, brightest_x, brightest_y) &&
          has_many_equal_neighbours(other, brightest_x, brightest_y));
}

Result<ImageComparison> compare_images(const Image& expected, const Image& actual,
                                       const DiffOptions& options) {
  CURVESCAN_PROPAGATE(validate_diff_options(options));
  ImageComparison out;
  DiffMetrics& m = out.metrics;
  m.expected_width = expected.width();
  m.expected_height = expected.height();
  m.actual_width = actual.width();
  m.actual_height = actual.height();
  if (expected.width() != actual.width() || expected.height() != actual.height()) {
    out.verdict = DiffVerdict::kSizeMismatch;
    return out;
  }

  const int width = expected.width(), height = expected.height();
  m.total_pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  const std::vector<std::uint8_t> ignored = ignore_mask(options.ignore_regions, width, height);
  const double max_delta = kMaxYiqDelta * options.yiq_threshold * options.yiq_threshold;
  if (options.make_diff_image) out.diff_image = Image(width, height);

  // Sums of |Δ| and Δ² fit exactly in 64 bits: at most 4·2^26 samples of at most 255² each (limits.h).
  std::uint64_t sum_abs = 0, sum_squares = 0;
  int min_x = width, min_y = height, max_x = -1, max_y = -1;
  // The largest channel |Δ| of each differing pixel, for the regions; allocated at the first one.
  std::vector<std::uint8_t> differing_deltas;
  for (int y = 0; y < height; ++y) {
    const Rgba8* row_a = expected.row(y);
    const Rgba8* row_b = actual.row(y);
    Rgba8* row_out = options.make_diff_image ? out.diff_image.row(y) : nullptr;
    // Fast path for the common case of a regression run, equal rows: bytewise equal pixels are canonically
    // equal and add nothing to the sums. Taken only when there is nothing to draw or mask; the per-pixel
    // loop below is the reference it must agree with (tested: metrics with and without the diff image).
    if (row_out == nullptr && ignored.empty() &&
        std::memcmp(row_a, row_b, sizeof(Rgba8) * static_cast<std::size_t>(width)) == 0) {
      m.compared_pixels += static_cast<std::uint64_t>(width);
      continue;
    }
    for (int x = 0; x < width; ++x) {
      const Rgba8 a = canonical(row_a[x]), b = canonical(row_b[x]);
      const std::size_t index = static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + x;
      if (!ignored.empty() && ignored[index] != 0) {
        if (row_out != nullptr) row_out[x] = ignored_tint(a);
        continue;
      }
      ++m.compared_pixels;
      Rgba8 drawn = a;  // a placeholder; every branch below sets it
      if (a == b) {
        drawn = faded_grey(a);
      } else {
        ++m.changed_pixels;
        const int deltas[4] = {std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b),
                               std::abs(a.a - b.a)};
        int largest = 0;
        for (int d : deltas) {
          largest = std::max(largest, d);
          sum_abs += static_cast<std::uint64_t>(d);
          sum_squares += static_cast<std::uint64_t>(d * d);
        }
        m.max_channel_delta = std::max(m.max_channel_delta, largest);
        const bool differs = options.metric == PixelMetric::kPerceptual
                                 ? std::abs(perceptual_delta(a, b)) > max_delta
                                 : largest > options.channel_tolerance;
        if (!differs) {
          drawn = faded_grey(a);
        } else if (options.ignore_antialiasing && (is_antialiased_pixel(expected, actual, x, y) ||
                                                   is_antialiased_pixel(actual, expected, x, y))) {
          ++m.antialiased_pixels;
          drawn = kAntialiasedColour;
        } else {
          ++m.different_pixels;
          drawn = kDifferentColour;
          if (differing_deltas.empty()) differing_deltas.assign(m.total_pixels, 0);
          differing_deltas[index] = static_cast<std::uint8_t>(largest);  // >= 1: the pixels differ
          min_x = std::min(min_x, x);
          max_x = std::max(max_x, x);
          min_y = std::min(min_y, y);
          max_y = std::max(max_y, y);
        }
      }
      if (row_out != nullptr) row_out[x] = drawn;
    }
  }

  const double samples = 4.0 * static_cast<double>(m.compared_pixels);
  if (samples > 0) {
    m.mean_channel_delta = static_cast<double>(sum_abs) / samples;
    m.rmse = std::sqrt(static_cast<double>(sum_squares) / samples);
  }
  m.psnr = m.rmse > 0.0 ? 20.0 * std::log10(255.0 / m.rmse) : std::numeric_limits<double>::infinity();
  m.different_percent = m.total_pixels > 0 ? 100.0 * static_cast<double>(m.different_pixels) /
                                                 static_cast<double>(m.total_pixels)
                                           : 0.0;
  if (max_x >= 0) m.difference_bounds = {min_x, min_y, max_x - min_x + 1, max_y - min_y + 1};
  if (!differing_deltas.empty()) {
    out.regions = find_difference_regions(differing_deltas, width, height, options.region_gap,
                                          options.max_regions, m.region_count);
  }
  out.verdict = within_tolerance(m, options) ? DiffVerdict::kSame : DiffVerdict::kDifferent;
  return out;
}

}  // namespace curvescan
