// RenderOptions::export_id (rsvg-convert's --export-id): one element alone, at the size of its ink box in
// its parent's user space. Sizes are whole numbers here (boxes on whole units), and the checked pixels lie
// well inside or outside the shapes: exact values.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

// The viewBox halves everything and the group moves it: neither applies to an exported element.
const std::string kDocument = svg_document(
    "width=\"200\" height=\"100\" viewBox=\"0 0 400 200\"",
    "<g id=\"g\" transform=\"translate(100 50)\" fill=\"blue\">"
    "<rect id=\"plain\" x=\"10\" y=\"20\" width=\"30\" height=\"40\"/>"
    "<rect id=\"stroked\" x=\"10\" y=\"20\" width=\"30\" height=\"40\" stroke=\"red\" stroke-width=\"4\"/>"
    "<rect id=\"turned\" width=\"30\" height=\"10\" transform=\"rotate(90)\"/>"
    "<rect id=\"empty\" width=\"0\" height=\"10\"/></g>");

Result<RenderedDocument> export_id(const std::string& id, double zoom = 1.0) {
  RenderOptions options;
  options.export_id = id;
  options.zoom = zoom;
  return render_svg_document(kDocument, options);
}

}  // namespace

TEST_CASE("export_id: the element alone, its ink box as the size, the styles it inherits", "[svg][export-id]") {
  const Result<RenderedDocument> plain = export_id("plain");
  REQUIRE(plain.is_ok());
  CHECK(plain->image.width() == 30);
  CHECK(plain->image.height() == 40);
  CHECK(plain->image.at(15, 20) == (Rgba8{0, 0, 255, 255}));  // the inherited fill
  // The stroke counts: 2 more on every side; the stroke's outer half at the edge is red.
  const Result<RenderedDocument> stroked = export_id("#stroked");
  REQUIRE(stroked.is_ok());
  CHECK(stroked->image.width() == 34);
  CHECK(stroked->image.height() == 44);
  CHECK(stroked->image.at(0, 22) == (Rgba8{255, 0, 0, 255}));
  CHECK(stroked->image.at(17, 22) == (Rgba8{0, 0, 255, 255}));
  // The element's own transform applies: 10 x 30 after the quarter turn.
  const Result<RenderedDocument> turned = export_id("turned");
  REQUIRE(turned.is_ok());
  CHECK(turned->image.width() == 10);
  CHECK(turned->image.height() == 30);
  // Zoom scales the natural size.
  const Result<RenderedDocument> zoomed = export_id("plain", 2.0);
  REQUIRE(zoomed.is_ok());
  CHECK(zoomed->image.width() == 60);
  // A group: the union of its children's ink boxes in its own space (its translate is not applied):
  // x from -10 (the turned rectangle) to 42 (the stroke), y from 0 (turned) to 62 (the stroke).
  const Result<RenderedDocument> group = export_id("g");
  REQUIRE(group.is_ok());
  CHECK(group->image.width() == 52);
  CHECK(group->image.height() == 62);
}

TEST_CASE("export_id: an id that names nothing, or an element that draws nothing, is an error", "[svg][export-id]") {
  const Result<RenderedDocument> missing = export_id("nope");
  REQUIRE_FALSE(missing.is_ok());
  CHECK(missing.error().message.find("no element with id \"nope\"") != std::string::npos);
  const Result<RenderedDocument> empty = export_id("empty");
  REQUIRE_FALSE(empty.is_ok());
  CHECK(empty.error().message.find("draws nothing") != std::string::npos);
}
