// An SVG document drawn by <image> is read as a top-level document is (svg_tree.h): its legacy encoding
// converted to UTF-8 (XML 1.0 4.3.3), its internal DTD entities expanded, an encoding nobody knows refused.
// Regression: the nested documents went straight to pugixml, which reads windows-1251 bytes as they are and
// leaves "&name;" unexpanded.
#include <catch2/catch.hpp>
#include <cstdint>
#include <string>
#include <vector>

#include "svg_test_support.h"

using namespace curvescan;
using namespace curvescan::svg;
using namespace curvescan::svg::testing;

namespace {

// A 20 x 10 document drawing `inner` (its bytes as they are) through <image> over its whole area.
std::string outer_document(const std::string& inner) {
  const std::vector<std::uint8_t> bytes(inner.begin(), inner.end());
  return svg_document(
      "width=\"20\" height=\"10\"",
      "<image width=\"20\" height=\"10\" href=\"data:image/svg+xml;base64," + base64(bytes) + "\"/>");
}

bool is_green(const Rgba8& p) {
  return p.r == 0 && p.g == 255 && p.b == 0 && p.a == 255;
}

}  // namespace

TEST_CASE("nested svg: a legacy encoding is converted as in a top-level document", "[svg][image][encoding]") {
  // windows-1251 0xE6 is U+0436 (ж): the id written in windows-1251 matches the reference written as a
  // character reference only once the bytes are converted to UTF-8.
  const std::string inner =
      "<?xml version=\"1.0\" encoding=\"windows-1251\"?>"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"20\" height=\"10\">"
      "<defs><rect id=\"\xE6\" width=\"20\" height=\"10\" fill=\"#00ff00\"/></defs>"
      "<use href=\"#&#x436;\"/></svg>";
  const RenderedDocument top = render(inner);
  CHECK(is_green(top.image.at(10, 5)));
  const RenderedDocument nested = render(outer_document(inner));
  CHECK(is_green(nested.image.at(10, 5)));
  CHECK(nested.warnings.empty());
}

TEST_CASE("nested svg: internal entities are expanded as in a top-level document", "[svg][image][entities]") {
  const std::string inner =
      "<!DOCTYPE svg [<!ENTITY green \"#00ff00\">]>"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"20\" height=\"10\">"
      "<rect width=\"20\" height=\"10\" fill=\"&green;\"/></svg>";
  const RenderedDocument nested = render(outer_document(inner));
  CHECK(is_green(nested.image.at(10, 5)));
  CHECK(nested.warnings.empty());
}

TEST_CASE("nested svg: an unknown encoding is not drawn, with a warning naming it",
          "[svg][image][encoding]") {
  const std::string inner =
      "<?xml version=\"1.0\" encoding=\"x-no-such-encoding\"?>"
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"20\" height=\"10\">"
      "<rect width=\"20\" height=\"10\" fill=\"#00ff00\"/></svg>";
  CHECK_FALSE(render_svg_document(inner, {}).is_ok());  // as a top-level document: an error
  const RenderedDocument nested = render(outer_document(inner));
  CHECK(nested.image.at(10, 5).a == 0);
  CHECK(contains(nested.warnings, "is not a well-formed SVG document"));
  CHECK(contains(nested.warnings, "x-no-such-encoding"));
}
