// The Vertical_Orientation property (UAX #50) that decides which characters of vertical text stand upright
// (CSS Writing Modes 3 5.1, text-orientation: mixed).
#include "svg/vertical_orientation.h"

#include <catch2/catch.hpp>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using curvescan::svg::detail::vertical_orientation;
using curvescan::svg::detail::VerticalOrientation;

TEST_CASE("emoji stand upright in vertical text, Latin letters turn (UAX #50)", "[svg][text][vertical]") {
  // Values from UAX #50's data (Unicode 15.0), one per kind of character.
  CHECK(vertical_orientation(U'A') == VerticalOrientation::kRotated);
  CHECK(vertical_orientation(U'\u0645') == VerticalOrientation::kRotated);      // Arabic letter meem
  CHECK(vertical_orientation(U'\u65E5') == VerticalOrientation::kUpright);      // CJK ideograph
  CHECK(vertical_orientation(U'\U0001F601') == VerticalOrientation::kUpright);  // grinning face (Emoticons)
  CHECK(vertical_orientation(U'\U0001F980') == VerticalOrientation::kUpright);  // crab (Supplemental Symbols)
  CHECK(vertical_orientation(U'\U0001F3F3') == VerticalOrientation::kUpright);  // white flag
  CHECK(vertical_orientation(U'\u00A9') == VerticalOrientation::kUpright);      // copyright sign
  CHECK(vertical_orientation(U'\u3041') == VerticalOrientation::kTransformedOrUpright);  // small hiragana a
  CHECK(vertical_orientation(U'\u3008') == VerticalOrientation::kTransformedOrRotated);  // left angle bracket
  CHECK(vertical_orientation(U'\u30FC') == VerticalOrientation::kTransformedOrRotated);  // long vowel mark
  CHECK(vertical_orientation(U'\U00020000') == VerticalOrientation::kUpright);           // plane 2 ideograph
  CHECK(vertical_orientation(U'\U000E0001') == VerticalOrientation::kRotated);           // language tag
  CHECK(vertical_orientation(U'\U0010FFFF') == VerticalOrientation::kRotated);  // noncharacter, unlisted
  CHECK(vertical_orientation(static_cast<char32_t>(0x110000)) == VerticalOrientation::kRotated);
  CHECK(vertical_orientation(static_cast<char32_t>(0xFFFFFFFF)) == VerticalOrientation::kRotated);
}

TEST_CASE("every code point has the Vertical_Orientation of the Unicode data file", "[svg][text][vertical]") {
  // The oracle is the Unicode Character Database file itself (Debian's unicode-data), read here with
  // its own rule: a code point it does not list is R.
  std::ifstream data("/usr/share/unicode/VerticalOrientation.txt");
  REQUIRE(data);
  std::vector<VerticalOrientation> expected(0x110000, VerticalOrientation::kRotated);
  std::string line;
  std::size_t listed = 0;
  while (std::getline(data, line)) {
    line = line.substr(0, line.find('#'));
    const auto semicolon = line.find(';');
    if (semicolon == std::string::npos) continue;
    const std::string code_points = line.substr(0, semicolon);
    std::istringstream value_stream(line.substr(semicolon + 1));
    std::string value;
    value_stream >> value;
    const auto dots = code_points.find("..");
    const auto hex = [](const std::string& digits) {
      return static_cast<std::uint32_t>(std::stoul(digits, nullptr, 16));
    };
    const std::uint32_t first = hex(code_points.substr(0, dots));
    const std::uint32_t last = dots == std::string::npos ? first : hex(code_points.substr(dots + 2));
    const VerticalOrientation v = value == "U"    ? VerticalOrientation::kUpright
                                  : value == "Tu" ? VerticalOrientation::kTransformedOrUpright
                                  : value == "Tr" ? VerticalOrientation::kTransformedOrRotated
                                                  : VerticalOrientation::kRotated;
    REQUIRE((value == "U" || value == "Tu" || value == "Tr" || value == "R"));
    REQUIRE(last < expected.size());
    for (std::uint32_t c = first; c <= last; ++c) expected[c] = v;
    ++listed;
  }
  REQUIRE(listed > 1000);  // the file was read, not an empty or truncated one
  std::size_t mismatches = 0;
  for (std::uint32_t c = 0; c < expected.size(); ++c) {
    if (vertical_orientation(static_cast<char32_t>(c)) != expected[c]) {
      if (mismatches++ < 10) FAIL_CHECK("U+" << std::hex << c << " has another Vertical_Orientation");
    }
  }
  CHECK(mismatches == 0);
}
