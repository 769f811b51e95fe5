// Elements of another namespace inside <text> are not text content (SVG 2 6.5: unknown elements are not
// rendered), even when their local name is an SVG one: mixed namespaces as in the SVG 1.1 test
// struct-frag-05. The checks count inked pixels, so they hold for any font the machine has.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

RenderedDocument text_with(const std::string& content) {
  return render(svg_document("width=\"100\" height=\"40\"",
                             "<text x=\"5\" y=\"30\" font-size=\"24\">" + content + "</text>"));
}

}  // namespace

TEST_CASE("text: an <a> of a foreign namespace draws nothing, one bound by a prefix to SVG does",
          "[svg][text][namespace]") {
  // The SVG namespace through another prefix is still SVG: its text is drawn.
  const RenderedDocument prefixed =
      text_with("<toto:a xmlns:toto=\"http://www.w3.org/2000/svg\">Valid</toto:a>");
  CHECK(inked_pixels(prefixed.image) > 0);
  const RenderedDocument plain = text_with("<a>Valid</a>");
  CHECK(inked_pixels(plain.image) == inked_pixels(prefixed.image));
  // The same local name in a default namespace that is not SVG's: not text content.
  const RenderedDocument foreign = text_with("<a xmlns=\"http://example.org/notsvg\">Invalid</a>");
  CHECK(inked_pixels(foreign.image) == 0);
  // Its SVG-looking children are foreign too (they inherit the default namespace).
  const RenderedDocument nested = text_with(
      "<x:g xmlns:x=\"http://example.org/notsvg\"><tspan "
      "xmlns=\"http://example.org/notsvg\">No</tspan></x:g>");
  CHECK(inked_pixels(nested.image) == 0);
}
