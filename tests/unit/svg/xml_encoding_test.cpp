// Documents in legacy encodings (XML 1.0 4.3.3; xml_encoding.h). The expected UTF-8 is written out from
// the code charts: windows-1251 0xCF 0xF0 0xE8 0xE2 0xE5 0xF2 is "Привет" (U+041F U+0440 U+0438 U+0432
// U+0435 U+0442), ISO-8859-1 0xE9 is "é" (U+00E9), ISO-8859-2 0xB1 is "ą" (U+0105).
#include "svg/xml_encoding.h"

#include <catch2/catch.hpp>
#include <string>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;

namespace {

std::string converted(const std::string& xml) {
  const Result<std::optional<std::string>> out = detail::transcode_to_utf8(xml, 1 << 20);
  REQUIRE(out.is_ok());
  REQUIRE(out->has_value());
  return **out;
}

}  // namespace

TEST_CASE("xml encoding: the declared encoding is read from the XML declaration", "[svg][encoding]") {
  CHECK(detail::declared_encoding("<?xml version=\"1.0\" encoding=\"Windows-1251\"?><svg/>") ==
        "Windows-1251");
  CHECK(detail::declared_encoding("<?xml version='1.0' encoding = 'koi8-r' standalone='no'?>") == "koi8-r");
  CHECK(detail::declared_encoding("<?xml version=\"1.0\"?><svg/>").empty());
  CHECK(detail::declared_encoding("<svg encoding=\"x\"/>").empty());  // no declaration
  CHECK(detail::declared_encoding("<?xml-stylesheet href=\"a\"?>").empty());
  CHECK(detail::declared_encoding("<?xml version=\"1.0\" encoding=\"latin1\"").empty());  // unterminated
}

TEST_CASE("xml encoding: legacy encodings become UTF-8, and the declaration says so", "[svg][encoding]") {
  CHECK(converted("<?xml version=\"1.0\" encoding=\"windows-1251\"?><t>\xCF\xF0\xE8\xE2\xE5\xF2</t>") ==
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?><t>\u041F\u0440\u0438\u0432\u0435\u0442</t>");
  CHECK(converted("<?xml version='1.0' encoding='ISO-8859-1'?><t>\xE9</t>") ==
        "<?xml version='1.0' encoding='UTF-8'?><t>\u00E9</t>");
  CHECK(converted("<?xml version=\"1.0\" encoding=\"ISO-8859-2\"?><t>\xB1</t>") ==
        "<?xml version=\"1.0\" encoding=\"UTF-8\"?><t>\u0105</t>");
  // UTF-8, ASCII and no declaration: nothing to convert.
  for (const char* same : {"<?xml version=\"1.0\" encoding=\"utf-8\"?><svg/>",
                           "<?xml version=\"1.0\" encoding=\"US-ASCII\"?><svg/>", "<svg/>"}) {
    const Result<std::optional<std::string>> out = detail::transcode_to_utf8(same, 1 << 20);
    REQUIRE(out.is_ok());
    CHECK_FALSE(out->has_value());
  }
}

TEST_CASE("xml encoding: unknown encodings, invalid bytes and the size limit are errors", "[svg][encoding]") {
  const auto error_of = [](const std::string& xml, std::int64_t limit) {
    const Result<std::optional<std::string>> out = detail::transcode_to_utf8(xml, limit);
    REQUIRE_FALSE(out.is_ok());
    return out.error().kind;
  };
  CHECK(error_of("<?xml version=\"1.0\" encoding=\"no-such-encoding\"?><svg/>", 1 << 20) ==
        ErrorKind::kCorruptInput);
  // Shift_JIS 0x81 begins a two-byte character: the text ends in the middle of it.
  CHECK(error_of("<?xml version=\"1.0\" encoding=\"Shift_JIS\"?><svg/>\x81", 1 << 20) ==
        ErrorKind::kCorruptInput);
  // Six Cyrillic letters take twelve bytes in UTF-8: beyond a limit of 40 bytes with the declaration.
  CHECK(error_of("<?xml version=\"1.0\" encoding=\"windows-1251\"?><t>\xCF\xF0\xE8\xE2\xE5\xF2</t>", 40) ==
        ErrorKind::kLimitExceeded);
}

TEST_CASE("xml encoding: a windows-1251 document renders, its ids in Cyrillic", "[svg][encoding]") {
  // The <use> finds the rectangle only if both ids were converted alike: a 10 x 10 green square.
  const std::string xml =
      "<?xml version=\"1.0\" encoding=\"windows-1251\"?>"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\">"
      "<defs><rect id=\"\xCF\xF0\xE8\" width=\"10\" height=\"10\" fill=\"#00ff00\"/></defs>"
      "<use href=\"#\xCF\xF0\xE8\"/></svg>";
  const RenderedDocument out = testing::render(xml);
  CHECK(out.image.at(5, 5) == Rgba8{0, 255, 0, 255});
  const Result<RenderedDocument> unknown =
      render_svg_document("<?xml version=\"1.0\" encoding=\"x-nothing\"?><svg/>", RenderOptions{});
  REQUIRE_FALSE(unknown.is_ok());
  CHECK(unknown.error().message.find("x-nothing") != std::string::npos);
}
