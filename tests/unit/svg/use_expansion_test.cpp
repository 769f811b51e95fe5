// The <use> expansion count of the document index (svg/use_expansion.cpp): the elements the drawing walk
// meets with every <use> expanded, counted before drawing, so that a <use> "billion laughs" is refused at
// once. Each expected count below is worked out by hand from the rules in use_expansion.cpp.
#include <catch2/catch.hpp>
#include <cstdint>
#include <limits>
#include <pugixml.hpp>
#include <string>

#include "curvescan/svg/document.h"
#include "svg/document_index.h"

using namespace curvescan;
using namespace curvescan::svg::detail;

namespace {

const char* const kOpen =
    "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" width=\"4\" "
    "height=\"4\">";

Result<DocumentIndex> index_of(const std::string& body, std::size_t max_elements, pugi::xml_document& xml,
                               Diagnostics& diagnostics) {
  const std::string text = kOpen + body + "</svg>";
  REQUIRE(xml.load_string(text.c_str()));
  return DocumentIndex::build(xml.document_element(), {"en"}, max_elements, nullptr, diagnostics);
}

std::uint64_t expanded(const std::string& body) {
  pugi::xml_document xml;
  Diagnostics diagnostics;
  const Result<DocumentIndex> index = index_of(body, 1000000, xml, diagnostics);
  REQUIRE(index.is_ok());
  return index->expanded_elements();
}

// `levels` levels of ten <use>s of the level below, the lowest a rectangle, all in <defs>, and one <use> of
// the top level drawn.
std::string laughs(int levels) {
  std::string body = "<defs><rect id=\"l0\" width=\"1\" height=\"1\"/>";
  for (int level = 1; level <= levels; ++level) {
    body += "<g id=\"l" + std::to_string(level) + "\">";
    for (int i = 0; i < 10; ++i) body += "<use xlink:href=\"#l" + std::to_string(level - 1) + "\"/>";
    body += "</g>";
  }
  return body + "</defs><use xlink:href=\"#l" + std::to_string(levels) + "\"/>";
}

}  // namespace

TEST_CASE("use expansion: each element the walk meets counts once, each <use> its target again",
          "[svg][use_expansion]") {
  // The root is not counted (the walk starts at its children): g, rect, rect. (No <use>: the element
  // count less the root, which is the same here.)
  CHECK(expanded("<g><rect/><rect/></g>") == 3);
  // defs counts, its content not (drawn only through references); the use counts itself and its rect.
  CHECK(expanded("<defs><rect id='r'/><rect/></defs><use href='#r'/>") == 3);
  // A use of a group: the use, the group and its two children.
  CHECK(expanded("<defs><g id='g'><rect/><rect/></g></defs><use href='#g'/>") == 1 + 1 + 3);
  // A use of a symbol draws the symbol's children (not the symbol, as render_use does).
  CHECK(expanded("<defs><symbol id='s'><rect/><rect/></symbol></defs><use href='#s'/>") == 1 + 1 + 2);
  // Two uses of a use: each counts the chain below it.
  CHECK(expanded("<rect id='r'/><use id='u' href='#r'/><use href='#u'/><use href='#u'/>") == 1 + 2 + 3 + 3);
  // A broken reference counts only the use.
  CHECK(expanded("<use href='#missing'/><use href='other.svg#x'/>") == 2);
}

TEST_CASE("use expansion: a billion laughs of <use> is counted exactly, saturating past 64 bits",
          "[svg][use_expansion]") {
  // defs (its content is not drawn there), the top use, and the top level as that use draws it: a level's
  // group counts itself and its ten uses, each with its target: g(k) = 1 + 10 (1 + g(k-1)), g(0) = 1 (the
  // rectangle).
  const auto group_count = [](int levels) {
    std::uint64_t count = 1;
    for (int level = 1; level <= levels; ++level) count = 1 + 10 * (1 + count);
    return count;
  };
  CHECK(expanded(laughs(3)) == 1 + 1 + group_count(3));
  CHECK(expanded(laughs(5)) == 1 + 1 + group_count(5));
  // 25 levels: about 2 * 10^25 elements, more than 2^64; the count stays at its largest value, not wrapped.
  pugi::xml_document xml;
  Diagnostics diagnostics;
  const std::string body = laughs(25);
  const std::string text = kOpen + body + "</svg>";
  REQUIRE(xml.load_string(text.c_str()));
  const Result<DocumentIndex> index = DocumentIndex::build(
      xml.document_element(), {"en"}, std::numeric_limits<std::size_t>::max(), nullptr, diagnostics);
  REQUIRE(index.is_ok());
  CHECK(index->expanded_elements() == std::numeric_limits<std::uint64_t>::max());
}

TEST_CASE("use expansion: past the element limit the index refuses the document with the walk's error",
          "[svg][use_expansion]") {
  pugi::xml_document xml;
  Diagnostics diagnostics;
  // laughs(4): 2 + 22221 elements.
  const Result<DocumentIndex> refused = index_of(laughs(4), 22222, xml, diagnostics);
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  CHECK(refused.error().message ==
        "rendering needs more than 22222 elements, <use> expansions included (raise --max-elements)");
  pugi::xml_document xml2;
  CHECK(index_of(laughs(4), 22223, xml2, diagnostics).is_ok());
}

TEST_CASE("use expansion: what is not drawn is not expanded", "[svg][use_expansion]") {
  const std::string defs = "<defs><g id='g'><rect/><rect/><rect/></g></defs>";  // 1; a use of #g adds 4
  CHECK(expanded(defs + "<use href='#g'/>") == 1 + 5);
  // display: none, from the attribute, the style attribute or a case the cascade keeps.
  CHECK(expanded(defs + "<use href='#g' display='none'/>") == 1 + 1);
  CHECK(expanded(defs + "<g style='display: NONE'><use href='#g'/></g>") == 1 + 1);
  CHECK(expanded("<defs><symbol id='s' display='none'><rect/></symbol></defs><use href='#s'/>") == 1 + 1);
  // Conditions that fail, and a <switch>: only the child it picks.
  CHECK(expanded(defs + "<use href='#g' systemLanguage='xx'/>") == 1 + 1);
  CHECK(expanded(defs +
                 "<switch><use href='#g' systemLanguage='xx'/><use href='#g'/><use href='#g'/></switch>") ==
        1 + 1 + 5);
  // Unknown and unsupported elements count, their content not.
  CHECK(expanded(defs + "<blink><use href='#g'/></blink><foreignObject><use href='#g'/></foreignObject>") ==
        1 + 2);
}

TEST_CASE("use expansion: circular references count only the <use>, as the walk skips them",
          "[svg][use_expansion]") {
  // A use of its own ancestor: g, rect, use.
  CHECK(expanded("<g id='a'><rect/><use href='#a'/></g>") == 3);
  // Two uses of each other: u1 counts u2, whose reference back to u1 is cut; u2 is memoised at 1.
  CHECK(expanded("<use id='u1' href='#u2'/><use id='u2' href='#u1'/>") == 2 + 1);
  // A use of itself.
  CHECK(expanded("<use id='u' href='#u'/>") == 1);
}

TEST_CASE("use expansion: masks, patterns and markers count their content once", "[svg][use_expansion]") {
  const std::string defs = "<defs><g id='g'><rect/><rect/><rect/></g>";  // defs: 1, a use of #g: 1 + 4
  // Each resource's content: one use of #g (5); the resource elements themselves sit in defs, uncounted.
  CHECK(expanded(defs + "<mask id='m'><use href='#g'/></mask></defs>") == 1 + 5);
  CHECK(
      expanded(defs +
               "<pattern id='p'><use href='#g'/></pattern><marker id='k'><use href='#g'/></marker></defs>") ==
      1 + 5 + 5);
  // Counted once however often they are referenced (the walk counts the further drawings as it makes them).
  CHECK(
      expanded(defs +
               "<marker id='k'><use href='#g'/></marker></defs><path d='M0 0 1 1 2 2' marker-mid='url(#k)'/>"
               "<path d='M0 0 1 1' marker-start='url(#k)'/>") == 1 + 5 + 2);
}

TEST_CASE("use expansion: a <use> billion laughs is refused before drawing, from the renderer too",
          "[svg][use_expansion]") {
  // Six levels: 2 222 223 elements. Refused by the index (no drawing happened, nothing to time here: the
  // refusal comes from DocumentIndex::build, the first step of render()).
  const std::string document = kOpen + laughs(6) + "</svg>";
  const Result<svg::RenderedDocument> refused = svg::render_svg_document(document, svg::RenderOptions{});
  REQUIRE_FALSE(refused.is_ok());
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  CHECK(refused.error().message.find("--max-elements") != std::string::npos);
  // Five levels, 222 223 elements: the walk counts the same, so a limit of exactly that renders (the index
  // refuses no more than the walk would) and one less is refused.
  svg::RenderOptions exact;
  exact.limits.max_elements = 222223;
  CHECK(svg::render_svg_document(kOpen + laughs(5) + "</svg>", exact).is_ok());
  svg::RenderOptions one_less;
  one_less.limits.max_elements = 222222;
  CHECK_FALSE(svg::render_svg_document(kOpen + laughs(5) + "</svg>", one_less).is_ok());
}
