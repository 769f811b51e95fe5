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
