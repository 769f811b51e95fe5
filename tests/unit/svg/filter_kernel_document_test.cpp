// The five kernel primitives reached from documents (feTurbulence, feMorphology, feConvolveMatrix,
// feDisplacementMap, feDiffuseLighting / feSpecularLighting): that the filter graph calls each with its
// inputs, subregion and colour space. The kernels' own arithmetic is held to the specification's formulas
// in filter_<name>_test.cpp; here the expected pixels are ones the formulas give exactly (identities,
// flat surfaces, a dilated square's new extent), in sRGB so no colour-space table rounds them.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

// A red 40 x 40 square at (30, 30) on a 100 x 100 canvas, through filter #f (region: the whole canvas).
RenderedDocument filtered(const std::string& primitives) {
  return render(svg_document(
      "width=\"100\" height=\"100\"",
      "<filter id=\"f\" filterUnits=\"userSpaceOnUse\" x=\"0\" y=\"0\" width=\"100\" height=\"100\" "
      "color-interpolation-filters=\"sRGB\">" +
          primitives + "</filter><rect x=\"30\" y=\"30\" width=\"40\" height=\"40\" fill=\"red\" filter=\"url(#f)\"/>"));
}

const Rgba8 kRed{255, 0, 0, 255};

}  // namespace

TEST_CASE("filter kernels in documents: morphology, convolution and displacement", "[svg][filter]") {
  // Dilate by 5: the square grows to 25..75.
  const RenderedDocument dilated = filtered("<feMorphology operator=\"dilate\" radius=\"5\"/>");
  CHECK(dilated.image.at(27, 50) == kRed);
  CHECK(dilated.image.at(23, 50) == Rgba8{});
  CHECK(dilated.warnings.empty());
  // Erode by 5: 35..65.
  const RenderedDocument eroded = filtered("<feMorphology operator=\"erode\" radius=\"5\"/>");
  CHECK(eroded.image.at(32, 50) == Rgba8{});
  CHECK(eroded.image.at(37, 50) == kRed);
  // The identity kernel keeps the input.
  const RenderedDocument identity = filtered("<feConvolveMatrix order=\"3\" kernelMatrix=\"0 0 0 0 1 0 0 0 0\"/>");
  CHECK(identity.image.at(50, 50) == kRed);
  CHECK(identity.image.at(20, 50) == Rgba8{});
  // A displacement of scale 0 keeps the input (in2: a flood).
  const RenderedDocument still = filtered(
      "<feFlood flood-color=\"#808080\" result=\"map\"/><feDisplacementMap in=\"SourceGraphic\" in2=\"map\" "
      "scale=\"0\"/>");
  CHECK(still.image.at(50, 50) == kRed);
  CHECK(still.image.at(20, 50) == Rgba8{});
}

TEST_CASE("filter kernels in documents: turbulence and lighting", "[svg][filter]") {
  // Turbulence fills its whole subregion with noise: some pixel of a 10 x 10 patch has colour.
  const RenderedDocument noise = filtered("<feTurbulence baseFrequency=\"0.05\" numOctaves=\"2\"/>");
  int coloured = 0;
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x) coloured += noise.image.at(x, y).a > 0 ? 1 : 0;
  CHECK(coloured > 0);
  // A flat surface lit by a distant light straight above (elevation 90): N·L = 1, so the result is the
  // lighting colour times kd = 1, opaque, wherever the height map is flat (inside the square, and outside).
  const RenderedDocument lit = filtered(
      "<feDiffuseLighting lighting-color=\"#00ff00\" diffuseConstant=\"1\"><feDistantLight elevation=\"90\"/>"
      "</feDiffuseLighting>");
  CHECK(lit.image.at(50, 50) == (Rgba8{0, 255, 0, 255}));
  CHECK(lit.image.at(10, 10) == (Rgba8{0, 255, 0, 255}));
  // Without a light source the primitive is in error: transparent, with a warning.
  const RenderedDocument dark = filtered("<feDiffuseLighting/>");
  CHECK(dark.image.at(50, 50) == Rgba8{});
  CHECK_FALSE(dark.warnings.empty());
}

TEST_CASE(
    "feDisplacementMap in documents: points displaced from outside the subregion or region read nothing",
    "[svg][filter][displacement]") {
  // Filter Effects 1, 15.13 and 9.7: P'(x, y) = P(x + scale·(XC - 1/2), y + scale·(YC - 1/2)), where P is
  // the input as this primitive sees it: clipped to its subregion (itself within the filter region), so
  // a displaced point outside the subregion reads transparent black even where the source has ink. The
  // map is an opaque flood read through its alpha (A selectors), so every pixel is displaced by
  // (scale/2, scale/2). Oracle, per pixel centre: inside the subregion, and displaced into it onto the
  // red square (30..70), it is red; anything else is transparent. Whole-pixel offsets: exact values.
  struct Case {
    const char* primitive_region;  // the displacement's x, y, width, height
    int scale;
    int x0, y0, x1, y1;  // the same subregion in pixels (the filter region is the whole canvas)
  };
  const Case cases[] = {
      {"x=\"40\" y=\"40\" width=\"20\" height=\"20\"", 20, 40, 40, 60, 60},      // reads 50..70 from 40..60
      {"x=\"40\" y=\"40\" width=\"20\" height=\"20\"", -20, 40, 40, 60, 60},     // reads 30..50
      {"x=\"20\" y=\"45\" width=\"60\" height=\"10\"", 30, 20, 45, 80, 55},      // a band: rows 45..55 only
      {"x=\"-50\" y=\"-50\" width=\"300\" height=\"300\"", 60, 0, 0, 100, 100},  // beyond the filter region
  };
  for (const Case& c : cases) {
    const RenderedDocument doc = filtered(
        "<feFlood flood-color=\"black\" result=\"map\"/><feDisplacementMap in=\"SourceGraphic\" "
        "in2=\"map\" scale=\"" +
        std::to_string(c.scale) + "\" " + c.primitive_region + "/>");
    const int shift = c.scale / 2;
    int mismatches = 0;
    for (int y = 0; y < 100; ++y) {
      for (int x = 0; x < 100; ++x) {
        const int sx = x + shift, sy = y + shift;
        const auto inside = [&](int px, int py) {
          return px >= c.x0 && px < c.x1 && py >= c.y0 && py < c.y1;
        };
        const bool red = inside(x, y) && inside(sx, sy) && sx >= 30 && sx < 70 && sy >= 30 && sy < 70;
        if (doc.image.at(x, y) != (red ? kRed : Rgba8{})) ++mismatches;
      }
    }
    INFO(c.primitive_region << " scale " << c.scale);
    CHECK(mismatches == 0);
    CHECK(doc.warnings.empty());
  }
}
