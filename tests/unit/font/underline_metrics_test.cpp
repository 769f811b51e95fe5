// The underline metrics of FontMetrics against the font's own post table: OpenType defines
// post.underlinePosition as the top of the stroke (OpenType spec, post table), so the centre that
// FontMetrics::underline_position gives is half a thickness below it, exactly, whatever the thickness.
#include <catch2/catch.hpp>
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "curvescan/text/font.h"
#include "font_files.h"

using namespace curvescan;

namespace {

std::vector<unsigned char> file_bytes(const char* file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::uint32_t big_endian(const std::vector<unsigned char>& bytes, std::size_t at, int size) {
  std::uint32_t value = 0;
  for (int k = 0; k < size; ++k) value = value << 8 | bytes.at(at + static_cast<std::size_t>(k));
  return value;
}

// The offset of table `tag` in an sfnt file (OpenType spec, "Table directory": numTables at byte 4,
// 16-byte records from byte 12: tag, checksum, offset, length).
std::size_t table_offset(const std::vector<unsigned char>& font, const std::string& tag) {
  const std::uint32_t tables = big_endian(font, 4, 2);
  for (std::uint32_t t = 0; t < tables; ++t) {
    const std::size_t record = 12 + 16 * static_cast<std::size_t>(t);
    if (std::string(font.begin() + static_cast<std::ptrdiff_t>(record),
                    font.begin() + static_cast<std::ptrdiff_t>(record + 4)) == tag) {
      return big_endian(font, record + 8, 4);
    }
  }
  FAIL("no " << tag << " table");
  return 0;
}

// post.underlinePosition and post.underlineThickness, FWORDs at bytes 8 and 10 of the table (OpenType
// spec, post table header).
constexpr std::size_t kUnderlinePosition = 8;
constexpr std::size_t kUnderlineThickness = 10;

double fword(const std::vector<unsigned char>& font, std::size_t at) {
  return static_cast<std::int16_t>(static_cast<std::uint16_t>(big_endian(font, at, 2)));
}

}  // namespace

TEST_CASE("underline metrics: the centre is half the post table's thickness below its underlinePosition",
          "[font]") {
  const std::vector<unsigned char> bytes = file_bytes(kDejaVuSansFile);
  REQUIRE(bytes.size() > 12);
  const std::size_t post = table_offset(bytes, "post");
  const Result<Font> font = Font::from_bytes(bytes, 0, "DejaVuSans.ttf");
  REQUIRE(font.is_ok());
  const double top = fword(bytes, post + kUnderlinePosition);
  const double thickness = fword(bytes, post + kUnderlineThickness);
  REQUIRE(thickness > 0.0);
  // Font units are integers and the halves exact in binary: no tolerance.
  CHECK(font->metrics().underline_thickness == thickness);
  CHECK(font->metrics().underline_position == top - 0.5 * thickness);
}

// Regression: the centre was FreeType's face->underline_position, which halves the thickness in
// integers (its sfobjs.c), so a stroke 91 units thick had its centre 45 units below post.underlinePosition,
// not 45.5: the stroke stood half a unit above the place the font gives it.
TEST_CASE("underline metrics: an odd thickness keeps its half unit", "[font]") {
  std::vector<unsigned char> bytes = file_bytes(kDejaVuSansFile);
  REQUIRE(bytes.size() > 12);
  const std::size_t post = table_offset(bytes, "post");
  // The same font with post.underlineThickness = 91 (FreeType reads post without its checksum).
  bytes.at(post + kUnderlineThickness) = 0;
  bytes.at(post + kUnderlineThickness + 1) = 91;
  const double top = fword(bytes, post + kUnderlinePosition);
  const Result<Font> font = Font::from_bytes(bytes, 0, "DejaVuSans.ttf, underline 91 thick");
  REQUIRE(font.is_ok());
  CHECK(font->metrics().underline_thickness == 91.0);
  // The stroke's top edge is post.underlinePosition itself.
  CHECK(font->metrics().underline_position + 0.5 * font->metrics().underline_thickness == top);
  CHECK(font->metrics().underline_position == top - 45.5);
}
