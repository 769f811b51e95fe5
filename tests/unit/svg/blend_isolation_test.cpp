// mix-blend-mode and isolation (CSS Compositing and Blending 1, sections 3.2 and 3.3) in documents: an
// element with a blend mode is drawn as a group and blended with what lies under it inside the nearest
// isolated group (a group with opacity, a mask, a blend mode or isolation: isolate; or the canvas). The
// shapes are opaque and cover whole pixels, so the expected colours are the modes' formulas on 0/255
// values: exact.
#include <catch2/catch.hpp>
#include <string>

#include "svg/painting_properties.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

RenderedDocument render20(const std::string& body) { return render(svg_document("width=\"20\" height=\"20\"", body)); }

}  // namespace

TEST_CASE("mix-blend-mode blends an element with what is drawn under it", "[svg][blend]") {
  // A blue square under a red one with screen: magenta where they overlap, red elsewhere.
  const RenderedDocument screen = render20(
      "<rect width=\"10\" height=\"20\" fill=\"blue\"/>"
      "<rect width=\"20\" height=\"20\" fill=\"red\" style=\"mix-blend-mode: screen\"/>");
  CHECK(screen.image.at(5, 5) == Rgba8{255, 0, 255, 255});
  CHECK(screen.image.at(15, 5) == Rgba8{255, 0, 0, 255});  // over the transparent canvas: the source
  CHECK(screen.warnings.empty());
  // multiply from a style sheet, on a group: red multiplied by yellow stays red, by blue black.
  const RenderedDocument multiply = render20(
      "<style>g { mix-blend-mode: multiply }</style>"
      "<rect width=\"10\" height=\"20\" fill=\"yellow\"/><rect x=\"10\" width=\"10\" height=\"20\" "
      "fill=\"blue\"/>"
      "<g><rect width=\"20\" height=\"20\" fill=\"red\"/></g>");
  CHECK(multiply.image.at(5, 5) == Rgba8{255, 0, 0, 255});
  CHECK(multiply.image.at(15, 5) == Rgba8{0, 0, 0, 255});
}

// Regression: mix-blend-mode and isolation were read as presentation attributes. SVG 2 6.6 gives no
// attribute to properties newer than SVG 1.1 (both come from CSS Compositing 1), and browsers ignore
// them: the attribute draws normally and is named once in a warning.
TEST_CASE("mix-blend-mode and isolation as attributes are not presentation attributes", "[svg][blend]") {
  const RenderedDocument blend = render20(
      "<rect width=\"20\" height=\"20\" fill=\"blue\"/>"
      "<rect width=\"20\" height=\"20\" fill=\"red\" mix-blend-mode=\"screen\"/>");
  CHECK(blend.image.at(5, 5) == Rgba8{255, 0, 0, 255});  // screen would give magenta
  CHECK(contains(blend.warnings, "mix-blend-mode attribute"));
  const std::string child =
      "<rect width=\"20\" height=\"20\" fill=\"red\" style=\"mix-blend-mode: difference\"/>";
  const RenderedDocument isolation =
      render20("<rect width=\"20\" height=\"20\" fill=\"white\"/><g isolation=\"isolate\">" + child + "</g>");
  CHECK(isolation.image.at(5, 5) == Rgba8{0, 255, 255, 255});  // not isolated: red difference white
  CHECK(contains(isolation.warnings, "isolation attribute"));
}

TEST_CASE("isolation: isolate keeps a group's children from blending with what lies outside it", "[svg][blend]") {
  const std::string child = "<rect width=\"20\" height=\"20\" fill=\"red\" style=\"mix-blend-mode: difference\"/>";
  // Not isolated: red difference over white = cyan.
  const RenderedDocument open = render20("<rect width=\"20\" height=\"20\" fill=\"white\"/><g>" + child + "</g>");
  CHECK(open.image.at(5, 5) == Rgba8{0, 255, 255, 255});
  // Isolated: the child blends with the group's transparent start (plain red), and the group is drawn
  // source-over.
  const RenderedDocument isolated =
      render20("<rect width=\"20\" height=\"20\" fill=\"white\"/><g style=\"isolation: isolate\">" + child + "</g>");
  CHECK(isolated.image.at(5, 5) == Rgba8{255, 0, 0, 255});
  // Opacity isolates too (a group with opacity is drawn offscreen as a whole).
  const RenderedDocument faded =
      render20("<rect width=\"20\" height=\"20\" fill=\"white\"/><g opacity=\"0.999\">" + child + "</g>");
  // Opacity 0.999 is layer alpha 254 (layer_alpha): plain red over white at 254/255 leaves g = 255·1/255
  // = 1 and r = 255, give or take the one step of composite_source_over's rounding; blended through the
  // group (not isolated) it would be cyan, g = 255.
  CHECK(faded.image.at(5, 5).r >= 254);
  CHECK(faded.image.at(5, 5).g <= 1);
}

TEST_CASE("mix-blend-mode and isolation: keywords, and what is refused", "[svg][blend]") {
  CHECK(detail::parse_blend_mode("color-dodge") == BlendMode::kColorDodge);
  CHECK(detail::parse_blend_mode("luminosity") == BlendMode::kLuminosity);
  CHECK_FALSE(detail::parse_blend_mode("Multiply"));
  CHECK_FALSE(detail::parse_blend_mode("add"));
  // An invalid value is ignored with a warning (normal blending); plus-lighter (a later draft) warns as
  // unsupported.
  const RenderedDocument invalid = render20(
      "<rect width=\"20\" height=\"20\" fill=\"blue\"/><rect width=\"20\" height=\"20\" fill=\"red\" "
      "style=\"mix-blend-mode: add\"/>");
  CHECK(invalid.image.at(5, 5) == Rgba8{255, 0, 0, 255});
  CHECK(contains(invalid.warnings, "mix-blend-mode"));
  const RenderedDocument later =
      render20("<rect width=\"20\" height=\"20\" fill=\"red\" style=\"mix-blend-mode: plus-lighter\"/>");
  CHECK(contains(later.warnings, "plus-lighter"));
}
