// feGaussianBlur (Filter Effects 1, 9.13) against independent oracles: a direct 2-D convolution with the
// sampled Gaussian for σ < 2, and the spec's three box blurs computed by plain summation for σ >= 2.
// Both oracles sum every tap in double precision; the fast blur uses float channels and prefix sums in
// double, so the two agree to float rounding: 1e-5 on values in [0, 1] (a float has 24 bits, 6e-8 relative,
// and at most a few hundred additions per value stay far below 1e-5).
#include <catch2/catch.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "svg/filter/gaussian_blur.h"

using namespace curvescan::svg::detail::filter;

namespace {

constexpr double kFloatTolerance = 1e-5;

FilterImage random_image(int w, int h, unsigned seed) {
  FilterImage image(w, h);
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      float* p = image.pixel(x, y);
      p[3] = unit(random);
      for (int c = 0; c < 3; ++c) p[c] = unit(random) * p[3];
    }
  }
  return image;
}

double max_difference(const FilterImage& a, const FilterImage& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < a.rgba.size(); ++i)
    worst = std::max(worst, std::fabs(double(a.rgba[i]) - b.rgba[i]));
  return worst;
}

// Reads `in` at (x, y) inside `r` under the edge mode, channel c.
double sample(const FilterImage& in, PixelRect r, long long x, long long y, int c, EdgeMode mode) {
  const auto fold = [&](long long v, long long lo, long long n) -> long long {
    const long long i = v - lo;
    if (i >= 0 && i < n) return v;
    if (mode == EdgeMode::kNone) return -1;
    if (mode == EdgeMode::kDuplicate) return i < 0 ? lo : lo + n - 1;
    return lo + ((i % n) + n) % n;
  };
  const long long sx = fold(x, r.x0, r.width()), sy = fold(y, r.y0, r.height());
  if (sx < 0 || sy < 0) return 0.0;
  return in.pixel(int(sx), int(sy))[c];
}

// σ < 2: out(x, y) = Σ g(i) g(j) in(x + i, y + j), g the normalized sampled Gaussian over ±ceil(3σ).
FilterImage direct_gaussian(const FilterImage& in, PixelRect r, double sx, double sy, EdgeMode mode) {
  const auto kernel = [](double sigma) {
    std::vector<double> k;
    if (!(sigma > 0.0)) return std::vector<double>{1.0};
    const int radius = int(std::ceil(3.0 * sigma));
    double total = 0.0;
    for (int i = -radius; i <= radius; ++i) {
      k.push_back(std::exp(-i * i / (2 * sigma * sigma)));
      total += k.back();
    }
    for (double& v : k) v /= total;
    return k;
  };
  const std::vector<double> kx = kernel(sx), ky = kernel(sy);
  const int rx = int(kx.size() / 2), ry = int(ky.size() / 2);
  FilterImage out(in.width, in.height);
  // Separable edge modes (duplicate, wrap) are applied per pass, as the blur is defined per axis.
  FilterImage horizontal(in.width, in.height);
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x)
      for (int c = 0; c < 4; ++c) {
        double sum = 0.0;
        for (int i = -rx; i <= rx; ++i) sum += kx[size_t(i + rx)] * sample(in, r, x + i, y, c, mode);
        horizontal.pixel(x, y)[c] = float(sum);
      }
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x)
      for (int c = 0; c < 4; ++c) {
        double sum = 0.0;
        for (int j = -ry; j <= ry; ++j) sum += ky[size_t(j + ry)] * sample(horizontal, r, x, y + j, c, mode);
        out.pixel(x, y)[c] = float(sum);
      }
  return out;
}

// One box along x (axis 0) or y (axis 1): mean of in[i - left .. i + right], summed tap by tap.
FilterImage naive_box(const FilterImage& in, PixelRect r, int axis, long long left, long long right,
                      EdgeMode mode) {
  FilterImage out(in.width, in.height);
  for (int y = r.y0; y < r.y1; ++y)
    for (int x = r.x0; x < r.x1; ++x)
      for (int c = 0; c < 4; ++c) {
        double sum = 0.0;
        for (long long k = -left; k <= right; ++k)
          sum += axis == 0 ? sample(in, r, x + k, y, c, mode) : sample(in, r, x, y + k, c, mode);
        out.pixel(x, y)[c] = float(sum / double(left + right + 1));
      }
  return out;
}

// σ >= 2: the spec's three boxes of d = floor(σ·3·sqrt(2π)/4 + 0.5), written from its prose.
FilterImage three_boxes(FilterImage image, PixelRect r, int axis, double sigma, EdgeMode mode) {
  const auto d =
      static_cast<long long>(std::floor(sigma * 3.0 * std::sqrt(2.0 * std::numbers::pi) / 4.0 + 0.5));
  if (d % 2 == 1) {
    for (int i = 0; i < 3; ++i) image = naive_box(image, r, axis, d / 2, d / 2, mode);
  } else {
    image = naive_box(image, r, axis, d / 2, d / 2 - 1, mode);  // centred left of the pixel
    image = naive_box(image, r, axis, d / 2 - 1, d / 2, mode);  // centred right of it
    image = naive_box(image, r, axis, d / 2, d / 2, mode);      // d + 1, centred
  }
  return image;
}

}  // namespace

TEST_CASE("feGaussianBlur: small σ is the exact sampled Gaussian", "[svg][filter][blur]") {
  const FilterImage in = random_image(23, 17, 1);
  const PixelRect all = in.bounds();
  for (const double sigma : {0.3, 0.8, 1.0, 1.7, 1.99}) {
    for (const EdgeMode mode : {EdgeMode::kNone, EdgeMode::kDuplicate, EdgeMode::kWrap}) {
      FilterImage out(in.width, in.height);
      gaussian_blur(in, all, sigma, sigma * 0.7, mode, out);
      INFO("sigma " << sigma << " mode " << int(mode));
      CHECK(max_difference(out, direct_gaussian(in, all, sigma, sigma * 0.7, mode)) < kFloatTolerance);
    }
  }
}

TEST_CASE("feGaussianBlur: σ >= 2 is the specification's three box blurs, odd and even d",
          "[svg][filter][blur]") {
  const FilterImage in = random_image(41, 29, 2);
  const PixelRect all = in.bounds();
  // d = 3 (σ 2.0), 4 (σ 2.5, even), 7 (σ 4.4), 10 (σ 6.5, even), 50 (σ 33, wider than the image).
  for (const double sigma : {2.0, 2.5, 4.4, 6.5, 33.0}) {
    for (const EdgeMode mode : {EdgeMode::kNone, EdgeMode::kDuplicate, EdgeMode::kWrap}) {
      FilterImage out(in.width, in.height);
      gaussian_blur(in, all, sigma, sigma, mode, out);
      const FilterImage expected = three_boxes(three_boxes(in, all, 0, sigma, mode), all, 1, sigma, mode);
      INFO("sigma " << sigma << " mode " << int(mode));
      CHECK(max_difference(out, expected) < kFloatTolerance);
    }
  }
  CHECK(box_blur_size(2.0) == 4);  // floor(2 · 1.87997 + 0.5) = floor(4.26) = 4
  CHECK(box_blur_size(10.0) == 19);
}

TEST_CASE("feGaussianBlur: the three boxes have the variance their sizes give, and the Gaussian's shape",
          "[svg][filter][blur]") {
  // A single opaque pixel blurred with σ = 6: d = floor(6 · 1.87997 + 0.5) = 11, odd, so each axis is three
  // centred boxes of 11, whose variances add: 3 · (11² - 1) / 12 = 30 (σ_eff = 5.48; the approximation's
  // known bias, which the specification accepts). The total stays 1 and the second moment is 30 on each
  // axis, to float rounding over 3721 values (1e-3 relative).
  FilterImage in(61, 61);
  in.pixel(30, 30)[3] = 1.0f;
  FilterImage out(61, 61);
  gaussian_blur(in, in.bounds(), 6.0, 6.0, EdgeMode::kNone, out);
  double total = 0.0, moment_x = 0.0, moment_y = 0.0, worst = 0.0;
  const double variance = 30.0, peak = 1.0 / (2.0 * std::numbers::pi * variance);
  for (int y = 0; y < 61; ++y)
    for (int x = 0; x < 61; ++x) {
      const double v = out.pixel(x, y)[3], dx = x - 30, dy = y - 30;
      total += v;
      moment_x += v * dx * dx;
      moment_y += v * dy * dy;
      // Against the Gaussian of the same variance. Three boxes peak lower: in 1-D the centre is 91 / 11³ =
      // 0.0684 (triples in [-5, 5] summing to 0) against 1 / sqrt(2π·30) = 0.0728, so 0.94² = 0.88 of the
      // Gaussian's peak in 2-D, 12 % off; 15 % bounds it, and anything like a wrong box size fails.
      worst = std::max(worst, std::fabs(v - peak * std::exp(-(dx * dx + dy * dy) / (2.0 * variance))));
    }
  CHECK(total == Approx(1.0).epsilon(1e-4));
  CHECK(moment_x == Approx(variance).epsilon(1e-3));
  CHECK(moment_y == Approx(variance).epsilon(1e-3));
  CHECK(worst < 0.15 * peak);
  CHECK(out.pixel(30, 30)[3] == Approx((91.0 / 1331.0) * (91.0 / 1331.0)).epsilon(1e-4));
}

TEST_CASE("feGaussianBlur: only the subregion is read and written — huge σ is bounded",
          "[svg][filter][blur]") {
  FilterImage in(20, 20);
  for (float& v : in.rgba) v = 1.0f;
  FilterImage out(20, 20);
  const PixelRect sub{5, 5, 15, 15};
  gaussian_blur(in, sub, 1e12, 3.0, EdgeMode::kNone, out);  // must return promptly
  CHECK(out.pixel(2, 2)[3] == 0.0f);                        // outside: untouched
  CHECK(out.pixel(10, 10)[3] >= 0.0f);
  CHECK(out.pixel(10, 10)[3] < 1e-6f);  // a box wider than anything averages the 10 pixels over 1e12
  // duplicate keeps a constant image constant whatever σ.
  FilterImage kept(20, 20);
  gaussian_blur(in, sub, 1e9, 50.0, EdgeMode::kDuplicate, kept);
  CHECK(kept.pixel(10, 10)[3] == Approx(1.0f).margin(1e-5));
}

TEST_CASE("feGaussianBlur: duplicate and wrap in a subregion, boxes many times the line, written part only",
          "[svg][filter][blur]") {
  // The subregion is the blur's whole input image: the edge modes fold at its edges, not the image's. σ 150
  // gives d = 282, a box some twenty times the 13-pixel line, whose first window is summed in closed form.
  const FilterImage in = random_image(19, 15, 3);
  const PixelRect sub{3, 2, 16, 13};
  for (const double sigma : {0.9, 2.5, 6.5, 150.0}) {
    for (const EdgeMode mode : {EdgeMode::kNone, EdgeMode::kDuplicate, EdgeMode::kWrap}) {
      FilterImage out(in.width, in.height);
      gaussian_blur(in, sub, sigma, sigma * 1.3, mode, out);
      const FilterImage expected =
          sigma < 2.0 ? direct_gaussian(in, sub, sigma, sigma * 1.3, mode)
                      : three_boxes(three_boxes(in, sub, 0, sigma, mode), sub, 1, sigma * 1.3, mode);
      INFO("sigma " << sigma << " mode " << int(mode));
      CHECK(max_difference(out, expected) < kFloatTolerance);
      // With `written`, only that part of the subregion is written, with the same values.
      const PixelRect part{5, 4, 9, 12};
      FilterImage some(in.width, in.height);
      gaussian_blur(in, sub, sigma, sigma * 1.3, mode, some, false, part);
      double worst = 0.0;
      bool outside_zero = true;
      for (int y = 0; y < in.height; ++y)
        for (int x = 0; x < in.width; ++x)
          for (int c = 0; c < 4; ++c) {
            if (part.contains(x, y)) {
              worst = std::max(worst, std::fabs(double(some.pixel(x, y)[c]) - expected.pixel(x, y)[c]));
            } else {
              outside_zero = outside_zero && some.pixel(x, y)[c] == 0.0f;
            }
          }
      CHECK(worst < kFloatTolerance);
      CHECK(outside_zero);
    }
  }
}

TEST_CASE("feGaussianBlur: a huge σ with duplicate or wrap makes each line one value",
          "[svg][filter][blur]") {
  // From the definition: a box of width d >> n over a periodic line holds ~d / n periods, so every pixel is
  // the line's mean (wrap); over a line extended by copies of its ends it holds ~d / 2 copies of each end,
  // so every pixel is the mean of the two end samples (duplicate). The difference is at most 2n / d,
  // 1e-20 for σ 1e22 over these 13 pixels: the float tolerance covers it.
  const FilterImage in = random_image(19, 15, 4);
  const PixelRect sub{3, 2, 16, 13};
  const auto mean_of = [&](PixelRect r, int c) {
    double total = 0.0;
    for (int y = r.y0; y < r.y1; ++y)
      for (int x = r.x0; x < r.x1; ++x) total += in.pixel(x, y)[c];
    return total / (double(r.width()) * r.height());
  };
  FilterImage wrap(in.width, in.height), duplicate(in.width, in.height);
  gaussian_blur(in, sub, 1e22, 1e22, EdgeMode::kWrap, wrap);
  gaussian_blur(in, sub, 1e22, 1e22, EdgeMode::kDuplicate, duplicate);
  for (int c = 0; c < 4; ++c) {
    const double corners =
        (double(in.pixel(3, 2)[c]) + in.pixel(15, 2)[c] + in.pixel(3, 12)[c] + in.pixel(15, 12)[c]) / 4.0;
    for (const auto& [x, y] : {std::pair{3, 2}, std::pair{9, 7}, std::pair{15, 12}}) {
      CHECK(wrap.pixel(x, y)[c] == Approx(mean_of(sub, c)).margin(kFloatTolerance));
      CHECK(duplicate.pixel(x, y)[c] == Approx(corners).margin(kFloatTolerance));
    }
  }
  CHECK(wrap.pixel(1, 1)[3] == 0.0f);  // outside the subregion: untouched
  // One axis huge, the other small or moderate: each row (or column) collapses, and the other axis is the
  // ordinary blur of the collapsed line. σ 1e9 gives d = 1.9e9, past 2^26 · 13: the collapsing path,
  // checked against the plain implementation's exact window sums (which take every box in full).
  for (const EdgeMode mode : {EdgeMode::kDuplicate, EdgeMode::kWrap}) {
    for (const auto& [sx, sy] : {std::pair{1e9, 1.5}, std::pair{1e9, 4.5}, std::pair{0.7, 1e9},
                                 std::pair{6.0, 1e9}, std::pair{1e9, 0.0}}) {
      FilterImage fast(in.width, in.height), plain(in.width, in.height);
      gaussian_blur(in, sub, sx, sy, mode, fast);
      gaussian_blur_reference(in, sub, sx, sy, mode, plain);
      INFO("mode " << int(mode) << " sigma " << sx << " " << sy);
      CHECK(max_difference(fast, plain) < kFloatTolerance);
    }
  }
  // SourceAlpha read from SourceGraphic (alpha_only): the colour channels are zero.
  FilterImage alpha(in.width, in.height);
  gaussian_blur(in, sub, 1e22, 1e22, EdgeMode::kWrap, alpha, true);
  CHECK(alpha.pixel(9, 7)[0] == 0.0f);
  CHECK(alpha.pixel(9, 7)[3] == Approx(mean_of(sub, 3)).margin(kFloatTolerance));
}
