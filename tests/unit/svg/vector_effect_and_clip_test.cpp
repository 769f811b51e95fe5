// vector-effect (SVG 2, "Vector effects" in the Coordinate Systems chapter) and the deprecated clip property.
// in device space, so a transformed shape with one matches the same shape drawn at device size with the
// same width and dashes; the paint keeps its user-space mapping.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using curvescan::svg::testing::render;

namespace {

std::string document(const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"40\" height=\"40\">" + body + "</svg>";
}

// Largest channel difference between two images of one size.
int max_difference(const Image& a, const Image& b) {
  REQUIRE(a.width() == b.width());
  REQUIRE(a.height() == b.height());
  int worst = 0;
  for (int y = 0; y < a.height(); ++y) {
    for (int x = 0; x < a.width(); ++x) {
      const Rgba8 p = a.at(x, y), q = b.at(x, y);
      worst = std::max(
          {worst, std::abs(p.r - q.r), std::abs(p.g - q.g), std::abs(p.b - q.b), std::abs(p.a - q.a)});
    }
  }
  return worst;
}

}  // namespace

// The two documents describe the same device-space geometry through different transforms, so their
// coverage differs only by floating-point rounding of the mapped coordinates: at most 1/255 per channel.
constexpr int kRoundingTolerance = 1;

TEST_CASE("vector-effect non-scaling-stroke: width and dashes in device pixels under a scale") {
  const RenderedDocument device =
      render(document("<path d=\"M4 4 H36 V20 L4 36\" fill=\"none\" stroke=\"#000\" stroke-width=\"3\" "
                      "stroke-dasharray=\"5 2\"/>"));
  const RenderedDocument scaled =
      render(document("<path transform=\"scale(4 2)\" d=\"M1 2 H9 V10 L1 18\" fill=\"none\" stroke=\"#000\" "
                      "stroke-width=\"3\" "
                      "stroke-dasharray=\"5 2\" vector-effect=\"non-scaling-stroke\"/>"));
  CHECK(max_difference(device.image, scaled.image) <= kRoundingTolerance);
  CHECK(device.image.at(20, 4).a == 255);  // inside the top edge's first dash, not an empty comparison
  // Without the property the same path is stroked in user space: 3 units are 12 device pixels across.
  const RenderedDocument scaling =
      render(document("<path transform=\"scale(4 2)\" d=\"M1 2 H9 V10 L1 18\" fill=\"none\" stroke=\"#000\" "
                      "stroke-width=\"3\" "
                      "stroke-dasharray=\"5 2\"/>"));
  CHECK(max_difference(device.image, scaling.image) == 255);
}

TEST_CASE("vector-effect non-scaling-stroke: a user-space gradient keeps its place on the stroke") {
  const std::string gradient =
      "<linearGradient id=\"g\" gradientUnits=\"userSpaceOnUse\" x1=\"%X1%\" x2=\"%X2%\">"
      "<stop offset=\"0\" stop-color=\"#f00\"/><stop offset=\"1\" stop-color=\"#00f\"/></linearGradient>";
  const auto with = [&](const std::string& x1, const std::string& x2) {
    std::string g = gradient;
    g.replace(g.find("%X1%"), 4, x1);
    g.replace(g.find("%X2%"), 4, x2);
    return g;
  };
  const RenderedDocument device =
      render(document(with("4", "36") +
                      "<rect x=\"4\" y=\"8\" width=\"32\" height=\"24\" fill=\"none\" stroke=\"url(#g)\" "
                      "stroke-width=\"4\"/>"));
  const RenderedDocument scaled =
      render(document(with("1", "9") +
                      "<rect transform=\"scale(4)\" x=\"1\" y=\"2\" width=\"8\" height=\"6\" fill=\"none\" "
                      "stroke=\"url(#g)\" stroke-width=\"4\" vector-effect=\"non-scaling-stroke\"/>"));
  CHECK(max_difference(device.image, scaled.image) <= kRoundingTolerance);
}

TEST_CASE("vector-effect: none is the initial value, the at-risk values are named, junk is invalid") {
  const RenderedDocument at_risk =
      render(document("<rect width=\"4\" height=\"4\" stroke=\"#000\" vector-effect=\"non-rotation\"/>"
                      "<rect width=\"4\" height=\"4\" stroke=\"#000\" vector-effect=\"bogus\"/>"));
  REQUIRE(at_risk.warnings.size() == 2);
  CHECK(at_risk.warnings[0] == "vector-effect: non-rotation is not supported, ignored");
  CHECK(at_risk.warnings[1].find("invalid value 'bogus' of property 'vector-effect'") != std::string::npos);
}

TEST_CASE("the clip property is named once when it would clip, silent when auto") {
  const RenderedDocument clipped =
      render(document("<svg width=\"10\" height=\"10\" clip=\"rect(1px, 2px, 3px, 4px)\"><rect width=\"4\" "
                      "height=\"4\"/></svg>"
                      "<svg width=\"10\" height=\"10\" style=\"clip: rect(0 1px 1px 0)\"><rect width=\"4\" "
                      "height=\"4\"/></svg>"));
  REQUIRE(clipped.warnings.size() == 1);
  CHECK(clipped.warnings[0] == "the clip property (use clip-path) is not supported, ignored");
  const RenderedDocument automatic = render(
      document("<svg width=\"10\" height=\"10\" clip=\"auto\"><rect width=\"4\" height=\"4\"/></svg>"));
  CHECK(automatic.warnings.empty());
}
