// The document index (svg/document_index.h): each element's role and conditions, the id index, the mask
// loops and the unsupported-element warnings, decided once per render by one walk.
#include "svg/document_index.h"

#include <catch2/catch.hpp>
#include <pugixml.hpp>
#include <string>
#include <vector>

using namespace curvescan;
using namespace curvescan::svg::detail;

namespace {

struct Indexed {
  pugi::xml_document xml;
  Diagnostics diagnostics;
  DocumentIndex index;

  explicit Indexed(const std::string& body, const std::vector<std::string>& languages = {"en"},
                   std::size_t max_elements = 1000) {
    const std::string text =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:c=\"urn:curvescan:curves\" "
        "xmlns:x=\"http://example.org/x\">" +
        body + "</svg>";
    REQUIRE(xml.load_string(text.c_str()));
    Result<DocumentIndex> built =
        DocumentIndex::build(xml.document_element(), languages, max_elements, nullptr, diagnostics);
    REQUIRE(built.is_ok());
    index = std::move(built).value();
  }

  pugi::xml_node by_id(const char* id) const {
    const auto found = index.ids().find(id);
    REQUIRE(found != index.ids().end());
    return found->second;
  }
  const ElementFacts& facts(const char* id) const { return index.facts(by_id(id)); }
};

int count_containing(const std::vector<std::string>& messages, const std::string& part) {
  int count = 0;
  for (const std::string& message : messages) count += message.find(part) != std::string::npos ? 1 : 0;
  return count;
}

}  // namespace

TEST_CASE("document index: each element's role", "[svg][document_index]") {
  const Indexed doc(
      "<g id='g'/><rect id='rect'/><linearGradient id='gradient'/><defs id='defs'/>"
      "<foreignObject id='foreign-object'/><blink id='unknown'/><x:rect id='foreign'/><c:bezier "
      "id='curve'/>");
  CHECK(doc.facts("g").role == ElementRole::kRendered);
  CHECK(doc.facts("rect").role == ElementRole::kRendered);
  CHECK(doc.facts("gradient").role == ElementRole::kNonRendering);
  CHECK(doc.facts("defs").role == ElementRole::kNonRendering);
  CHECK(doc.facts("foreign-object").role == ElementRole::kUnsupported);
  CHECK(doc.facts("unknown").role == ElementRole::kUnknown);
  CHECK(doc.facts("foreign").role == ElementRole::kForeign);
  CHECK(doc.facts("curve").role == ElementRole::kCurve);
  CHECK(doc.index.facts(doc.xml.document_element()).role == ElementRole::kRendered);
  // What a <switch> may pick: graphics elements, curves, and unsupported elements (named, drawing nothing).
  CHECK(is_switch_candidate(ElementRole::kRendered));
  CHECK(is_switch_candidate(ElementRole::kCurve));
  CHECK(is_switch_candidate(ElementRole::kUnsupported));
  CHECK_FALSE(is_switch_candidate(ElementRole::kNonRendering));
  CHECK_FALSE(is_switch_candidate(ElementRole::kUnknown));
  CHECK_FALSE(is_switch_candidate(ElementRole::kForeign));
}

TEST_CASE("document index: the namespace of each name, as Namespaces in XML scopes it",
          "[svg][document_index]") {
  const Indexed doc(
      "<g xmlns='http://example.org/x'><rect id='in-x'/>"
      "<s:rect xmlns:s='http://www.w3.org/2000/svg' id='prefixed'/>"
      "<g xmlns='http://www.w3.org/2000/svg'><rect id='back-in-svg'/></g>"
      "<g xmlns=''><rect id='no-namespace'/></g></g>"
      "<rect id='after'/>");
  CHECK(doc.facts("in-x").role == ElementRole::kForeign);
  CHECK(doc.facts("prefixed").role == ElementRole::kRendered);
  CHECK(doc.facts("back-in-svg").role == ElementRole::kRendered);
  CHECK(doc.facts("no-namespace").role == ElementRole::kRendered);  // no namespace is read as SVG
  CHECK(doc.facts("after").role == ElementRole::kRendered);
}

TEST_CASE("document index: conditions against the user's languages", "[svg][document_index]") {
  const std::string body =
      "<rect id='plain'/><rect id='german' systemLanguage='de'/><rect id='english' systemLanguage='fr, "
      "en-GB'/>"
      "<rect id='extension' requiredExtensions='http://example.org/x'/>"
      "<rect id='feature' requiredFeatures='http://www.w3.org/TR/SVG11/feature#Shape'/>";
  const Indexed english(body, {"en"});
  CHECK(english.facts("plain").conditions_hold);
  CHECK_FALSE(english.facts("german").conditions_hold);
  CHECK(english.facts("english").conditions_hold);
  CHECK_FALSE(english.facts("extension").conditions_hold);
  CHECK(english.facts("feature").conditions_hold);
  const Indexed german(body, {"de"});
  CHECK(german.facts("german").conditions_hold);
  CHECK_FALSE(german.facts("english").conditions_hold);
}

TEST_CASE("document index: the first element of an id wins", "[svg][document_index]") {
  const Indexed doc("<rect id='a' width='1'/><g><rect id='a' width='2'/></g>");
  CHECK(std::string(doc.by_id("a").attribute("width").value()) == "1");
}

TEST_CASE("document index: an unsupported element is named once, unless its conditions fail",
          "[svg][document_index]") {
  const Indexed doc("<foreignObject/><defs><foreignObject/></defs><video requiredExtensions='x'/>");
  CHECK(count_containing(doc.diagnostics.warnings, "<foreignObject> is not supported") == 1);
  CHECK(count_containing(doc.diagnostics.warnings, "<video>") == 0);
}

TEST_CASE("document index: a mask reference that closes a loop counts as none", "[svg][document_index]") {
  const Indexed doc(
      "<mask id='m1'><rect id='self' mask='url(#m1)'/><rect id='to-m2' mask='url(#m2)'/></mask>"
      "<mask id='m2'><rect id='back' mask='url(#m1)'/></mask>"
      "<rect id='user' mask='url(#m1)'/>");
  CHECK(doc.facts("self").mask_loop_dropped);  // m1 inside m1
  CHECK(doc.facts("back").mask_loop_dropped);  // m1 -> m2 -> m1: the reference back to m1 goes
  CHECK_FALSE(doc.facts("to-m2").mask_loop_dropped);
  CHECK_FALSE(doc.facts("user").mask_loop_dropped);  // outside every mask: no loop
  CHECK(count_containing(doc.diagnostics.warnings, "closes a loop back to mask id=\"m1\"") == 2);
}

TEST_CASE("document index: more elements than the limit is a limit error", "[svg][document_index]") {
  pugi::xml_document xml;
  REQUIRE(xml.load_string("<svg xmlns='http://www.w3.org/2000/svg'><g><rect/><rect/></g></svg>"));
  Diagnostics diagnostics;
  CHECK(DocumentIndex::build(xml.document_element(), {"en"}, 4, nullptr, diagnostics).is_ok());
  const Result<DocumentIndex> over =
      DocumentIndex::build(xml.document_element(), {"en"}, 3, nullptr, diagnostics);
  REQUIRE_FALSE(over.is_ok());
  CHECK(over.error().kind == ErrorKind::kLimitExceeded);
  CHECK(over.error().message.find("more than 3 elements") != std::string::npos);
}
