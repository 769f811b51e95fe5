// The filter graph's speed-ups must not change a pixel: the fast blur (edgeMode none) against the plain
// reference implementation, and filters over a small ink (each primitive computes only where its result
// can be other than transparent, per-pixel primitives reuse their input's memory, a blur reads SourceAlpha
// from SourceGraphic) against the same filters made to compute their whole region.
#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "filter_kernel_support.h"
#include "svg/filter/gaussian_blur.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;
using namespace curvescan::svg::detail::filter;

namespace {

// Both blurs sum in double and store floats; they differ in the order of additions (running sums against
// prefix sums, columns first against rows first), so they agree to float rounding: values are in [0, 1],
// a float carries 6e-8 relative, and 1e-5 leaves room for the hundreds of additions per value (the same
// bound as filter_blur_test.cpp holds both to the direct oracles).
constexpr double kBlurTolerance = 1e-5;

}  // namespace

TEST_CASE("feGaussianBlur: the fast path's bands of rows and strips of columns join seamlessly",
          "[svg][filter][blur]") {
  // The fast path blurs rows 32 at a time and columns 64 at a time: a rectangle of several bands and
  // strips, with partial ones at the end, and a written part that starts inside a strip.
  const FilterImage in = random_image(150, 97, 11);
  for (const auto& [sx, sy] : {std::pair{1.5, 0.7}, std::pair{4.4, 6.5}, std::pair{25.0, 3.0}}) {
    FilterImage fast(in.width, in.height), plain(in.width, in.height), part(in.width, in.height);
    gaussian_blur(in, in.bounds(), sx, sy, EdgeMode::kNone, fast);
    gaussian_blur_reference(in, in.bounds(), sx, sy, EdgeMode::kNone, plain);
    const ImageDifference d = compare_images(fast, plain);
    INFO("sigma " << sx << ", " << sy << " worst at " << d.x << "," << d.y);
    CHECK(d.max_diff < kBlurTolerance);
    const PixelRect written{37, 20, 141, 90};
    gaussian_blur(in, in.bounds(), sx, sy, EdgeMode::kNone, part, false, written);
    CHECK(same_inside_and_transparent_outside(part, fast, written));
  }
}

TEST_CASE("feGaussianBlur: the fast path for edgeMode none is the reference blur", "[svg][filter][blur]") {
  const FilterImage in = random_image(53, 37, 7);
  for (const PixelRect area : {in.bounds(), PixelRect{3, 5, 40, 30}, PixelRect{10, 2, 11, 35}}) {
    // σ < 2 (exact kernel), odd and even box sizes, one axis only, and a box wider than the image.
    for (const auto& [sx, sy] : {std::pair{0.5, 1.5}, std::pair{2.0, 2.5}, std::pair{4.4, 6.5},
                                 std::pair{0.0, 3.0}, std::pair{3.0, 0.0}, std::pair{33.0, 1.0}}) {
      FilterImage fast(in.width, in.height), plain(in.width, in.height);
      gaussian_blur(in, area, sx, sy, EdgeMode::kNone, fast);
      gaussian_blur_reference(in, area, sx, sy, EdgeMode::kNone, plain);
      const ImageDifference d = compare_images(fast, plain);
      INFO("sigma " << sx << ", " << sy << " area " << area.x0 << "," << area.y0 << " worst at " << d.x << ","
                    << d.y);
      CHECK(d.max_diff < kBlurTolerance);
    }
  }
  // Asked for part of the result only, the blur writes that part, equal to the whole blur there.
  for (const EdgeMode mode : {EdgeMode::kNone, EdgeMode::kDuplicate}) {
    const PixelRect part{12, 9, 30, 21};
    FilterImage whole(in.width, in.height), some(in.width, in.height);
    gaussian_blur(in, in.bounds(), 3.0, 1.2, mode, whole);
    gaussian_blur(in, in.bounds(), 3.0, 1.2, mode, some, false, part);
    double inside = 0.0, outside = 0.0;
    for (int y = 0; y < in.height; ++y)
      for (int x = 0; x < in.width; ++x)
        for (int c = 0; c < 4; ++c) {
          const double a = some.pixel(x, y)[c], b = whole.pixel(x, y)[c];
          if (part.contains(x, y)) {
            inside = std::max(inside, std::fabs(a - b));
          } else {
            outside = std::max(outside, std::fabs(a));
          }
        }
    CHECK(inside < kBlurTolerance);
    CHECK(outside == 0.0);
  }
  // Only the colour channels that hold something are blurred; the others are written as zero.
  FilterImage alpha_only(20, 20), out(20, 20);
  alpha_only.pixel(10, 10)[3] = 1.0f;
  for (float& v : out.rgba) v = 0.5f;
  gaussian_blur(alpha_only, alpha_only.bounds(), 2.0, 2.0, EdgeMode::kNone, out);
  CHECK(out.pixel(10, 10)[0] == 0.0f);
  CHECK(out.pixel(10, 10)[3] > 0.0f);
  CHECK(blur_reach(0.0) == 0);
  CHECK(blur_reach(1.0) == 3);                                   // ceil(3σ)
  CHECK(blur_reach(10.0) == 3 * (box_blur_size(10.0) / 2) + 1);  // three boxes of half-width 9, plus one
}

TEST_CASE("filters compute only over the ink, with the same result", "[svg][filter]") {
  // Each filter chains primitives whose extents differ: offsets, blurs (exact and box, SourceAlpha read
  // directly or made), Porter-Duff operators, arithmetic with and without k4, merges, blends, colour
  // matrices with an alpha offset, component transfers that lift alpha 0, floods into a subregion,
  // morphology (which computes its whole subregion), and colour-space changes between them.
  const std::string filters[] = {
      // the drop shadow of the benchmark
      "<feGaussianBlur in='SourceAlpha' stdDeviation='3'/><feOffset dx='4' dy='-3' result='o'/>"
      "<feFlood flood-color='#203040' flood-opacity='0.6'/><feComposite in2='o' operator='in'/>"
      "<feMerge><feMergeNode/><feMergeNode in='SourceGraphic'/></feMerge>",
      "<feGaussianBlur stdDeviation='1.2 0.4' result='b'/><feComposite in='SourceGraphic' in2='b' "
      "operator='xor' color-interpolation-filters='sRGB'/>",
      "<feOffset dx='-7' dy='5' result='o'/><feComposite in='o' in2='SourceGraphic' operator='out'/>"
      "<feComposite in2='SourceAlpha' operator='atop'/>",
      "<feFlood flood-color='red' x='85' y='85' width='30' height='20' result='f'/>"
      "<feComposite in='f' in2='SourceGraphic' operator='arithmetic' k1='0.5' k2='0.3' k3='0.4' k4='0.1'/>",
      "<feOffset dx='3' result='o'/><feComposite in='o' in2='SourceGraphic' operator='arithmetic' k1='1'/>"
      "<feBlend in2='SourceGraphic' mode='multiply'/>",
      "<feColorMatrix type='matrix' values='1 0 0 0 0 0 1 0 0 0 0 0 1 0 0 0 0 0 1 0.2'/>"
      "<feGaussianBlur stdDeviation='2.5'/>",
      "<feComponentTransfer><feFuncA type='linear' slope='0.5' intercept='0.25'/></feComponentTransfer>"
      "<feOffset dx='2' dy='2'/>",
      "<feColorMatrix type='saturate' values='0.3'/><feComponentTransfer><feFuncR type='gamma' "
      "exponent='2'/></feComponentTransfer><feMerge><feMergeNode in='SourceAlpha'/><feMergeNode/></feMerge>",
      "<feGaussianBlur in='SourceAlpha' stdDeviation='4' edgeMode='duplicate'/>"
      "<feBlend in2='SourceGraphic' mode='screen'/>",
      "<feMorphology radius='2' operator='dilate'/><feComposite in2='SourceGraphic' operator='lighter'/>",
  };
  // The ink: two overlapping translucent shapes in the middle of a 200 x 200 canvas. The filter region is
  // the whole canvas. The oracle document adds two dots of alpha 1/255 at opposite corners, so the ink's
  // box is the whole region and every primitive computes all of it; each dot changes pixels at most as far
  // as the filter carries content (under 20 pixels here), so the two renders are compared on [30, 170)^2.
  const std::string shapes =
      "<rect x='80' y='85' width='35' height='25' fill='#3070c0' fill-opacity='0.8'/>"
      "<circle cx='110' cy='112' r='14' fill='#e0a020'/>";
  const std::string dots =
      "<rect x='0' y='0' width='1' height='1' fill='#000' fill-opacity='0.004'/>"
      "<rect x='199' y='199' width='1' height='1' fill='#000' fill-opacity='0.004'/>";
  for (const std::string& primitives : filters) {
    const auto document = [&](const std::string& extra) {
      return svg_document(
          "width='200' height='200'",
          "<filter id='f' filterUnits='userSpaceOnUse' x='0' y='0' width='200' height='200'>" + primitives +
              "</filter><g filter='url(#f)'>" + shapes + extra + "</g>");
    };
    const RenderedDocument fast = render(document("")), oracle = render(document(dots));
    int worst = 0;
    for (int y = 30; y < 170; ++y)
      for (int x = 30; x < 170; ++x) {
        const Rgba8 p = fast.image.at(x, y), q = oracle.image.at(x, y);
        worst = std::max(
            {worst, std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
      }
    INFO(primitives);
    // The blurs add in a different order over a narrower line (1e-5 at most, kBlurTolerance), which can
    // move a value across a rounding boundary of the 8-bit output: one level.
    CHECK(worst <= 1);
    CHECK(fast.warnings.empty());
    CHECK(inked_pixels(fast.image) > 0);
  }
}

TEST_CASE("a filter crossing the canvas edge gives the pixels a larger canvas shows", "[svg][filter]") {
  // The filter region is cut to the canvas grown by each primitive's reach (primitive_reach), and the
  // primitives compute only what lands on the canvas (input_needed): the visible pixels must not change.
  // Oracle: the same document on a canvas twice as large (same user space), cropped.
  const std::string filters[] = {
      "<feGaussianBlur in='SourceAlpha' stdDeviation='4'/><feOffset dx='-6' dy='3' result='o'/>"
      "<feFlood flood-color='#203040' flood-opacity='0.6'/><feComposite in2='o' operator='in'/>"
      "<feMerge><feMergeNode/><feMergeNode in='SourceGraphic'/></feMerge>",
      // Each kernel reads a neighbourhood of an offset or a blur: that primitive must compute what the
      // kernel's pixels on the canvas read beyond the canvas's edge.
      "<feOffset dx='-2' dy='1'/><feMorphology radius='3' operator='dilate'/>",
      "<feGaussianBlur stdDeviation='0.8'/><feMorphology radius='2 4' operator='erode'/>",
      "<feOffset dx='1'/><feConvolveMatrix order='5' "
      "kernelMatrix='1 0 0 0 0 0 1 0 0 0 0 0 1 0 0 0 0 0 1 0 0 0 0 0 1' targetX='1'/>",
      "<feOffset dx='2' result='s'/><feTurbulence baseFrequency='0.05' numOctaves='2' result='t'/>"
      "<feDisplacementMap in='s' in2='t' scale='12' xChannelSelector='R' yChannelSelector='G'/>",
      "<feOffset dx='-1' result='s'/><feDiffuseLighting in='s' surfaceScale='4'><feDistantLight azimuth='30' "
      "elevation='40'/></feDiffuseLighting><feComposite in2='SourceAlpha' operator='in'/>",
      "<feDropShadow dx='5' dy='-4' stdDeviation='3'/>",
  };
  // Stripes of one pixel just beyond the canvas's right edge (x = 100) make any shortfall visible.
  std::string shapes =
      "<rect x='70' y='30' width='50' height='40' fill='#3070c0'/><circle cx='95' cy='60' r='15' "
      "fill='#e0a020' fill-opacity='0.7'/>";
  for (int x = 100; x < 108; x += 2)
    shapes += "<rect x='" + std::to_string(x) + "' y='20' width='1' height='60' fill='#" +
              (x % 4 == 0 ? std::string("f0f") : std::string("0f0")) + "'/>";
  for (const std::string& primitives : filters) {
    const auto document = [&](int size) {
      const std::string side = std::to_string(size);
      return svg_document(
          "width='" + side + "' height='" + side + "'",
          "<filter id='f' filterUnits='userSpaceOnUse' x='0' y='0' width='200' height='100'>" + primitives +
              "</filter><g filter='url(#f)'>" + shapes + "</g>");
    };
    const RenderedDocument small = render(document(100)), large = render(document(200));
    int worst = 0;
    for (int y = 0; y < 100; ++y)
      for (int x = 0; x < 100; ++x) {
        const Rgba8 p = small.image.at(x, y), q = large.image.at(x, y);
        worst = std::max(
            {worst, std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
      }
    INFO(primitives);
    CHECK(worst <= 1);  // the blurs' order of additions, as above
    CHECK(inked_pixels(small.image) > 0);
  }
}
