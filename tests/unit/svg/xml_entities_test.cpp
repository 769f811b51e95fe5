// Internal DTD entities (svg/xml_entities.h; XML 1.0 sections 4.2 and 4.4), on their own and in
// rendered documents.
#include "svg/xml_entities.h"

#include <catch2/catch.hpp>
#include <string>

#include "curvescan/svg/document.h"

using namespace curvescan;
using namespace curvescan::svg;

namespace {

std::string expand(std::string_view xml, std::vector<std::string>* warnings_out = nullptr) {
  std::vector<std::string> warnings;
  const Result<std::optional<std::string>> expanded = detail::expand_internal_entities(xml, warnings);
  INFO(xml);
  if (!expanded) INFO(expanded.error().message);
  REQUIRE(expanded.is_ok());
  if (warnings_out) *warnings_out = warnings;
  return expanded->value_or(std::string(xml));
}

Error expand_error(std::string_view xml) {
  std::vector<std::string> warnings;
  const Result<std::optional<std::string>> expanded = detail::expand_internal_entities(xml, warnings);
  REQUIRE_FALSE(expanded.is_ok());
  return expanded.error();
}

const std::string kDoctype = "<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" \"http://x/[svg11].dtd\" [\n";

}  // namespace

TEST_CASE("entities: no internal subset, or no entity in it, leaves the text alone") {
  std::vector<std::string> warnings;
  CHECK_FALSE(detail::expand_internal_entities("<svg>&a;</svg>", warnings).value());
  CHECK_FALSE(detail::expand_internal_entities("<!DOCTYPE svg SYSTEM 'a.dtd'><svg/>", warnings).value());
  CHECK_FALSE(
      detail::expand_internal_entities("<!DOCTYPE svg [ <!ELEMENT svg ANY> ]><svg/>", warnings).value());
  CHECK(warnings.empty());
}

TEST_CASE("entities: references in attribute values and content are replaced, recursively") {
  const std::string xml =
      "<?xml version='1.0'?>\n<!-- c -->" + kDoctype +
      "  <!ENTITY st0 \"fill:#F00;\">\n  <!ENTITY st0 \"ignored: the first declaration wins\">\n"
      "  <!ENTITY ns 'http://www.w3.org/2000/svg'>\n  <!ENTITY both \"&st0;stroke:blue\">\n"
      "  <!ENTITY chars \"&#60;g/&#x3E;\">\n]>\n"
      "<svg xmlns=\"&ns;\"><rect style=\"&both;\"/>&chars;<!-- &st0; --><![CDATA[&st0;]]>"
      "<text>&amp;&lt;&#65;&undeclared;</text></svg>";
  const std::string out = expand(xml);
  const std::string body = out.substr(out.find("]>") + 2);
  CHECK(body ==
        "\n<svg xmlns=\"http://www.w3.org/2000/svg\"><rect style=\"fill:#F00;stroke:blue\"/><g/>"
        "<!-- &st0; --><![CDATA[&st0;]]><text>&amp;&lt;&#65;&undeclared;</text></svg>");
}

TEST_CASE("entities: quotes and '<' from an entity cannot end an attribute value") {
  const std::string out =
      expand(kDoctype + "<!ENTITY q \"a'b&#34;c<d\">]><svg id='&q;' class=\"&q;\">&q;</svg>");
  CHECK(out.substr(out.find("<svg")) ==
        "<svg id='a&apos;b&quot;c&lt;d' class=\"a&apos;b&quot;c&lt;d\">a'b\"c<d</svg>");
}

TEST_CASE("entities: external and parameter entities are not read, with a warning") {
  std::vector<std::string> warnings;
  const std::string out = expand(kDoctype +
                                     "<!ENTITY ext SYSTEM \"file:///etc/passwd\"><!ENTITY % pe 'x'>"
                                     "<!ENTITY in 'y'>]><svg>&ext;&in;</svg>",
                                 &warnings);
  CHECK(out.substr(out.find("<svg")) == "<svg>y</svg>");
  REQUIRE(warnings.size() == 2);
  CHECK(warnings[0] == "parameter entities (<!ENTITY % ...>) are not supported; ignored");
  CHECK(warnings[1] == "external entity '&ext;' is not read (no file or network access); dropped");
}

TEST_CASE("entities: the billion laughs, deep nesting and recursion are refused") {
  // Ten levels of ten references to 64 bytes: 6.4 * 10^11 bytes if expanded.
  std::string laughs = kDoctype + "<!ENTITY l0 \"" + std::string(64, 'l') + "\">";
  for (int i = 1; i <= 10; ++i) {
    laughs += "<!ENTITY l" + std::to_string(i) + " \"";
    for (int k = 0; k < 10; ++k) laughs += "&l" + std::to_string(i - 1) + ";";
    laughs += "\">";
  }
  laughs += "]><svg><text>&l10;</text></svg>";
  const Error bomb = expand_error(laughs);
  CHECK(bomb.kind == ErrorKind::kLimitExceeded);
  CHECK(bomb.message.find("entity expansion exceeds 8388608 bytes") != std::string::npos);

  // Expanding to nothing still counts the references: 100^4 empty expansions.
  std::string empty = kDoctype + "<!ENTITY e0 \"\">";
  for (int i = 1; i <= 4; ++i) {
    empty += "<!ENTITY e" + std::to_string(i) + " \"";
    for (int k = 0; k < 100; ++k) empty += "&e" + std::to_string(i - 1) + ";";
    empty += "\">";
  }
  empty += "]><svg>&e4;</svg>";
  CHECK(expand_error(empty).message.find("more than 1000000 entity references") != std::string::npos);

  std::string deep = kDoctype + "<!ENTITY d0 \"x\">";
  for (int i = 1; i <= detail::kMaxEntityDepth + 1; ++i) {
    deep += "<!ENTITY d" + std::to_string(i) + " \"&d" + std::to_string(i - 1) + ";\">";
  }
  deep += "]><svg>&d" + std::to_string(detail::kMaxEntityDepth + 1) + ";</svg>";
  CHECK(expand_error(deep).message.find("nested more than 16 deep") != std::string::npos);

  const Error recursive = expand_error(kDoctype + "<!ENTITY a \"&b;\"><!ENTITY b \"&a;\">]><svg>&a;</svg>");
  CHECK(recursive.kind == ErrorKind::kCorruptInput);
  CHECK(recursive.message == "entity '&a;' refers to itself");
}

TEST_CASE("entities in rendered documents: Illustrator's style entities and elements from an entity") {
  const std::string xml = kDoctype +
                          "  <!ENTITY st0 \"fill:#00FF00;\">\n"
                          "  <!ENTITY Rect \"<rect x='10' width='10' height='10' fill='#0000ff'/>\">\n]>\n"
                          "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"20\" height=\"10\">"
                          "<rect style=\"&st0;\" width=\"10\" height=\"10\"/>&Rect;</svg>";
  const Result<RenderedDocument> rendered = render_svg_document(xml, {});
  REQUIRE(rendered.is_ok());
  CHECK(rendered->image.at(5, 5).g == 255);  // full coverage inside the square: exact colour
  CHECK(rendered->image.at(5, 5).r == 0);
  CHECK(rendered->image.at(15, 5).b == 255);
  CHECK(rendered->warnings.empty());

  const Result<RenderedDocument> external = render_svg_document(
      kDoctype + "<!ENTITY x SYSTEM 'x.svg'>]><svg xmlns=\"http://www.w3.org/2000/svg\">&x;</svg>", {});
  REQUIRE(external.is_ok());
  REQUIRE(external->warnings.size() == 1);
  CHECK(external->warnings[0].find("external entity '&x;' is not read") != std::string::npos);
}
