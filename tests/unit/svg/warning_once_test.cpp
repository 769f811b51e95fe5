// Each kind of warning is given once per document (docs/svg.md, "Exit codes and messages"), however often
// the content that causes it is drawn: by several <use>s, by a marker at every vertex, by a pattern or a
// mask applied to several elements. The renderer says it at each drawing; the document's messages keep the
// first of each text (document.cpp, messages_for_the_user), and the unsupported elements are named by the
// document index, once per name.
#include <algorithm>
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

long occurrences(const std::vector<std::string>& messages, const std::string& part) {
  return std::count_if(messages.begin(), messages.end(),
                       [&](const std::string& message) { return message.find(part) != std::string::npos; });
}

// Content that warns (an unsupported element, an unknown one, a broken paint reference, an invalid value,
// an unsupported property value), drawn three times through <use>, at three marker vertices, in a pattern
// painted on two elements and in a mask applied to two.
const std::string kBody =
    "<defs>"
    "<g id='g'><animate/><blink/><rect width='1' height='1' fill='url(#none1)' stroke-linejoin='bogus' "
    "vector-effect='non-rotation'/></g>"
    "<marker id='m'><foreignObject/><frob/><circle r='1' fill='url(#none2)' stroke-width='bad'/></marker>"
    "<pattern id='p' width='2' height='2' patternUnits='userSpaceOnUse'><set/><blonk/>"
    "<rect width='1' height='1' fill='url(#none3)'/></pattern>"
    "<mask id='k'><script/><flob/><rect width='8' height='8' fill='white' fill-opacity='x'/></mask>"
    "</defs>"
    "<use href='#g'/><use href='#g' x='2'/><use href='#g' x='4'/>"
    "<path d='M0 0 2 2 4 4 6 6' stroke='black' marker-mid='url(#m)'/>"
    "<rect width='2' height='2' fill='url(#p)'/><rect x='2' width='2' height='2' fill='url(#p)'/>"
    "<rect width='2' height='2' mask='url(#k)'/><rect y='4' width='2' height='2' mask='url(#k)'/>";

}  // namespace

TEST_CASE("warnings: each is given once however often its content is drawn", "[svg][warnings]") {
  const RenderedDocument rendered = render(svg_document("width='8' height='8'", kBody));
  for (const char* part :
       {"<animate> is not supported", "<foreignObject> is not supported", "<set> is not supported",
        "<script> is not supported", "'#none1', which does not exist", "'#none2', which does not exist",
        "'#none3', which does not exist", "'bogus'", "'bad'", "fill-opacity",
        "vector-effect: non-rotation"}) {
    INFO(part);
    CHECK(occurrences(rendered.warnings, part) == 1);
  }
  // Unknown element names are warnings too, once per name.
  for (const char* name : {"<blink>", "<frob>", "<blonk>", "<flob>"}) {
    INFO(name);
    CHECK(occurrences(rendered.warnings, std::string(name) + " is not a known SVG element") == 1);
  }
}
