// compare_images: metrics on synthetic pairs whose answers follow from the definitions in image_diff.h.
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "curvescan/diff/image_diff.h"
#include "diff_test_support.h"

using namespace curvescan;
using curvescan::test::filled;
using curvescan::test::paint;

namespace {

constexpr Rgba8 kWhite{255, 255, 255, 255};
constexpr Rgba8 kBlack{0, 0, 0, 255};
constexpr Rgba8 kGrey{100, 100, 100, 255};

ImageComparison compare(const Image& a, const Image& b, const DiffOptions& options = {}) {
  Result<ImageComparison> result = compare_images(a, b, options);
  REQUIRE(result.is_ok());
  return std::move(*result);
}

DiffOptions per_channel(int tolerance) {
  DiffOptions options;
  options.metric = PixelMetric::kPerChannel;
  options.channel_tolerance = tolerance;
  return options;
}

}  // namespace

TEST_CASE("identical images are the same with zero error and infinite PSNR", "[diff]") {
  Image a = filled(16, 9, kGrey);
  paint(a, 2, 2, 7, 5, Rgba8{10, 20, 30, 40});
  const ImageComparison c = compare(a, a);
  CHECK(c.verdict == DiffVerdict::kSame);
  CHECK(c.metrics.total_pixels == 16u * 9u);
  CHECK(c.metrics.compared_pixels == c.metrics.total_pixels);
  CHECK(c.metrics.changed_pixels == 0);
  CHECK(c.metrics.different_pixels == 0);
  CHECK(c.metrics.max_channel_delta == 0);
  CHECK(c.metrics.rmse == 0.0);
  CHECK(std::isinf(c.metrics.psnr));
  CHECK(c.metrics.difference_bounds.empty());
}

TEST_CASE("one pixel off by k: max, mean, RMSE, PSNR, count and box follow from the definitions", "[diff]") {
  const int width = 8, height = 8;
  const Image a = filled(width, height, kGrey);
  for (int k : {1, 7, 100}) {
    Image b = a;
    b.at(3, 5).r = static_cast<std::uint8_t>(kGrey.r + k);
    const ImageComparison c = compare(a, b, per_channel(0));
    const double samples = 4.0 * width * height;  // four channels of every pixel
    // Exact integer sums divided once: a few ulps at most, hence the 1e-12 relative margin.
    CHECK(c.metrics.max_channel_delta == k);
    CHECK(c.metrics.mean_channel_delta == Approx(k / samples).epsilon(1e-12));
    CHECK(c.metrics.rmse == Approx(std::sqrt(k * k / samples)).epsilon(1e-12));
    CHECK(c.metrics.psnr == Approx(20.0 * std::log10(255.0 / std::sqrt(k * k / samples))).epsilon(1e-12));
    CHECK(c.metrics.changed_pixels == 1);
    CHECK(c.metrics.different_pixels == 1);
    CHECK(c.metrics.different_percent == Approx(100.0 / (width * height)).epsilon(1e-12));
    CHECK(c.metrics.difference_bounds == PixelBox{3, 5, 1, 1});
    CHECK(c.verdict == DiffVerdict::kDifferent);
    // The per-channel tolerance is "more than N levels": k itself is tolerated, k - 1 is not.
    CHECK(compare(a, b, per_channel(k)).verdict == DiffVerdict::kSame);
    CHECK(compare(a, b, per_channel(k - 1)).verdict == DiffVerdict::kDifferent);
  }
}

TEST_CASE("a hard edge shifted by one column differs along that column and is not anti-aliasing", "[diff]") {
  const int width = 24, height = 20, top = 4, bottom = 16, edge = 10;
  Image a = filled(width, height, kWhite);
  Image b = a;
  paint(a, 0, top, edge, bottom, kBlack);
  paint(b, 0, top, edge + 1, bottom, kBlack);
  DiffOptions options;
  options.ignore_antialiasing = true;
  const ImageComparison c = compare(a, b, options);
  CHECK(c.metrics.different_pixels == static_cast<std::uint64_t>(bottom - top));
  CHECK(c.metrics.antialiased_pixels == 0);
  CHECK(c.metrics.difference_bounds == PixelBox{edge, top, 1, bottom - top});
  CHECK(c.metrics.max_channel_delta == 255);
}

TEST_CASE("an anti-aliased edge column that changes is anti-aliasing, counted only without --ignore-aa",
          "[diff]") {
  // A black rectangle with a partly covered column at its right edge (coverage 50% in A, 30% in B), as a
  // rasterizer draws an edge at x = 10.5 or 10.3: the column lies between flat black and flat white.
  const int width = 24, height = 20, top = 4, bottom = 16, edge = 10;
  Image a = filled(width, height, kWhite);
  paint(a, 0, top, edge, bottom, kBlack);
  Image b = a;
  paint(a, edge, top, edge + 1, bottom, Rgba8{128, 128, 128, 255});
  paint(b, edge, top, edge + 1, bottom, Rgba8{179, 179, 179, 255});
  const ImageComparison counted = compare(a, b);
  CHECK(counted.metrics.different_pixels == static_cast<std::uint64_t>(bottom - top));
  CHECK(counted.verdict == DiffVerdict::kDifferent);

  DiffOptions options;
  options.ignore_antialiasing = true;
  const ImageComparison ignored = compare(a, b, options);
  CHECK(ignored.metrics.different_pixels == 0);
  CHECK(ignored.metrics.antialiased_pixels == static_cast<std::uint64_t>(bottom - top));
  CHECK(ignored.verdict == DiffVerdict::kSame);
  CHECK(ignored.diff_image.at(edge, top) == Rgba8{255, 255, 0, 255});  // AA drawn yellow

  // A blob in a flat area is never anti-aliasing.
  Image blob = a;
  paint(blob, 18, 2, 21, 5, Rgba8{255, 0, 0, 255});
  const ImageComparison real = compare(a, blob, options);
  CHECK(real.metrics.different_pixels == 9);
  CHECK(real.diff_image.at(19, 3) == Rgba8{255, 0, 0, 255});
}

TEST_CASE("an alpha-only difference is seen by both metrics when the colour is not white", "[diff]") {
  // Straight blue (0, 0, 255) at alpha 255 and at alpha 128 (premultiplied blue 128).
  const Image a = filled(4, 4, Rgba8{0, 0, 255, 255});
  const Image b = filled(4, 4, Rgba8{0, 0, 128, 128});
  const ImageComparison perceptual = compare(a, b);
  CHECK(perceptual.metrics.different_pixels == 16);
  CHECK(perceptual.metrics.max_channel_delta == 127);
  CHECK(compare(a, b, per_channel(0)).metrics.different_pixels == 16);
}

TEST_CASE("the perceptual metric blends over white: white and transparent look the same (documented)",
          "[diff]") {
  // pixelmatch's behaviour, kept on purpose and documented in docs/diff.md: a fully covered white pixel
  // and a transparent one both show white over white. The statistics and the per-channel metric see it.
  const Image a = filled(4, 4, kWhite);
  const Image b = filled(4, 4, Rgba8{0, 0, 0, 0});
  const ImageComparison perceptual = compare(a, b);
  CHECK(perceptual.metrics.different_pixels == 0);
  CHECK(perceptual.metrics.changed_pixels == 16);
  CHECK(perceptual.metrics.max_channel_delta == 255);
  CHECK(compare(a, b, per_channel(0)).metrics.different_pixels == 16);
}

TEST_CASE("fully transparent pixels are equal whatever their colour bits", "[diff]") {
  // Colour bits under a = 0 break image.h's invariant; images from other producers can carry them.
  const Image a = filled(5, 3, Rgba8{0, 0, 0, 0});
  const Image b = filled(5, 3, Rgba8{200, 17, 99, 0});
  const ImageComparison c = compare(a, b, per_channel(0));
  CHECK(c.verdict == DiffVerdict::kSame);
  CHECK(c.metrics.changed_pixels == 0);
  CHECK(c.metrics.max_channel_delta == 0);
  CHECK(perceptual_delta(a.at(0, 0), b.at(0, 0)) == 0.0);
}

TEST_CASE("images of different sizes are a size mismatch with both sizes reported", "[diff]") {
  const ImageComparison c = compare(filled(4, 3, kGrey), filled(3, 4, kGrey));
  CHECK(c.verdict == DiffVerdict::kSizeMismatch);
  CHECK(c.metrics.expected_width == 4);
  CHECK(c.metrics.expected_height == 3);
  CHECK(c.metrics.actual_width == 3);
  CHECK(c.metrics.actual_height == 4);
  CHECK(c.diff_image.empty());
}

TEST_CASE("perceptual delta: zero for equal colours, sign by brightness, bounded by 35215", "[diff]") {
  // Black against white differs only in luma: 0.5053·255² (the I and Q coefficients sum to ~0, 1e-6).
  const double black_white = perceptual_delta(kBlack, kWhite);
  CHECK(black_white == Approx(0.5053 * 255.0 * 255.0).epsilon(1e-6));
  CHECK(perceptual_delta(kWhite, kBlack) == Approx(-black_white));  // a brighter: negative
  // A premultiplied half-covered pixel equals the opaque pixel it shows over white, exactly: 100 + 127.
  CHECK(perceptual_delta(Rgba8{100, 100, 100, 128}, Rgba8{227, 227, 227, 255}) == 0.0);

  std::mt19937 random(20261121);  // seeded: the same pairs on every run
  std::uniform_int_distribution<int> byte(0, 255);
  for (int i = 0; i < 20000; ++i) {
    const auto pixel = [&] {
      const auto a = static_cast<std::uint8_t>(byte(random));
      const auto channel = [&] { return static_cast<std::uint8_t>(byte(random) * a / 255); };
      return Rgba8{channel(), channel(), channel(), a};
    };
    const Rgba8 p = pixel(), q = pixel();
    // 35215 is pixelmatch's bound of the squared distance; 1e-9 covers the rounding of the products.
    CHECK(std::abs(perceptual_delta(p, q)) <= 35215.0 + 1e-9);
    CHECK(perceptual_delta(p, q) == Approx(-perceptual_delta(q, p)).margin(1e-9));
  }
}

TEST_CASE("the perceptual threshold is pixelmatch's: differs when delta > 35215 t^2", "[diff]") {
  const Image a = filled(3, 3, kGrey);
  const Image b = filled(3, 3, Rgba8{110, 100, 100, 255});
  const double delta = std::abs(perceptual_delta(a.at(0, 0), b.at(0, 0)));
  const double exact_threshold = std::sqrt(delta / 35215.0);
  DiffOptions options;
  options.yiq_threshold = exact_threshold * 1.01;  // 1% above the boundary: tolerated
  CHECK(compare(a, b, options).metrics.different_pixels == 0);
  options.yiq_threshold = exact_threshold * 0.99;  // 1% below: every pixel differs
  CHECK(compare(a, b, options).metrics.different_pixels == 9);
}

TEST_CASE("per-image tolerance: --max-pixels and --max-percent, both must hold when both are set", "[diff]") {
  const Image a = filled(10, 10, kGrey);
  Image b = a;
  paint(b, 0, 0, 5, 1, kBlack);  // 5 of 100 pixels
  DiffOptions options;
  options.max_different_pixels = 5;
  CHECK(compare(a, b, options).verdict == DiffVerdict::kSame);
  options.max_different_pixels = 4;
  CHECK(compare(a, b, options).verdict == DiffVerdict::kDifferent);
  options.max_different_pixels.reset();
  options.max_different_percent = 5.0;
  CHECK(compare(a, b, options).verdict == DiffVerdict::kSame);
  options.max_different_percent = 4.9;
  CHECK(compare(a, b, options).verdict == DiffVerdict::kDifferent);
  options.max_different_percent = 50.0;
  options.max_different_pixels = 1;
  CHECK(compare(a, b, options).verdict == DiffVerdict::kDifferent);
}

TEST_CASE("ignore regions are not compared and are clipped to the image", "[diff]") {
  const Image a = filled(10, 8, kGrey);
  Image b = a;
  paint(b, 6, 5, 10, 8, kBlack);  // a 4 x 3 block in the bottom-right corner
  DiffOptions options;
  options.ignore_regions.push_back({6, 5, 100, 100});  // reaches far outside: clipped to 4 x 3
  const ImageComparison c = compare(a, b, options);
  CHECK(c.verdict == DiffVerdict::kSame);
  CHECK(c.metrics.compared_pixels == 10u * 8u - 4u * 3u);
  CHECK(c.metrics.max_channel_delta == 0);
  options.ignore_regions = {{6, 5, 3, 3}};  // misses the last column
  CHECK(compare(a, b, options).metrics.different_pixels == 3);
}

TEST_CASE("the diff image is pixelmatch's faded grey of A with red differences", "[diff]") {
  const Image a = filled(4, 4, kGrey);
  Image b = a;
  b.at(1, 2) = kBlack;
  const ImageComparison c = compare(a, b);
  REQUIRE(c.diff_image.width() == 4);
  CHECK(c.diff_image.at(1, 2) == Rgba8{255, 0, 0, 255});
  // 255 + (Y − 255)·0.1 for an opaque grey Y = 100 (the coefficients sum to 1 within 1e-8): 239.5 → 240.
  const auto grey = static_cast<std::uint8_t>(std::lround(255.0 + (100.0 - 255.0) * 0.1));
  CHECK(c.diff_image.at(0, 0) == Rgba8{grey, grey, grey, 255});
  DiffOptions no_image;
  no_image.make_diff_image = false;
  CHECK(compare(a, b, no_image).diff_image.empty());
}

TEST_CASE("invalid options are refused with a message naming them, NaN included", "[diff]") {
  const Image a = filled(2, 2, kGrey);
  DiffOptions options;
  options.yiq_threshold = std::nan("");
  CHECK_FALSE(compare_images(a, a, options).is_ok());
  options = {};
  options.yiq_threshold = 1.5;
  CHECK_FALSE(compare_images(a, a, options).is_ok());
  options = {};
  options.channel_tolerance = 256;
  CHECK_FALSE(compare_images(a, a, options).is_ok());
  options = {};
  options.max_different_percent = std::nan("");
  CHECK_FALSE(compare_images(a, a, options).is_ok());
  options = {};
  options.ignore_regions = {{0, 0, -1, 2}};
  const Result<ImageComparison> refused = compare_images(a, a, options);
  REQUIRE_FALSE(refused.is_ok());
  CHECK_THAT(refused.error().message, Catch::Contains("ignore region"));
}

TEST_CASE("the equal-row fast path (no diff image) agrees with the per-pixel reference loop", "[diff]") {
  std::mt19937 random(7);  // seeded
  std::uniform_int_distribution<int> byte(0, 255);
  for (int trial = 0; trial < 50; ++trial) {
    Image a(17, 13);
    for (Rgba8& p : a.pixels()) {
      const auto alpha = static_cast<std::uint8_t>(byte(random) < 40 ? 0 : byte(random));
      const auto channel = [&] { return static_cast<std::uint8_t>(byte(random) * alpha / 255); };
      p = Rgba8{channel(), channel(), channel(), alpha};
    }
    Image b = a;
    for (int k = 0; k < trial % 6; ++k) {  // a few changed pixels on a few rows; most rows stay equal
      b.at(byte(random) % 17, byte(random) % 13) = Rgba8{static_cast<std::uint8_t>(byte(random)), 0, 0, 255};
    }
    DiffOptions with_image, without_image;
    without_image.make_diff_image = false;
    with_image.ignore_antialiasing = without_image.ignore_antialiasing = trial % 2 == 0;
    const DiffMetrics reference = compare(a, b, with_image).metrics;
    const DiffMetrics fast = compare(a, b, without_image).metrics;
    CHECK(fast.compared_pixels == reference.compared_pixels);
    CHECK(fast.changed_pixels == reference.changed_pixels);
    CHECK(fast.different_pixels == reference.different_pixels);
    CHECK(fast.antialiased_pixels == reference.antialiased_pixels);
    CHECK(fast.max_channel_delta == reference.max_channel_delta);
    CHECK(fast.rmse == reference.rmse);  // the same integer sums: bit-identical
    CHECK(fast.difference_bounds == reference.difference_bounds);
  }
}
