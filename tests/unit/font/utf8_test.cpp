// decode_utf8 against Unicode 15 table 3-7: every well-formed boundary, every ill-formed class refused
// with the offending byte's offset.
#include "curvescan/text/utf8.h"

#include <catch2/catch.hpp>
#include <random>
#include <string>
#include <utility>

using curvescan::append_utf8;
using curvescan::decode_utf8;
using curvescan::Result;

TEST_CASE("utf8: ASCII, two-, three- and four-byte characters at the ends of their ranges", "[font][utf8]") {
  const Result<std::u32string> text =
      decode_utf8("A\xC2\x80\xDF\xBF\xE0\xA0\x80\xEF\xBF\xBF\xF0\x90\x80\x80\xF4\x8F\xBF\xBF");
  REQUIRE(text.is_ok());
  CHECK(*text ==
        std::u32string{U'A', U'\u0080', U'\u07FF', U'\u0800', U'\uFFFF', U'\U00010000', U'\U0010FFFF'});
}

TEST_CASE("utf8: the empty string and an embedded NUL decode", "[font][utf8]") {
  CHECK(decode_utf8("")->empty());
  CHECK(*decode_utf8(std::string("a\0b", 3)) == std::u32string(U"a\0b", 3));
}

TEST_CASE("utf8: ill-formed sequences are refused with the byte offset", "[font][utf8]") {
  struct Case {
    std::string bytes;
    const char* offset_text;
  };
  const Case cases[] = {
      {"ab\x80", "at offset 2 (the 3rd byte)"},            // stray continuation byte
      {"\xC0\xAF", "at offset 0 (the 1st byte)"},          // overlong two-byte lead
      {"\xC1\xBF", "at offset 0 (the 1st byte)"},          // overlong two-byte lead
      {"\xE0\x9F\xBF", "at offset 1 (the 2nd byte)"},      // overlong three-byte form
      {"\xED\xA0\x80", "at offset 1 (the 2nd byte)"},      // UTF-16 surrogate U+D800
      {"\xF0\x8F\xBF\xBF", "at offset 1 (the 2nd byte)"},  // overlong four-byte form
      {"\xF4\x90\x80\x80", "at offset 1 (the 2nd byte)"},  // above U+10FFFF
      {"\xF5\x80\x80\x80", "at offset 0 (the 1st byte)"},  // lead byte beyond U+10FFFF
      {"\xFF", "at offset 0 (the 1st byte)"},              // never valid
      {"x\xE2\x82", "at offset 1 (the 2nd byte)"},         // truncated at the end
      {"\xE2\x28\xA1", "at offset 1 (the 2nd byte)"},      // continuation missing
  };
  for (const Case& c : cases) {
    const Result<std::u32string> text = decode_utf8(c.bytes);
    INFO(c.offset_text);
    REQUIRE_FALSE(text.is_ok());
    CHECK(text.error().kind == curvescan::ErrorKind::kInvalidArgument);
    CHECK(text.error().message.find(c.offset_text) != std::string::npos);
  }
}

TEST_CASE("utf8: the message gives the byte, its offset from 0, its place from 1, and why", "[font][utf8]") {
  // "byte 2" alone read as the second byte when it was the third: the offset (as hex dumps count) and the
  // place (as a reader counts) are both given.
  const auto message = [](const std::string& bytes) { return decode_utf8(bytes).error().message; };
  CHECK(message("ab\x80") ==
        "not valid UTF-8: byte 0x80 at offset 2 (the 3rd byte) is a continuation byte without a lead byte "
        "before it");
  CHECK(message("\xC0\xAF") ==
        "not valid UTF-8: byte 0xC0 at offset 0 (the 1st byte) would start an overlong form of a character "
        "below "
        "U+0080");
  CHECK(message("\xF5\x80\x80\x80") ==
        "not valid UTF-8: byte 0xF5 at offset 0 (the 1st byte) would start a character beyond U+10FFFF");
  CHECK(message("\xFE") == "not valid UTF-8: byte 0xFE at offset 0 (the 1st byte) never occurs in UTF-8");
  CHECK(message("x\xE2\x82") ==
        "not valid UTF-8: byte 0xE2 at offset 1 (the 2nd byte) starts a character that the text ends before "
        "completing");
  CHECK(message(std::string(10, 'a') + "\xFF").find("(the 11th byte)") != std::string::npos);
  CHECK(message(std::string(11, 'a') + "\xFF").find("(the 12th byte)") != std::string::npos);
  CHECK(message(std::string(20, 'a') + "\xFF").find("(the 21st byte)") != std::string::npos);
  CHECK(message(std::string(111, 'a') + "\xFF").find("(the 112th byte)") != std::string::npos);
  CHECK(message(std::string(121, 'a') + "\xFF").find("(the 122nd byte)") != std::string::npos);
}

TEST_CASE("utf8: random code points survive an encode/decode round trip", "[font][utf8]") {
  std::mt19937 rng(8);
  std::uniform_int_distribution<std::uint32_t> any(0, 0x10FFFF);
  std::u32string expected;
  std::string encoded;
  while (expected.size() < 20000) {
    const char32_t c = any(rng);
    if (c >= 0xD800 && c <= 0xDFFF) continue;  // surrogates are not characters
    expected.push_back(c);
    // Encoding by the table, independent of the decoder.
    if (c < 0x80) {
      encoded += static_cast<char>(c);
    } else if (c < 0x800) {
      encoded += static_cast<char>(0xC0 | (c >> 6));
      encoded += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      encoded += static_cast<char>(0xE0 | (c >> 12));
      encoded += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      encoded += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      encoded += static_cast<char>(0xF0 | (c >> 18));
      encoded += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      encoded += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      encoded += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  const Result<std::u32string> decoded = decode_utf8(encoded);
  REQUIRE(decoded.is_ok());
  CHECK(*decoded == expected);
}

TEST_CASE("append_utf8 writes RFC 3629's bytes for each length, and decode_utf8 reads them back") {
  const std::pair<char32_t, std::string> known[] = {
      {U'A', "A"},
      {0x7F, "\x7F"},
      {0xE9, "\xC3\xA9"},
      {0x7FF, "\xDF\xBF"},
      {0x20AC, "\xE2\x82\xAC"},
      {0xFFFD, "\xEF\xBF\xBD"},
      {0x1F600, "\xF0\x9F\x98\x80"},
      {0x10FFFF, "\xF4\x8F\xBF\xBF"},
  };
  for (const auto& [c, bytes] : known) {
    std::string out;
    append_utf8(out, c);
    CHECK(out == bytes);
    const Result<std::u32string> back = decode_utf8(out);
    REQUIRE(back.is_ok());
    CHECK(*back == std::u32string(1, c));
  }
}
