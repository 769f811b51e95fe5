// Warnings about an invalid property value say where the element is in the document ("line L, column C:
// <rect> ignoring invalid value ..."), as the XML errors and the style sheet warnings do: lines and
// columns from 1, columns in bytes, the column of the element's '<'.
#include <catch2/catch.hpp>
#include <string>

#include "svg/source_positions.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

TEST_CASE("source positions: line and column of byte offsets") {
  const detail::SourcePositions positions("ab\ncd\n\nef");
  CHECK(positions.describe(0) == "line 1, column 1");
  CHECK(positions.describe(2) == "line 1, column 3");  // the newline ends line 1
  CHECK(positions.describe(3) == "line 2, column 1");
  CHECK(positions.describe(6) == "line 3, column 1");  // an empty line
  CHECK(positions.describe(8) == "line 4, column 2");
  CHECK(positions.describe(-5) == "line 1, column 1");    // clamped to the text
  CHECK(positions.describe(1000) == "line 4, column 3");  // clamped to its end
  CHECK(detail::SourcePositions().describe(0) == "line 1, column 1");
}

TEST_CASE("invalid property values are reported with the element's line and column") {
  const std::string xml =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"20\" height=\"20\">\n"
      "  <style>.a { fill: bogus }</style>\n"
      "  <g>\n"
      "    <rect class=\"a\" width=\"10\" height=\"10\" stroke=\"nonsense\"/>\n"
      "\t<rect width=\"-4\" height=\"10\" style=\"opacity: half\"/>\n"
      "  </g>\n"
      "</svg>\n";
  const RenderedDocument rendered = render(xml);
  // A presentation attribute and a style sheet value of the element on line 4, column 5.
  CHECK(contains(rendered.warnings,
                 "line 4, column 5: <rect> ignoring invalid value 'nonsense' of property 'stroke'"));
  CHECK(contains(rendered.warnings,
                 "line 4, column 5: <rect> ignoring invalid value 'bogus' of property 'fill'"));
  // The style attribute and a geometry property of the element on line 5 (a tab is one column).
  CHECK(contains(rendered.warnings,
                 "line 5, column 2: <rect> ignoring invalid value 'half' of property 'opacity'"));
  CHECK(contains(rendered.warnings,
                 "line 5, column 2: <rect> ignoring invalid value '-4' of property 'width'"));
}

// Regression: a declaration with an empty value was dropped without a word. CSS Syntax 3 (5.4.6) gives it
// no value, which no property accepts: invalid, warned about like any invalid value, and the value below
// it stays in force.
TEST_CASE("empty property values in style sheets and style attributes are reported as invalid") {
  const std::string xml =
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"20\" height=\"20\">\n"
      "  <style>rect { fill: }</style>\n"
      "  <rect width=\"10\" height=\"10\" fill=\"blue\"/>\n"
      "  <rect x=\"10\" width=\"10\" height=\"10\" fill=\"blue\" style=\"stroke: !important; fill:\"/>\n"
      "</svg>\n";
  RenderOptions options;
  options.style_sheet = "rect { opacity: }";
  const RenderedDocument rendered = render(xml, options);
  CHECK(contains(rendered.warnings, "line 3, column 3: <rect> ignoring invalid value '' of property 'fill'"));
  CHECK(contains(rendered.warnings, "line 4, column 3: <rect> ignoring invalid value '' of property 'fill'"));
  CHECK(
      contains(rendered.warnings, "line 4, column 3: <rect> ignoring invalid value '' of property 'stroke'"));
  CHECK(contains(rendered.warnings,
                 "line 3, column 3: <rect> ignoring invalid value '' of property 'opacity'"));
  // The invalid declarations are not part of the cascade: the presentation attribute's blue remains,
  // at full opacity.
  CHECK(rendered.image.at(5, 5) == Rgba8{0, 0, 255, 255});
  CHECK(rendered.image.at(15, 5) == Rgba8{0, 0, 255, 255});
}
