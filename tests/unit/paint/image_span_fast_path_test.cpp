// The image span compositor's fast path for a nearest-sampled image placed by a whole-pixel translation
// (image_span_compositor.h) against the general path's own arithmetic, written out here: map each pixel
// centre through device_to_image, ImagePattern::sample, multiply by the pattern's alpha, composite
// source-over with the span's coverage.
//
// Metric: bytes must be identical (maximum difference 0): the fast path claims to read the very pixel the
// general path samples, so no tolerance is justified.
#include <catch2/catch.hpp>
#include <random>
#include <span>
#include <vector>

#include "curvescan/raster/image_pattern.h"
#include "curvescan/raster/mask.h"
#include "curvescan/raster/paint.h"
#include "paint/image_span_compositor.h"

using namespace curvescan;

namespace {

Image random_image(int w, int h, std::mt19937& rng) {
  Image image(w, h);
  std::uniform_int_distribution<int> byte(0, 255);
  for (Rgba8& p : image.pixels()) {
    const auto a = static_cast<std::uint8_t>(byte(rng) < 64 ? 0 : byte(rng));  // some transparent pixels
    const auto channel = [&] { return static_cast<std::uint8_t>(a == 0 ? 0 : byte(rng) % (a + 1)); };
    p = Rgba8{channel(), channel(), channel(), a};
  }
  return image;
}

// The general path, pixel by pixel.
void reference_blend(Image& target, int origin_x, int origin_y, const ImagePattern& pattern,
                     const Affine& device_to_image, std::span<const Span> spans) {
  for (const Span& span : spans) {
    if (span.coverage == 0) continue;
    for (int i = 0; i < span.len; ++i) {
      Rgba8 color = pattern.sample(device_to_image.apply(Point{span.x + i + 0.5, span.y + 0.5}));
      const unsigned alpha = pattern.alpha;
      color = Rgba8{multiply_coverage(color.r, alpha), multiply_coverage(color.g, alpha),
                    multiply_coverage(color.b, alpha), multiply_coverage(color.a, alpha)};
      Rgba8& pixel = target.at(span.x + i - origin_x, span.y - origin_y);
      if (color.a != 0) pixel = composite_source_over(pixel, color, span.coverage);
    }
  }
}

}  // namespace

TEST_CASE("image span compositor: a whole-pixel translation reads the image rows directly, same bytes",
          "[paint][image]") {
  std::mt19937 rng(20);
  const Image image = random_image(13, 9, rng);
  for (const std::uint8_t alpha : {std::uint8_t{255}, std::uint8_t{128}}) {
    ImagePattern pattern{image, Affine::identity(), PatternExtend::kNone, PatternFilter::kNearest, alpha};
    // Shifts that put the image inside, across every edge, and entirely outside the target.
    for (const auto& [e, f] : std::vector<std::pair<double, double>>{
             {0, 0}, {-3, -2}, {5, 4}, {-20, 0}, {0, 30}, {-12, -8}, {6, -5}}) {
      INFO("shift " << e << ", " << f << ", alpha " << int(alpha));
      const Affine device_to_image = Affine::translate(e, f);
      Image background(20, 16);
      for (Rgba8& p : background.pixels()) p = Rgba8{10, 20, 30, 40};
      // Spans over the whole target with varied coverage, some starting left of the image.
      std::vector<Span> spans;
      for (int y = 0; y < 16; ++y) {
        spans.push_back(Span{0, y, 7, static_cast<std::uint8_t>(255 - 9 * y)});
        spans.push_back(Span{7, y, 13, 255});
      }
      Image fast = background, slow = background;
      detail::ImageSpanCompositor compositor(fast, 0, 0, pattern, device_to_image);
      compositor.blend(spans);
      reference_blend(slow, 0, 0, pattern, device_to_image, spans);
      CHECK(fast.pixels() == slow.pixels());
    }
  }
}
