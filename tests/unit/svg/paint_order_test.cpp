// paint-order (SVG 2 13.10): the keyword list, and the order of fill, stroke and markers on a shape and on
// text. Shapes are axis-aligned on whole pixels, so every checked pixel is entirely inside one paint:
// exact values.
#include <catch2/catch.hpp>
#include <string>

#include "svg/painting_properties.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;
using detail::PaintLayer;
using detail::PaintOrder;

namespace {

const Rgba8 kRed{255, 0, 0, 255};
const Rgba8 kBlue{0, 0, 255, 255};
const Rgba8 kGreen{0, 128, 0, 255};

constexpr PaintLayer F = PaintLayer::kFill;
constexpr PaintLayer S = PaintLayer::kStroke;
constexpr PaintLayer M = PaintLayer::kMarkers;

// A 20 x 20 red square at (10, 10) with a blue stroke 8 wide (6..14 around its left side), and a green
// 4 x 4 marker square centred on every vertex.
std::string square(const std::string& paint_order_attribute) {
  return svg_document(
      "width=\"40\" height=\"40\"",
      "<marker id=\"m\" markerUnits=\"userSpaceOnUse\" markerWidth=\"4\" markerHeight=\"4\" refX=\"2\" refY=\"2\">"
      "<rect width=\"4\" height=\"4\" fill=\"green\"/></marker>"
      "<path d=\"M10 10 H30 V30 H10 Z\" fill=\"red\" stroke=\"blue\" stroke-width=\"8\" marker-start=\"url(#m)\" " +
          paint_order_attribute + "/>");
}

}  // namespace

TEST_CASE("paint-order: keywords, the ones left out in normal order, and invalid lists", "[svg][paint-order]") {
  CHECK(detail::parse_paint_order("normal") == PaintOrder{F, S, M});
  CHECK(detail::parse_paint_order("fill") == PaintOrder{F, S, M});
  CHECK(detail::parse_paint_order("stroke") == PaintOrder{S, F, M});
  CHECK(detail::parse_paint_order("markers") == PaintOrder{M, F, S});
  CHECK(detail::parse_paint_order("markers stroke") == PaintOrder{M, S, F});
  CHECK(detail::parse_paint_order(" stroke\tmarkers fill ") == PaintOrder{S, M, F});
  CHECK_FALSE(detail::parse_paint_order("stroke stroke"));
  CHECK_FALSE(detail::parse_paint_order("stroke, fill"));
  CHECK_FALSE(detail::parse_paint_order("normal fill"));
  CHECK_FALSE(detail::parse_paint_order(""));
  // Keywords in any ASCII case (SVG 2, 4.2 "Attribute syntax": presentation attributes parse as CSS).
  CHECK(detail::parse_paint_order("Fill Markers") == PaintOrder{F, M, S});
}

TEST_CASE("paint-order orders the fill, the stroke and the markers of a shape", "[svg][paint-order]") {
  // (12, 20): inside the square and under the stroke's inner half. (10, 10) corner: the marker, the
  // stroke and the fill all cover (9, 9)... (11, 11); pixel (10, 10) shows the last painted.
  const RenderedDocument normal = render(square(""));
  CHECK(normal.image.at(12, 20) == kBlue);   // stroke over fill
  CHECK(normal.image.at(10, 10) == kGreen);  // markers last
  const RenderedDocument stroke_first = render(square("paint-order=\"stroke\""));
  CHECK(stroke_first.image.at(12, 20) == kRed);  // fill over the stroke's inner half
  CHECK(stroke_first.image.at(8, 20) == kBlue);  // the outer half still shows
  CHECK(stroke_first.image.at(10, 10) == kGreen);
  const RenderedDocument markers_first = render(square("paint-order=\"markers\""));
  CHECK(markers_first.image.at(10, 10) == kBlue);  // markers, fill, then the stroke over both
  CHECK(markers_first.image.at(12, 20) == kBlue);
  // Inherited, and through CSS.
  const RenderedDocument inherited = render(svg_document(
      "width=\"40\" height=\"40\"",
      "<g style=\"paint-order: stroke fill\"><rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" fill=\"red\" "
      "stroke=\"blue\" stroke-width=\"8\"/></g>"));
  CHECK(inherited.image.at(12, 20) == kRed);
  // An invalid value is ignored with a warning: the normal order.
  const RenderedDocument invalid = render(square("paint-order=\"stroke stroke\""));
  CHECK(invalid.image.at(12, 20) == kBlue);
  CHECK(contains(invalid.warnings, "paint-order"));
}

TEST_CASE("paint-order applies to text: a stroke painted first leaves the glyphs' fill whole", "[svg][paint-order]") {
  // A bold 'I' (a plain stem) 60 px high with a wide blue stroke: with the stroke first, the stem's middle
  // column shows the red fill; in the normal order the stroke (14 wide, 7 each side) covers a stem
  // narrower than 14 px entirely.
  const std::string text_element =
      "<text x=\"20\" y=\"70\" font-family=\"DejaVu Sans\" font-weight=\"bold\" font-size=\"60\" fill=\"red\" "
      "stroke=\"blue\" stroke-width=\"14\" PAINT_ORDER>I</text>";
  auto document = [&](const std::string& paint_order) {
    std::string body = text_element;
    body.replace(body.find("PAINT_ORDER"), 11, paint_order);
    return svg_document("width=\"80\" height=\"80\"", body);
  };
  const RenderedDocument normal = render(document(""));
  const RenderedDocument stroke_first = render(document("paint-order=\"stroke\""));
  // Find the stem's middle column on the row through the glyph's middle, from the fill alone.
  const RenderedDocument fill_only = render(svg_document(
      "width=\"80\" height=\"80\"",
      "<text x=\"20\" y=\"70\" font-family=\"DejaVu Sans\" font-weight=\"bold\" font-size=\"60\" "
      "fill=\"red\">I</text>"));
  int first = -1, last = -1;
  for (int x = 0; x < 80; ++x) {
    if (fill_only.image.at(x, 45) == kRed) {
      if (first < 0) first = x;
      last = x;
    }
  }
  REQUIRE(first >= 0);
  const int middle = (first + last) / 2;
  CHECK(stroke_first.image.at(middle, 45) == kRed);
  CHECK(normal.image.at(middle, 45) == kBlue);
}
