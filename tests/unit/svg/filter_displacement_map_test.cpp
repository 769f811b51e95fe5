// feDisplacementMap (Filter Effects 1, section 15.13). The oracle applies the formula
//   P'(x, y) = P(x + scale * (XC(x, y) - 0.5), y + scale * (YC(x, y) - 0.5))
// per pixel with the documented sampling — the displaced centre (x + 0.5 + dx, y + 0.5 + dy) read from the
// pixel containing it, transparent black outside the subregion — and XC, YC the map's unpremultiplied
// channels. Pixels are copied, so the match is exact.
#include <catch2/catch.hpp>

#include "filter_kernel_support.h"
#include "svg/filter/displacement_map.h"

using namespace curvescan;
using namespace curvescan::svg::detail::filter;
using curvescan::svg::testing::compare_images;
using curvescan::svg::testing::PrimitiveXml;
using curvescan::svg::testing::random_image;
using curvescan::svg::testing::transparent_outside;

namespace {

FilterImage oracle(const FilterImage& in, const FilterImage& map, PixelRect area, double sx, double sy,
                   int xc, int yc) {
  FilterImage out(in.width, in.height);
  for (int y = area.y0; y < area.y1; ++y) {
    for (int x = area.x0; x < area.x1; ++x) {
      const float* m = map.pixel(x, y);
      const auto channel = [&](int c) -> double {
        if (c == 3) return m[3];
        return m[3] == 0.0f ? 0.0 : std::min(1.0, double(m[c]) / m[3]);
      };
      const double px = x + 0.5 + sx * (channel(xc) - 0.5);
      const double py = y + 0.5 + sy * (channel(yc) - 0.5);
      const int ix = static_cast<int>(std::floor(px)), iy = static_cast<int>(std::floor(py));
      if (!area.contains(ix, iy)) continue;
      std::copy_n(in.pixel(ix, iy), 4, out.pixel(x, y));
    }
  }
  return out;
}

DisplacementMapParams read(const std::string& xml) {
  const PrimitiveXml doc(xml);
  std::string error;
  const auto params = read_displacement_map(doc.element(), error);
  REQUIRE(params);
  return *params;
}

}  // namespace

TEST_CASE("feDisplacementMap: matches the formula with nearest-pixel sampling",
          "[svg][filter][displacement]") {
  const FilterImage in = random_image(31, 27, 1);
  const FilterImage map = random_image(31, 27, 2);
  FilterSpace scaled;
  scaled.scale_x = 2.0;
  scaled.scale_y = 0.75;
  FilterSpace bbox_units;
  bbox_units.bounding_box_units = true;
  bbox_units.bbox = Rect{0.0, 0.0, 40.0, 10.0};
  struct Case {
    const char* xml;
    FilterSpace space;
    double sx, sy;  // the scale in filter pixels along each axis
    int xc, yc;
  };
  const Case cases[] = {
      {R"(<feDisplacementMap scale="10"/>)", FilterSpace{}, 10, 10, 3, 3},
      {R"(<feDisplacementMap scale="-7.3" xChannelSelector="R" yChannelSelector="G"/>)", FilterSpace{}, -7.3,
       -7.3, 0, 1},
      {R"(<feDisplacementMap scale="12" xChannelSelector="B" yChannelSelector="A"/>)", scaled, 24, 9, 2, 3},
      {R"(<feDisplacementMap scale="0.25" xChannelSelector="G" yChannelSelector="B"/>)", bbox_units, 10, 2.5,
       1, 2},
  };
  for (const Case& c : cases) {
    const DisplacementMapParams params = read(c.xml);
    for (const PixelRect area : {in.bounds(), PixelRect{4, 2, 25, 20}}) {
      FilterImage out(31, 27);
      render_displacement_map(params, c.space, area, in, map, out);
      const auto diff = compare_images(out, oracle(in, map, area, c.sx, c.sy, c.xc, c.yc));
      INFO(c.xml << " worst at " << diff.x << "," << diff.y << " channel " << diff.channel);
      CHECK(diff.max_diff == 0.0);
      CHECK(transparent_outside(out, area));
    }
  }
}

TEST_CASE("feDisplacementMap: a neutral map or zero scale is the identity — an opaque map shifts",
          "[svg][filter][displacement]") {
  const FilterImage in = random_image(10, 8, 3);
  // A map whose alpha is 1 shifts by scale / 2 along both axes with the default A selectors: scale 4 reads
  // the pixel 2 to the right and 2 down.
  FilterImage opaque(10, 8);
  for (std::size_t i = 3; i < opaque.rgba.size(); i += 4) opaque.rgba[i] = 1.0f;
  FilterImage out(10, 8);
  render_displacement_map(read(R"(<feDisplacementMap scale="4"/>)"), FilterSpace{}, in.bounds(), in, opaque,
                          out);
  CHECK(std::equal(out.pixel(3, 1), out.pixel(3, 1) + 4, in.pixel(5, 3)));
  CHECK(out.pixel(9, 7)[3] == 0.0f);  // displaced outside: transparent black
  FilterImage same(10, 8);
  render_displacement_map(read("<feDisplacementMap/>"), FilterSpace{}, in.bounds(), in, opaque, same);
  CHECK(compare_images(same, in).max_diff == 0.0);
}

TEST_CASE("feDisplacementMap: attributes and hostile scales", "[svg][filter][displacement]") {
  const DisplacementMapParams d = read("<feDisplacementMap/>");
  CHECK(d.scale == 0.0);
  CHECK(d.x_channel == ColorChannel::kA);
  CHECK(d.y_channel == ColorChannel::kA);
  const DisplacementMapParams junk =
      read(R"(<feDisplacementMap scale="x" xChannelSelector="r" yChannelSelector="RGB"/>)");
  CHECK(junk.scale == 0.0);
  CHECK(junk.x_channel == ColorChannel::kA);
  CHECK(junk.y_channel == ColorChannel::kA);
  const FilterImage in = random_image(16, 16, 5);
  const FilterImage map = random_image(16, 16, 6);
  for (const char* xml :
       {R"(<feDisplacementMap scale="1e308"/>)", R"(<feDisplacementMap scale="-1e308"/>)"}) {
    FilterSpace big;
    big.scale_x = 1e10;  // the scale overflows to infinity in filter pixels
    for (const FilterSpace& space : {FilterSpace{}, big}) {
      FilterImage out(16, 16);
      render_displacement_map(read(xml), space, in.bounds(), in, map, out);
      for (const float v : out.rgba) REQUIRE((v >= 0.0f && v <= 1.0f));
    }
  }
}
