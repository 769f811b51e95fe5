// <switch> and conditional processing (SVG 1.1 5.8), and duplicate ids: exact pixels of whole-pixel
// rectangles.
#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

const Rgba8 kGreen{0, 128, 0, 255};

// The colour at the centre of a 10 x 10 document with `body`.
Rgba8 centre(const std::string& body, const RenderOptions& options = {}) {
  return render(svg_document("width=\"10\" height=\"10\"", body), options).image.at(5, 5);
}

std::string rect(const std::string& attributes, const std::string& fill) {
  return "<rect width=\"10\" height=\"10\" fill=\"" + fill + "\" " + attributes + "/>";
}

}  // namespace

TEST_CASE("switch: the first child whose conditions hold, and only it", "[svg][switch]") {
  CHECK(centre("<switch>" + rect("", "green") + rect("", "red") + "</switch>") == kGreen);
  CHECK(centre("<switch><!-- a comment --><blink/>" + rect("", "green") + rect("", "red") + "</switch>") ==
        kGreen);
  CHECK(centre("<switch>" + rect("requiredExtensions=\"http://example.org/x\"", "red") + rect("", "green") +
               "</switch>") == kGreen);
  CHECK(centre("<switch>" + rect("requiredExtensions=\"\"", "red") + rect("", "green") + "</switch>") ==
        kGreen);
  CHECK(centre("<switch>" + rect("requiredFeatures=\"http://www.w3.org/TR/SVG11/feature#Shape\"", "green") +
               rect("", "red") + "</switch>") == kGreen);
  // A chosen child with display="none" renders nothing; the next one is still not chosen.
  CHECK(centre("<switch>" + rect("display=\"none\"", "red") + rect("", "red") + "</switch>") == Rgba8{});
  // The switch's own attributes apply as a group's.
  CHECK(centre("<switch fill=\"green\"><rect width=\"10\" height=\"10\"/></switch>") == kGreen);
}

TEST_CASE("switch: systemLanguage against the user's languages", "[svg][switch]") {
  const auto chosen = [](const std::string& value, const RenderOptions& options = {}) {
    return centre(
               "<switch>" + rect("systemLanguage=\"" + value + "\"", "green") + rect("", "red") + "</switch>",
               options) == kGreen;
  };
  CHECK(chosen("en"));
  CHECK(chosen("en-GB"));  // "en" is a prefix followed by '-'
  CHECK(chosen("EN-us"));  // tags compare without case
  CHECK(chosen("ru, en"));
  CHECK_FALSE(chosen("ru-RU"));
  CHECK_FALSE(chosen("eng"));
  CHECK_FALSE(chosen(""));
  RenderOptions french;
  french.languages = {"fr", "de"};
  CHECK(chosen("de", french));
  CHECK_FALSE(chosen("en", french));
  // Outside a switch a failing condition removes the element; on the root, the whole drawing.
  CHECK(centre(rect("", "green") + rect("systemLanguage=\"ru\"", "red")) == kGreen);
  CHECK(render(svg_document("width=\"10\" height=\"10\" systemLanguage=\"ru\"", rect("", "red")))
            .image.at(5, 5) == Rgba8{});
}

TEST_CASE("duplicate ids: a reference finds the first element with the id, as browsers do", "[svg][ids]") {
  CHECK(centre("<defs><rect id=\"r\" width=\"10\" height=\"10\" fill=\"green\"/>"
               "<g><rect id=\"r\" width=\"10\" height=\"10\" fill=\"red\"/></g></defs><use href=\"#r\"/>") ==
        kGreen);
  CHECK(centre("<defs><g><rect id=\"r\" width=\"10\" height=\"10\" fill=\"green\"/></g>"
               "<rect id=\"r\" width=\"10\" height=\"10\" fill=\"red\"/></defs><use href=\"#r\"/>") ==
        kGreen);
}

// Regression (resvg's structure/systemLanguage/on-tspan): the conditional processing attributes were read on
// graphics elements only, so a <tspan systemLanguage="ru-RU"> was drawn over the text before it. SVG 1.1
// 5.8.1 applies them to the text content elements too: a failing <tspan> (or <tref>, <textPath>, <a>) is not
// rendered, with its text. Exact: each document is held to the bytes of the same text without the element.
TEST_CASE("conditional processing on text content elements", "[svg][switch][text]") {
  const auto text = [](const std::string& content) {
    return render(svg_document(
                      "width=\"120\" height=\"40\"",
                      "<text y=\"30\" font-family=\"DejaVu Sans\" font-size=\"24\">" + content + "</text>"))
        .image;
  };
  const Image expected = text("<tspan x=\"8\" fill=\"green\">Text</tspan>");
  REQUIRE(inked_pixels(expected) > 0);
  CHECK(text("<tspan x=\"8\" fill=\"green\">Text</tspan>"
             "<tspan x=\"8\" fill=\"red\" systemLanguage=\"ru-RU\">Text</tspan>") == expected);
  CHECK(text("<tspan x=\"8\" fill=\"green\">Text</tspan>"
             "<a x=\"8\" requiredExtensions=\"http://example.org/x\"><tspan fill=\"red\">Text</tspan></a>") ==
        expected);
  // A condition that holds changes nothing: the same tspan with systemLanguage="en" is drawn.
  CHECK(text("<tspan x=\"8\" fill=\"green\" systemLanguage=\"en\">Text</tspan>") == expected);
}
