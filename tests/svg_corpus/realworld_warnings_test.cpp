// The corpus's documents as editors write them (realworld_*.svg): an Illustrator export (a DTD with
// internal entities, an entity in a style attribute, <style> classes, enable-background, the
// <switch>/<foreignObject requiredExtensions> wrapper and the i:pgf block of "preserve editing
// capabilities"), an Inkscape drawing (sodipodi:/inkscape: attributes and elements, RDF metadata, a
// gradient through href, a stock marker with context-stroke and auto-start-reverse, and a 0.92 flowRoot),
// a Figma export (alpha and luminance masks in user space, a pattern of an image through <use>, a clip of
// the frame) and an icon sheet (<symbol>s with viewBox drawn by <use>, currentColor from classes and
// :nth-child). svg_corpus_test.cpp holds their pixels to rsvg-convert's; here, what they say on stderr:
// every feature that is not drawn is named once, and nothing else — editor metadata, foreign namespaces,
// enable-background (it only matters for BackgroundImage, itself named) and the fallback branch of a
// <switch> whose <foreignObject> can never be chosen are not losses.
#include <catch2/catch.hpp>
#include <filesystem>
#include <string>
#include <vector>

#include "curvescan/svg/document.h"
#include "run_command.h"

using namespace curvescan;

namespace {

std::vector<std::string> warnings_of(const std::string& name) {
  const std::filesystem::path path =
      std::filesystem::path(CURVESCAN_SOURCE_DIR) / "tests/svg_corpus/documents" / (name + ".svg");
  const Result<svg::RenderedDocument> rendered =
      svg::render_svg_document(test::read_text(path), svg::RenderOptions{});
  REQUIRE(rendered.is_ok());
  return rendered->warnings;
}

}  // namespace

TEST_CASE("real-world documents: what is not drawn is named once, and nothing else is said") {
  CHECK(warnings_of("realworld_illustrator_icon").empty());
  CHECK(warnings_of("realworld_figma_card").empty());
  CHECK(warnings_of("realworld_icon_sheet").empty());
  // Inkscape 0.92's flowed text (SVG 1.2 drafts) is drawn by no renderer: its text is named, not lost.
  CHECK(warnings_of("realworld_inkscape_drawing") ==
        std::vector<std::string>{"<flowRoot> is not supported, ignored"});
}

TEST_CASE("unsupported elements whose own conditions fail are not named: no renderer draws them") {
  const auto warnings = [](const std::string& body) {
    const Result<svg::RenderedDocument> rendered = svg::render_svg_document(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"4\" height=\"4\">" + body + "</svg>",
        svg::RenderOptions{});
    REQUIRE(rendered.is_ok());
    return rendered->warnings;
  };
  const std::string fallback = "<rect width=\"4\" height=\"4\" fill=\"green\"/>";
  CHECK(warnings("<switch><foreignObject requiredExtensions=\"http://example.org/x\"/>" + fallback +
                 "</switch>")
            .empty());
  CHECK(warnings("<foreignObject systemLanguage=\"xx\"/>").empty());  // not a language of the render
  // Without a failing condition, or chosen by the switch, it is named.
  CHECK(warnings("<switch><foreignObject/>" + fallback + "</switch>") ==
        std::vector<std::string>{"<foreignObject> is not supported, ignored"});
  CHECK(warnings("<foreignObject systemLanguage=\"en\"/>") ==
        std::vector<std::string>{"<foreignObject> is not supported, ignored"});
}
