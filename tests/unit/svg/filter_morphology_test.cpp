// feMorphology (Filter Effects 1, section 15.20). The oracle takes, for every pixel and channel, the
// minimum or maximum over the whole (2 rx + 1) x (2 ry + 1) window clipped to where the input exists (its
// own subregion, which may reach beyond the primitive's) by brute force; a window with no input pixel gives
// transparent. Min and max select one of the input values, so the kernel must match exactly (tolerance 0).
#include <catch2/catch.hpp>
#include <chrono>

#include "filter_kernel_support.h"
#include "svg/filter/morphology.h"

using namespace curvescan;
using namespace curvescan::svg::detail::filter;
using curvescan::svg::testing::compare_images;
using curvescan::svg::testing::PrimitiveXml;
using curvescan::svg::testing::random_image;
using curvescan::svg::testing::transparent_outside;

namespace {

FilterImage oracle(const FilterImage& in, PixelRect area, PixelRect input_area, int rx, int ry, bool dilate) {
  FilterImage out(in.width, in.height);
  for (int y = area.y0; y < area.y1; ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      for (int c = 0; c < 4; ++c) {
        float best = dilate ? 0.0f : 1.0f;
        bool any = false;
        for (int wy = y - ry; wy <= y + ry; ++wy) {
          for (int wx = x - rx; wx <= x + rx; ++wx) {
            if (!input_area.contains(wx, wy)) continue;
            const float v = in.pixel(wx, wy)[c];
            best = dilate ? std::max(best, v) : std::min(best, v);
            any = true;
          }
        }
        out.pixel(x, y)[c] = any ? best : 0.0f;
      }
    }
  }
  return out;
}

MorphologyParams read(const std::string& xml) {
  const PrimitiveXml doc(xml);
  std::string error;
  const auto params = read_morphology(doc.element(), error);
  REQUIRE(params);
  CHECK(error.empty());
  return *params;
}

}  // namespace

TEST_CASE("feMorphology: erode and dilate match the brute-force window", "[svg][filter][morphology]") {
  const FilterImage in = random_image(29, 23, 5);
  FilterSpace scaled;
  scaled.scale_x = 1.5;  // radius 2 -> 3 pixels
  scaled.scale_y = 0.5;  // radius 3 -> 1.5 -> 2 pixels (rounded half away from zero)
  struct Case {
    const char* xml;
    FilterSpace space;
    int rx, ry;  // the window half-sizes in pixels the documented rounding gives
  };
  const Case cases[] = {
      {R"(<feMorphology radius="1"/>)", FilterSpace{}, 1, 1},
      {R"(<feMorphology operator="dilate" radius="2 0.6"/>)", FilterSpace{}, 2, 1},
      {R"(<feMorphology operator="erode" radius="4 1"/>)", FilterSpace{}, 4, 1},
      {R"(<feMorphology operator="dilate" radius="0.2 3"/>)", FilterSpace{}, 0, 3},
      {R"(<feMorphology operator="dilate" radius="2 3"/>)", scaled, 3, 2},
      {R"(<feMorphology radius="40 100"/>)", FilterSpace{}, 40, 100},  // wider than the image
      // One radius zero: along the other axis only, as Chromium and Firefox do (morphology.h).
      {R"(<feMorphology operator="dilate" radius="3 0"/>)", FilterSpace{}, 3, 0},
      {R"(<feMorphology radius="0 2"/>)", FilterSpace{}, 0, 2},
  };
  for (const Case& c : cases) {
    const MorphologyParams params = read(c.xml);
    for (const PixelRect area : {in.bounds(), PixelRect{3, 4, 21, 20}, PixelRect{10, 10, 11, 18}}) {
      FilterImage out(29, 23);
      render_morphology(params, c.space, area, in, out);
      const auto diff =
          compare_images(out, oracle(in, area, area, c.rx, c.ry, params.op == MorphologyOperator::kDilate));
      INFO(c.xml << " worst at " << diff.x << "," << diff.y << " channel " << diff.channel);
      CHECK(diff.max_diff == 0.0);
      CHECK(transparent_outside(out, area));
    }
    // The input exists beyond the primitive's subregion (its own subregion is larger): the windows read it
    // there. And a subregion larger than the input's: windows reach only the input's pixels, and pixels
    // whose whole window lies beyond it are transparent.
    const std::pair<PixelRect, PixelRect> reads[] = {{PixelRect{3, 4, 21, 20}, in.bounds()},
                                                     {PixelRect{10, 10, 11, 18}, PixelRect{2, 2, 25, 21}},
                                                     {in.bounds(), PixelRect{8, 6, 20, 15}}};
    for (const auto& [area, input_area] : reads) {
      FilterImage out(29, 23);
      render_morphology(params, c.space, area, in, out, input_area);
      const auto diff = compare_images(
          out, oracle(in, area, input_area, c.rx, c.ry, params.op == MorphologyOperator::kDilate));
      INFO(c.xml << " reading beyond the subregion, worst at " << diff.x << "," << diff.y << " channel "
                 << diff.channel);
      CHECK(diff.max_diff == 0.0);
      CHECK(transparent_outside(out, area));
    }
  }
}

TEST_CASE("feMorphology: a negative radius, or both zero, passes the input through",
          "[svg][filter][morphology]") {
  // Filter Effects 1: "A negative or zero value disables the effect of the given filter primitive (i.e., the
  // result is the filter input image)." A single zero radius is the window without extent along that axis
  // (the cases above).
  const FilterImage in = random_image(12, 10, 8);
  for (const char* xml :
       {"<feMorphology/>", R"(<feMorphology radius="0"/>)", R"(<feMorphology radius="-2"/>)",
        R"(<feMorphology operator="dilate" radius="0 0"/>)", R"(<feMorphology radius="-1 5"/>)",
        R"(<feMorphology radius="4 -1"/>)", R"(<feMorphology radius="junk"/>)"}) {
    FilterImage out(12, 10);
    render_morphology(read(xml), FilterSpace{}, {1, 1, 11, 9}, in, out);
    FilterImage expected(12, 10);
    for (int y = 1; y < 9; ++y)
      for (int x = 1; x < 11; ++x) std::copy_n(in.pixel(x, y), 4, expected.pixel(x, y));
    INFO(xml);
    CHECK(compare_images(out, expected).max_diff == 0.0);
  }
}

TEST_CASE("feMorphology: attributes", "[svg][filter][morphology]") {
  const MorphologyParams d = read("<feMorphology/>");
  CHECK(d.op == MorphologyOperator::kErode);
  CHECK(d.radius_x == 0.0);
  const MorphologyParams p = read(R"(<feMorphology operator="dilate" radius="1.5,2"/>)");
  CHECK(p.op == MorphologyOperator::kDilate);
  CHECK(p.radius_x == 1.5);
  CHECK(p.radius_y == 2.0);
  CHECK(read(R"(<feMorphology operator="Dilate" radius="1 2 3"/>)").op == MorphologyOperator::kErode);
  CHECK(read(R"(<feMorphology radius="1 2 3"/>)").radius_x == 0.0);
}

TEST_CASE("feMorphology: cost does not grow with the radius", "[svg][filter][morphology]") {
  // A radius of 1e308 on a 512 x 512 image: a window-by-window implementation would never finish; the
  // running extremum does two linear passes. The result is the global minimum of each channel.
  const FilterImage in = random_image(512, 512, 4);
  FilterImage out(512, 512);
  const auto start = std::chrono::steady_clock::now();
  render_morphology(read(R"(<feMorphology radius="1e308"/>)"), FilterSpace{}, in.bounds(), in, out);
  render_morphology(read(R"(<feMorphology operator="dilate" radius="1e308 1e9"/>)"), FilterSpace{},
                    in.bounds(), in, out);
  CHECK(std::chrono::steady_clock::now() - start < std::chrono::seconds(10));
  float global_max = 0.0f;
  for (std::size_t i = 3; i < in.rgba.size(); i += 4) global_max = std::max(global_max, in.rgba[i]);
  CHECK(out.pixel(0, 0)[3] == global_max);
  CHECK(out.pixel(511, 300)[3] == global_max);
}

TEST_CASE("feMorphology: an input whose ink is a small part reads only that ink, and only the needed part",
          "[svg][filter][morphology]") {
  // The input is transparent outside its ink rectangle (its extent). The kernel reads the ink (dilate) or
  // the ink and one ring around it (erode), and computes only the needed pixels: still the brute-force
  // window over the whole input area, exactly, with the input area reaching beyond the ink or not.
  FilterImage in(31, 27);
  const FilterImage random = random_image(31, 27, 9);
  const PixelRect ink{9, 7, 20, 16};
  for (int y = ink.y0; y < ink.y1; ++y)
    for (int x = ink.x0; x < ink.x1; ++x) std::copy_n(random.pixel(x, y), 4, in.pixel(x, y));
  // A fully opaque block inside the ink, so that erosion leaves something.
  for (int y = 10; y < 14; ++y)
    for (int x = 12; x < 18; ++x) std::fill_n(in.pixel(x, y), 4, 1.0f);
  in.extent = ink;
  const PixelRect needed{4, 5, 25, 14};
  for (const char* xml :
       {R"(<feMorphology radius="1"/>)", R"(<feMorphology operator="dilate" radius="3 2"/>)",
        R"(<feMorphology radius="1e30"/>)", R"(<feMorphology operator="dilate" radius="1e30"/>)",
        R"(<feMorphology operator="dilate" radius="9 0"/>)"}) {
    const MorphologyParams params = read(xml);
    const int rx = params.radius_x > 100 ? 31 : int(std::lround(params.radius_x));
    const int ry = params.radius_y > 100 ? 27 : int(std::lround(params.radius_y));
    for (const PixelRect input_area : {in.bounds(), ink, PixelRect{10, 8, 19, 15}}) {
      FilterImage out(31, 27);
      const PixelRect written =
          render_morphology(params, FilterSpace{}, in.bounds(), in, out, input_area, needed);
      const FilterImage expected =
          oracle(in, in.bounds(), input_area, rx, ry, params.op == MorphologyOperator::kDilate);
      double worst = 0.0;
      for (int y = needed.y0; y < needed.y1; ++y)
        for (int x = needed.x0; x < needed.x1; ++x)
          for (int c = 0; c < 4; ++c)
            worst = std::max(worst, double(std::fabs(out.pixel(x, y)[c] - expected.pixel(x, y)[c])));
      INFO(xml << " input area " << input_area.x0 << "," << input_area.y0 << " " << input_area.x1 << ","
               << input_area.y1);
      CHECK(worst == 0.0);
      CHECK(transparent_outside(out, written));
      CHECK(needed.intersect(written) == written);
    }
  }
}
