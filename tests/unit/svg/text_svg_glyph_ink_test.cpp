// svg::Document::glyph_ink_box: the box of what draw_glyph paints for one SVG-in-OpenType glyph, in the
// document's user space (font units, y down), which the text command sizes its canvas by (docs/text.md,
// "Colour fonts"). Every expected box here is read off the document's numbers; the rectangles' edges and a
// stroke's square corners (miter joins at right angles, whose outline lies at half the width from the
// edge) are exact, so the only error is floating-point rounding of a few operations, far below 1e-9.
#include <catch2/catch.hpp>
#include <optional>
#include <string>

#include "curvescan/svg/document.h"

using namespace curvescan;
using namespace curvescan::svg;

namespace {

std::optional<Rect> ink_of(const std::string& xml, std::uint32_t glyph, double units_per_em = 1000.0) {
  const Result<Document> document = Document::parse_glyph_document(xml);
  REQUIRE(document.is_ok());
  return document->glyph_ink_box(glyph, units_per_em, RenderOptions{});
}

void check_box(const std::optional<Rect>& box, double x0, double y0, double x1, double y1) {
  REQUIRE(box.has_value());
  constexpr double kRounding = 1e-9;  // see the top of the file
  CHECK(box->x0 == Approx(x0).margin(kRounding));
  CHECK(box->y0 == Approx(y0).margin(kRounding));
  CHECK(box->x1 == Approx(x1).margin(kRounding));
  CHECK(box->y1 == Approx(y1).margin(kRounding));
}

}  // namespace

TEST_CASE("glyph_ink_box: the root as the glyph, ink beyond the em on every side", "[svg][text]") {
  check_box(
      ink_of("<svg xmlns='http://www.w3.org/2000/svg' id='glyph8'><rect x='-200' y='-1000' width='1100' "
             "height='1300'/></svg>",
             8),
      -200.0, -1000.0, 900.0, 300.0);
}

TEST_CASE("glyph_ink_box: an element's own transform and its stroke count, as draw_glyph paints them",
          "[svg][text]") {
  // The rect (0,-500)-(200,0) moved 100 to the right, its stroke 20 wide reaching 10 beyond each edge.
  const std::string xml =
      "<svg xmlns='http://www.w3.org/2000/svg'><g id='glyph4' transform='translate(100,0)'>"
      "<rect y='-500' width='200' height='500' fill='red' stroke='blue' stroke-width='20'/></g>"
      "<rect id='glyph5' width='50%' height='10%'/></svg>";
  check_box(ink_of(xml, 4), 90.0, -510.0, 310.0, 10.0);
  // Percentages are of the em square (units_per_em on each side), as draw_glyph resolves them.
  check_box(ink_of(xml, 5, 2048.0), 0.0, 0.0, 1024.0, 204.8);
}

TEST_CASE("glyph_ink_box: nothing for a glyph the document lacks or that draws nothing", "[svg][text]") {
  const std::string xml =
      "<svg xmlns='http://www.w3.org/2000/svg'><g id='glyph1'/><rect id='glyph2' width='9' height='9' "
      "display='none'/></svg>";
  CHECK_FALSE(ink_of(xml, 1).has_value());
  CHECK_FALSE(ink_of(xml, 2).has_value());
  CHECK_FALSE(ink_of(xml, 3).has_value());
}
