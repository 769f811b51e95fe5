// shape-rendering (SVG 1.1 11.7.1): optimizeSpeed and crispEdges draw shapes without anti-aliasing (a
// pixel is in when its centre is, Antialias::kNone); auto and geometricPrecision keep exact coverage. The
// property is inherited and may come from CSS. Expected values follow from the geometry: a square from
// 2.25 to 7.75 covers pixel 2 by 0.75 (coverage 191 of 255 in exact mode) and contains its centre 2.5.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

// The alpha of pixel (2, 4), on the square's left edge, for a square drawn under `attributes`.
int edge_alpha(const std::string& group_attributes, const std::string& rect_attributes = "") {
  const RenderedDocument rendered =
      render(svg_document("width=\"10\" height=\"10\"", "<g " + group_attributes +
                                                            "><rect x=\"2.25\" y=\"2.25\" "
                                                            "width=\"5.5\" height=\"5.5\" " +
                                                            rect_attributes + "/></g>"));
  INFO(group_attributes << " " << rect_attributes);
  CHECK(rendered.warnings.empty());
  CHECK(rendered.image.at(5, 5).a == 255);  // the interior either way
  return rendered.image.at(2, 4).a;
}

}  // namespace

TEST_CASE("shape-rendering: crispEdges and optimizeSpeed alias shapes, auto and geometricPrecision do not") {
  // Exact coverage 0.75 is 191.25 -> 191 (round to nearest); aliased, the centre 2.5 is inside: 255.
  CHECK(edge_alpha("") == 191);
  CHECK(edge_alpha("shape-rendering=\"auto\"") == 191);
  CHECK(edge_alpha("shape-rendering=\"geometricPrecision\"") == 191);
  CHECK(edge_alpha("shape-rendering=\"crispEdges\"") == 255);  // inherited from the group
  CHECK(edge_alpha("shape-rendering=\"optimizeSpeed\"") == 255);
  CHECK(edge_alpha("style=\"shape-rendering: crispEdges\"") == 255);  // from CSS
  CHECK(edge_alpha("shape-rendering=\"crispEdges\"", "shape-rendering=\"auto\"") ==
        191);  // the shape's own wins
}

TEST_CASE("shape-rendering: an invalid value is ignored with a warning (the inherited value stays)") {
  const RenderedDocument rendered =
      render(svg_document("width=\"10\" height=\"10\"",
                          "<g shape-rendering=\"crispEdges\"><rect x=\"2.25\" y=\"2.25\" width=\"5.5\" "
                          "height=\"5.5\" shape-rendering=\"jagged\"/></g>"));
  CHECK(rendered.image.at(2, 4).a == 255);
  CHECK(contains(rendered.warnings, "ignoring invalid value 'jagged' of property 'shape-rendering'"));
}
