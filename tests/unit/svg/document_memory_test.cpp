// The parsed XML tree counts against the render's memory budget: a document whose tree alone passes
// --max-memory is refused at parse time, and the tree's bytes are held against the canvas's budget.
#include <catch2/catch.hpp>

#include <string>

#include "curvescan/svg/document.h"

namespace curvescan::svg {
namespace {

// `count` small elements: about 40 bytes of text each, and one pugixml node (with its attributes) each.
std::string many_rects(int count) {
  std::string xml = R"(<svg xmlns="http://www.w3.org/2000/svg" width="8" height="8">)";
  for (int i = 0; i < count; ++i) xml += R"(<rect x="1" y="1" width="2" height="2"/>)";
  xml += "</svg>";
  return xml;
}

TEST_CASE("a document whose XML tree passes the memory limit is refused when parsed", "[svg][document][limits]") {
  const std::string xml = many_rects(50'000);  // ~2 MB of text
  const Result<Document> refused = Document::parse(xml, std::int64_t{1} << 20);
  REQUIRE_FALSE(refused);
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  CHECK_THAT(refused.error().message, Catch::Contains("XML tree") && Catch::Contains("--max-memory"));

  const Result<Document> accepted = Document::parse(xml);
  REQUIRE(accepted);
  // pugixml parses a copy of the text in place, so the tree holds at least the text's bytes.
  CHECK(accepted->memory_bytes() >= static_cast<std::int64_t>(xml.size()));
  // And not absurdly more: a node and four attributes per element are well under 1 KiB each.
  CHECK(accepted->memory_bytes() < static_cast<std::int64_t>(xml.size()) + 50'000 * 1024);
}

TEST_CASE("render_svg_document applies the render's memory limit to the tree", "[svg][document][limits]") {
  RenderOptions options;
  options.limits.render.max_memory_bytes = std::int64_t{1} << 20;
  const Result<RenderedDocument> refused = render_svg_document(many_rects(50'000), options);
  REQUIRE_FALSE(refused);
  CHECK(refused.error().kind == ErrorKind::kLimitExceeded);
  // A small document under the same limit renders.
  CHECK(render_svg_document(many_rects(10), options));
}

TEST_CASE("parsing after a refused parse counts from zero again", "[svg][document][limits]") {
  // The count belongs to one parse: a refusal must not leave the next parse (or an unlimited one) short.
  REQUIRE_FALSE(Document::parse(many_rects(50'000), std::int64_t{1} << 20));
  CHECK(Document::parse(many_rects(2'000), std::int64_t{1} << 20));
}

}  // namespace
}  // namespace curvescan::svg
