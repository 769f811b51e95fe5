// The CSS cascade in rendered documents (svg/cascade.h, svg/style_elements.h): <style> sheets,
// specificity and source order, !important, the style attribute, presentation attributes, at-rule and
// selector warnings, the user style sheet of RenderOptions and the bounds of docs/limits.md.
//
// Colours are checked at pixel centres well inside 10 x 10 squares, where coverage is exactly 1, so a
// solid fill gives its exact sRGB value: no tolerance is needed.
#include <catch2/catch.hpp>
#include <string>

#include "curvescan/svg/document.h"
#include "svg/css/style_sheet.h"
#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;

using namespace curvescan::svg::testing;

namespace {

std::string svg_document(const std::string& body) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"40\" height=\"10\">" + body + "</svg>";
}

// Four squares, ids s0..s3, each with `attributes[i]` added.
std::string squares(const std::array<std::string, 4>& attributes) {
  std::string body;
  for (int i = 0; i < 4; ++i) {
    body += "<rect id=\"s" + std::to_string(i) + "\" x=\"" + std::to_string(10 * i) +
            "\" width=\"10\" height=\"10\" " + attributes[static_cast<std::size_t>(i)] + "/>";
  }
  return body;
}

}  // namespace

TEST_CASE("cascade: an Illustrator-style icon's classes give its colours (regression: black squares)") {
  // What Illustrator and the Carbon icon set write: the fills only in class rules of a <style> in <defs>.
  const std::string icon =
      R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 10" width="40" height="10">
    <defs><style>.cls-1{fill:#e6332a;}.cls-2{fill:#1d71b8;}.cls-3{fill:none;stroke:#000;}</style></defs>
    <title>icon</title>
    <rect class="cls-1" width="10" height="10"/>
    <rect class="cls-2" x="10" width="10" height="10"/>
    <rect class="cls-3" x="20" width="10" height="10"/>
    <rect class="cls-1 cls-2" x="30" width="10" height="10"/>
  </svg>)";
  const RenderedDocument rendered = render(icon);
  CHECK(square_colour(rendered.image, 0) == "#e6332a");
  CHECK(square_colour(rendered.image, 1) == "#1d71b8");
  CHECK(square_colour(rendered.image, 2) == "none");
  CHECK(square_colour(rendered.image, 3) == "#1d71b8");  // equal specificity: the later rule wins
  CHECK(rendered.warnings.empty());
  // The same drawing with presentation attributes is the same image, bit for bit.
  const std::string attributes =
      R"(<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 10" width="40" height="10">
    <rect fill="#e6332a" width="10" height="10"/>
    <rect fill="#1d71b8" x="10" width="10" height="10"/>
    <rect fill="none" stroke="#000" x="20" width="10" height="10"/>
    <rect fill="#1d71b8" x="30" width="10" height="10"/>
  </svg>)";
  CHECK(render(attributes).image.pixels() == rendered.image.pixels());
}

TEST_CASE("cascade: specificity, then source order, decide between rules (CSS Cascade 4, 6.4 and 6.5)") {
  const RenderedDocument rendered = render(svg_document(
      "<style>#s0 { fill: #008000 } rect { fill: #ff0000 } rect.a { fill: #008000 } .a { fill: #ff0000 }"
      " .b { fill: #ff0000 } .b { fill: #008000 } svg > #s3 { fill: #008000 } #s3 { fill: #ff0000 }</style>" +
      squares({"", "class=\"a\"", "class=\"b\"", ""})));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
}

TEST_CASE("cascade: :where() weighs nothing, :is() its most specific argument, of-type counts by name") {
  // s0: :where(#s0) is (0,0,0) and loses to rect (0,0,1) though later. s1: :is(#s1, .x) is (1,0,0) and beats
  // rect.b (0,1,1). s2: rect:nth-of-type(3) (0,1,1) is s2, the third rect though the fourth child (a
  // <circle> comes first), and beats .c (0,1,0). s3: rect:last-of-type beats .d the same way.
  const RenderedDocument rendered = render(svg_document(
      "<style>rect { fill: #008000 } :where(#s0) { fill: #ff0000 } :is(#s1, .x) { fill: #008000 }"
      " rect.b { fill: #ff0000 } rect:nth-of-type(3) { fill: #008000 } rect:last-of-type { fill: #008000 }"
      " .c, .d { fill: #ff0000 }</style>"
      "<circle r=\"1\" cx=\"100\" cy=\"100\"/>" +
      squares({"", "class=\"b\"", "class=\"c\"", "class=\"d\""})));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
  CHECK(rendered.warnings.empty());
}

TEST_CASE("cascade: presentation attribute < sheet < style attribute < !important sheet < !important style") {
  const RenderedDocument rendered = render(svg_document(
      "<style>.p { fill: #008000 } .s { fill: #ff0000 } .i { fill: #008000 !important }"
      " .j { fill: #ff0000 !important }</style>" +
      squares({"class=\"p\" fill=\"#ff0000\"", "class=\"s\" style=\"fill: #008000\"",
               "class=\"i\" style=\"fill: #ff0000\"", "class=\"j\" style=\"fill: #008000 !important\""})));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
}

TEST_CASE("cascade: an !important rule beats a more specific normal one, and inherits like any value") {
  const RenderedDocument rendered =
      render(svg_document("<style>rect { fill: #008000 !important } #s0 { fill: #ff0000 }"
                          " g { fill: #0000ff } #s1 { fill: inherit !important }</style>"
                          "<g>" +
                          squares({"", "", "", ""}) + "</g>"));
  CHECK(square_colour(rendered.image, 0) == "#008000");
  CHECK(square_colour(rendered.image, 1) == "#0000ff");  // inherit, !important, from the <g>
}

TEST_CASE("cascade: <style> anywhere -- after use, nested, several, CDATA -- and type other than CSS") {
  const RenderedDocument rendered = render(svg_document(
      squares({"class=\"a\"", "class=\"b\"", "class=\"c\" fill=\"#008000\"", "class=\"d\""}) +
      "<style>.a { fill: #008000 }</style>"
      "<g><defs><style type=\"text/css\"><![CDATA[ .b > x, .b { fill: #008000 } ]]></style></defs></g>"
      "<style type=\"text/plain\">.c { fill: #ff0000 }</style>"
      "<style type=\"TEXT/CSS; charset=utf-8\">.d { fill: #008000 }</style>"));
  for (int i = 0; i < 4; ++i) CHECK(square_colour(rendered.image, i) == "#008000");
  CHECK(contains(rendered.warnings, "<style type=\"text/plain\"> is not CSS; skipped"));
}

TEST_CASE("cascade: at-rules and unsupported selectors are skipped with a warning — the rest applies") {
  const RenderedDocument rendered = render(svg_document(
      "<style>@import url(green.css); @charset \"utf-8\"; @media print { rect { fill: #ff0000 } }"
      "@font-face { font-family: x; src: url(x.ttf) } rect:hover, rect::before { fill: #ff0000 }"
      "#s0 { fill: #008000 } rect:focus { fill: #ff0000 }</style>" +
      squares({"", "", "", ""})));
  CHECK(square_colour(rendered.image, 0) == "#008000");
  CHECK(square_colour(rendered.image, 1) == "#000000");  // nothing applied: the initial black
  CHECK(contains(rendered.warnings, "@import 'url(green.css)' refused: external style sheets are not read"));
  CHECK_FALSE(contains(rendered.warnings, "@media"));  // supported (css_media_test.cpp): print does not match
  CHECK(contains(rendered.warnings, "@font-face is not supported; the at-rule is skipped"));
  CHECK(contains(rendered.warnings,
                 "rule 'rect:hover, rect::before' skipped: the pseudo-class ':hover' is not supported"));
  CHECK(contains(rendered.warnings, "rule 'rect:focus' skipped"));
  CHECK_FALSE(contains(rendered.warnings, "charset"));  // the text is decoded already: nothing to say
}

TEST_CASE("cascade: font-size from a sheet applies before em lengths — gradients' stops are styled too") {
  const RenderedDocument rendered =
      render(svg_document("<style>.w { stroke-width: 1em; font-size: 10px; stroke: #008000 }"
                          " .stop { stop-color: #008000 }</style>"
                          "<linearGradient id=\"g\"><stop class=\"stop\" offset=\"0\"/><stop class=\"stop\" "
                          "offset=\"1\"/></linearGradient>"
                          "<line x1=\"0\" y1=\"0\" x2=\"20\" y2=\"0\" class=\"w\"/>"
                          "<rect x=\"30\" width=\"10\" height=\"10\" fill=\"url(#g)\"/>"));
  // The line's stroke covers y in [-5, 5] when 1em is the sheet's 10 px (declared after stroke-width in
  // the same rule), y in [-8, 8] if it were the initial 16 px: row 4 (centre 4.5) is covered, row 5 not.
  CHECK(rendered.image.at(10, 4).a == 255);
  CHECK(rendered.image.at(10, 5).a == 0);
  CHECK(square_colour(rendered.image, 3) == "#008000");
}

TEST_CASE("cascade: the user style sheet applies after the document's sheets, before the style attribute") {
  RenderOptions options;
  options.style_sheet = ".a { fill: #008000 } #s2 { fill: #008000 } @import 'x.css';";
  const RenderedDocument rendered =
      render(svg_document("<style>.a { fill: #ff0000 } rect { fill: #0000ff }</style>" +
                          squares({"class=\"a\"", "", "style=\"fill: #ff00ff\"", ""})),
             options);
  CHECK(square_colour(rendered.image, 0) == "#008000");
  CHECK(square_colour(rendered.image, 1) == "#0000ff");
  CHECK(square_colour(rendered.image, 2) == "#ff00ff");
  // The at-rule's position in the sheet: 43 characters precede its '@'.
  CHECK(contains(rendered.warnings, "user style sheet: line 1, column 44: @import"));
  // Without the option the document's own sheet decides.
  const RenderedDocument plain =
      render(svg_document("<style>.a { fill: #ff0000 }</style>" + squares({"class=\"a\"", "", "", ""})));
  CHECK(square_colour(plain.image, 0) == "#ff0000");
}

TEST_CASE("cascade: retained documents render the sheets the same way every time") {
  const Result<Document> document = Document::parse(
      svg_document("<style>.a { fill: #008000 } :hover { }</style>" + squares({"class=\"a\"", "", "", ""})));
  REQUIRE(document.is_ok());
  for (int round = 0; round < 2; ++round) {
    const Result<RenderedDocument> rendered = document->render({});
    REQUIRE(rendered.is_ok());
    CHECK(square_colour(rendered->image, 0) == "#008000");
    CHECK(rendered->warnings.size() == 1);  // the parse-time warning, repeated once per render
  }
}

TEST_CASE("cascade limits: a style sheet past the byte bound is skipped, selectors past the count too") {
  std::string big = "/*" + std::string(css::kMaxStyleSheetBytes, 'x') + "*/";
  const RenderedDocument skipped =
      render(svg_document("<style>.a { fill: #008000 }</style><style>" + big +
                          ".a { fill: #ff0000 }</style>" + squares({"class=\"a\"", "", "", ""})));
  CHECK(square_colour(skipped.image, 0) == "#008000");
  CHECK(contains(skipped.warnings,
                 "<style>: skipped: style sheets of more than 4194304 bytes in all are not read"));

  std::string many;
  for (std::size_t i = 0; i < css::kMaxStyleRules; ++i) many += ".x" + std::to_string(i) + "{fill:red}";
  const RenderedDocument counted = render(
      svg_document("<style>" + many + ".a { fill: #ff0000 }</style>" + squares({"class=\"a\"", "", "", ""})));
  CHECK(square_colour(counted.image, 0) == "#000000");
  CHECK(
      contains(counted.warnings, "more than 65536 selectors in all; the rest of the style sheet is skipped"));
}

TEST_CASE(
    "cascade: the transform property of a sheet or style attribute wins over the attribute (SVG 2 8.5)") {
  const RenderedDocument rendered = render(svg_document(
      "<style>#a { transform: translate(10, 0) } #b { transform: none }</style>"
      "<rect id=\"a\" width=\"10\" height=\"10\" fill=\"#008000\" transform=\"translate(30, 0)\"/>"
      "<rect id=\"b\" width=\"10\" height=\"10\" fill=\"#0000ff\" transform=\"translate(20, 0)\"/>"
      "<rect width=\"10\" height=\"10\" fill=\"#ff00ff\" transform=\"translate(30, 0)\""
      " style=\"transform: translate(2rem, 0)\"/>"));
  CHECK(square_colour(rendered.image, 1) == "#008000");  // the sheet's translate(10, 0), not the attribute's 30
  CHECK(square_colour(rendered.image, 0) == "#0000ff");  // none: the attribute's translate(20, 0) is overridden
  CHECK(square_colour(rendered.image, 2) == "none");
  // A relative length neither syntax reads (rem: the root's font size): the declaration is ignored with a warning, the
  // attribute applies (CSS units that are read: css_validity_test.cpp).
  CHECK(square_colour(rendered.image, 3) == "#ff00ff");
  CHECK(contains(rendered.warnings, "<rect> ignoring the transform property"));
}

TEST_CASE("cascade limits: style sheet warnings stop after 32, with one line saying so") {
  std::string sheet;
  for (int i = 0; i < 100; ++i) sheet += "a:hover" + std::to_string(i) + " { } @media x { }";
  const RenderedDocument rendered = render(svg_document("<style>" + sheet + "</style>"));
  REQUIRE(rendered.warnings.size() == css::kMaxStyleWarnings + 1);
  CHECK(rendered.warnings.back() == "further style sheet warnings are not shown");
}

TEST_CASE("cascade limits: declarations past the count are skipped — repeats in a block keep the last") {
  const RenderedDocument repeated =
      render(svg_document("<style>.a { fill: #ff0000; fill: #008000 !important; fill: #0000ff; fill: #ff00ff "
                          "!important }</style>" +
                          squares({"class=\"a\"", "", "", ""})));
  CHECK(square_colour(repeated.image, 0) == "#ff00ff");  // the last !important one

  std::string many = ".a { fill: #008000 } .b {";
  for (std::size_t i = 0; i < css::kMaxStyleDeclarations; ++i) many += "x" + std::to_string(i) + ":1;";
  const RenderedDocument counted = render(svg_document("<style>" + many + "} .c { fill: #ff0000 }</style>" +
                                                       squares({"class=\"a\"", "class=\"c\"", "", ""})));
  CHECK(square_colour(counted.image, 0) == "#008000");
  CHECK(square_colour(counted.image, 1) == "#000000");  // .c came after the bound
  CHECK(contains(counted.warnings,
                 "more than 65536 declarations in all; the rest of the style sheet is skipped"));
}

TEST_CASE("cascade: messages about the rules of a sheet give its line and column") {
  const RenderedDocument rendered = render(svg_document(
      "<style>\nrect { fill: #008000 }\n  rect > > a { fill: #0000ff }\r\n\t@font-face { x: y }</style>" +
      squares({""})));
  // Lines are counted after CSS's preprocessing (CR LF is one newline); columns count bytes from 1.
  CHECK(contains(rendered.warnings, "<style>: line 3, column 3: rule 'rect > > a' skipped"));
  CHECK(contains(rendered.warnings, "<style>: line 4, column 2: @font-face is not supported"));
}
