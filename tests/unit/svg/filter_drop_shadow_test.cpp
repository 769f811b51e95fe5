// feDropShadow and drop-shadow() (Filter Effects 1, 9.11 and 13) against an independent oracle: the
// specification's chain written out plainly -- the input's alpha blurred (a direct 2-D convolution with the
// sampled Gaussian for σ < 2, the three box blurs by plain summation for σ >= 2, 9.13), moved by the whole
// pixel offset, flood colour "in" it, the input merged over it -- and the computation of only the needed
// pixels, which a huge stdDeviation over a huge region relies on to cost what the canvas costs.
//
// Tolerance 1e-5: the oracle sums every tap in double precision, the blur under test uses float channels
// with double prefix sums; a float has 24 bits (6e-8 relative) and a few hundred additions per value stay
// far below 1e-5 on values in [0, 1].
#include <catch2/catch.hpp>
#include <cmath>
#include <vector>

#include "filter_kernel_support.h"
#include "svg/filter/drop_shadow.h"
#include "svg/filter/gaussian_blur.h"

using namespace curvescan::svg::detail::filter;
using curvescan::svg::testing::compare_images;
using curvescan::svg::testing::random_image;
using curvescan::svg::testing::same_inside_and_transparent_outside;

namespace {

constexpr double kFloatTolerance = 1e-5;

// One axis of the blur as weights over offsets: the sampled Gaussian for σ < 2, else the spec's three
// boxes (d = floor(σ · 3 · sqrt(2π) / 4 + 0.5); odd d: three centred boxes of d; even d: a box of d centred
// between x - 1 and x, one between x and x + 1, and one of d + 1 centred) convolved together.
std::vector<double> axis_weights(double sigma, int& radius) {
  if (!(sigma > 0.0)) {
    radius = 0;
    return {1.0};
  }
  if (sigma < 2.0) {
    radius = static_cast<int>(std::ceil(3.0 * sigma));
    std::vector<double> w(2 * radius + 1);
    double total = 0.0;
    for (int k = -radius; k <= radius; ++k)
      total += w[k + radius] = std::exp(-(k * k) / (2.0 * sigma * sigma));
    for (double& v : w) v /= total;
    return w;
  }
  const int d = static_cast<int>(std::floor(sigma * 3.0 * std::sqrt(2.0 * M_PI) / 4.0 + 0.5));
  // Each box as [from, to] offsets read by the output pixel.
  std::vector<std::pair<int, int>> boxes;
  if (d % 2 == 1) {
    boxes.assign(3, {-(d / 2), d / 2});
  } else {
    boxes = {{-(d / 2), d / 2 - 1}, {-(d / 2 - 1), d / 2}, {-(d / 2), d / 2}};
  }
  radius = 0;
  std::vector<double> w{1.0};  // weights over [-radius, radius]
  for (const auto& [from, to] : boxes) {
    const int next_radius = radius + std::max(-from, to);
    std::vector<double> next(2 * next_radius + 1, 0.0);
    for (int i = -radius; i <= radius; ++i)
      for (int k = from; k <= to; ++k) next[i + k + next_radius] += w[i + radius] / (to - from + 1);
    w = next;
    radius = next_radius;
  }
  return w;
}

// The specification's chain, every output pixel of `subregion` computed from scratch.
FilterImage oracle_drop_shadow(const FilterImage& in, const DropShadowParams& params, PixelRect subregion) {
  int rx = 0, ry = 0;
  const std::vector<double> wx = axis_weights(params.sigma_x, rx), wy = axis_weights(params.sigma_y, ry);
  const auto alpha = [&](int x, int y) { return subregion.contains(x, y) ? double(in.pixel(x, y)[3]) : 0.0; };
  // feGaussianBlur of SourceAlpha, clipped to the subregion.
  const auto blurred = [&](int x, int y) {
    if (!subregion.contains(x, y)) return 0.0;
    double sum = 0.0;
    for (int j = -ry; j <= ry; ++j)
      for (int i = -rx; i <= rx; ++i) sum += wx[i + rx] * wy[j + ry] * alpha(x + i, y + j);
    return sum;
  };
  // feOffset in whole pixels, the nearest with a half rounded down (docs/svg.md: 7.5 moves by 7).
  const int dx = static_cast<int>(std::ceil(params.dx - 0.5)),
            dy = static_cast<int>(std::ceil(params.dy - 0.5));
  FilterImage out(in.width, in.height);
  for (int y = subregion.y0; y < subregion.y1; ++y) {
    for (int x = subregion.x0; x < subregion.x1; ++x) {
      const double shadow = blurred(x - dx, y - dy);  // feOffset
      const double flood[4] = {params.color.r * params.color.a, params.color.g * params.color.a,
                               params.color.b * params.color.a, params.color.a};
      const float* source = in.pixel(x, y);
      for (int c = 0; c < 4; ++c)  // flood "in" the shadow, then the source merged over it
        out.pixel(x, y)[c] = static_cast<float>(source[c] + flood[c] * shadow * (1.0 - source[3]));
    }
  }
  return out;
}

// `image` with every pixel outside `ink` transparent, and its extent set to `ink`.
FilterImage with_ink_only_in(FilterImage image, PixelRect ink) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      if (!ink.contains(x, y)) std::fill(image.pixel(x, y), image.pixel(x, y) + 4, 0.0f);
  image.extent = ink;
  return image;
}

}  // namespace

TEST_CASE("drop_shadow is the specification's blur, offset, flood-in and merge chain",
          "[filter][drop_shadow]") {
  const PixelRect subregion{3, 2, 45, 38};
  const PixelRect ink{10, 8, 30, 26};
  const FilterImage in = with_ink_only_in(random_image(48, 40, 7), ink);
  for (const double sigma : {0.0, 0.6, 1.7, 2.0, 3.3, 5.0}) {
    for (const auto& [dx, dy] :
         std::vector<std::pair<double, double>>{{0, 0}, {4.4, -2.6}, {-7.5, 3}, {60, 0}}) {
      DropShadowParams params;
      params.sigma_x = sigma;
      params.sigma_y = sigma * 0.5;
      params.dx = dx;
      params.dy = dy;
      params.color = FilterColor{0.2f, 0.5f, 0.9f, 0.7f};
      FilterImage out(in.width, in.height);
      drop_shadow(in, params, subregion, out);
      const auto difference = compare_images(out, oracle_drop_shadow(in, params, subregion));
      INFO("sigma " << sigma << " offset " << dx << ", " << dy << ": " << difference.max_diff << " at "
                    << difference.x << ", " << difference.y << " channel " << difference.channel);
      CHECK(difference.max_diff <= kFloatTolerance);
    }
  }
}

TEST_CASE("drop_shadow computes only the needed pixels, the same values there", "[filter][drop_shadow]") {
  const PixelRect subregion{0, 0, 64, 48};
  const FilterImage in = with_ink_only_in(random_image(64, 48, 11), PixelRect{20, 10, 40, 30});
  DropShadowParams params;
  params.sigma_x = 3.0;
  params.sigma_y = 1.2;
  params.dx = 9.0;
  params.dy = -4.0;
  params.color = FilterColor{1.0f, 0.0f, 0.0f, 0.5f};
  FilterImage whole(in.width, in.height);
  drop_shadow(in, params, subregion, whole);
  // Needed rectangles over the ink, over the shadow only, across both, and outside everything.
  for (const PixelRect needed : {PixelRect{22, 12, 30, 20}, PixelRect{45, 5, 60, 20},
                                 PixelRect{0, 20, 64, 24}, PixelRect{0, 40, 10, 48}}) {
    FilterImage part(in.width, in.height);
    drop_shadow(in, params, subregion, part, needed);
    INFO("needed " << needed.x0 << ", " << needed.y0 << ", " << needed.x1 << ", " << needed.y1);
    CHECK(same_inside_and_transparent_outside(part, whole, needed));
    CHECK(part.extent.intersect(needed) == part.extent);
  }
}
