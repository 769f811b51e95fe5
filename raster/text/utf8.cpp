// Strict UTF-8 decoding, byte ranges from Unicode 15 table 3-7 (the same table RFC 3629 section 4 gives
// as ABNF): the second byte's allowed range depends on the first byte, which is what rules out overlong
// forms, surrogates and code points above U+10FFFF without any post-check.
#include "curvescan/text/utf8.h"

#include <cstdint>
#include <cstdio>
#include <string>

namespace curvescan {
namespace {

struct LeadByte {
  int continuation_bytes = 0;                         // how many bytes follow
  std::uint8_t second_min = 0x80, second_max = 0xBF;  // allowed range of the byte after the lead
  char32_t payload = 0;                               // the lead byte's code point bits
};

// Table 3-7 row by row; false for a byte that cannot start a sequence (80..C1, F5..FF).
bool classify_lead(std::uint8_t byte, LeadByte& lead) noexcept {
  if (byte >= 0xC2 && byte <= 0xDF)
    lead = {1, 0x80, 0xBF, char32_t{byte} & 0x1Fu};
  else if (byte == 0xE0)
    lead = {2, 0xA0, 0xBF, 0};
  else if (byte == 0xED)
    lead = {2, 0x80, 0x9F, 0xD};
  else if (byte >= 0xE1 && byte <= 0xEF)
    lead = {2, 0x80, 0xBF, char32_t{byte} & 0x0Fu};
  else if (byte == 0xF0)
    lead = {3, 0x90, 0xBF, 0};
  else if (byte >= 0xF1 && byte <= 0xF3)
    lead = {3, 0x80, 0xBF, char32_t{byte} & 0x07u};
  else if (byte == 0xF4)
    lead = {3, 0x80, 0x8F, 4};
  else
    return false;
  return true;
}

// "1st", "2nd", "3rd", "4th", ..., "11th", "12th", "13th", "21st": the position a reader counts.
std::string ordinal(std::size_t n) {
  const std::size_t tens = n % 100, units = n % 10;
  const char* suffix = (tens >= 11 && tens <= 13) ? "th"
                       : units == 1               ? "st"
                       : units == 2               ? "nd"
                       : units == 3               ? "rd"
                                                  : "th";
  return std::to_string(n) + suffix;
}

// The offset (from 0, as hex dumps and seek count) and the ordinal (from 1, as a reader counts) of the
// byte: "byte 2" alone was read as the second byte when it was the third.
Error invalid_at(std::size_t offset, std::uint8_t byte, const char* why) {
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned>(byte));
  return Error{ErrorKind::kInvalidArgument, "not valid UTF-8: byte " + std::string(hex) + " at offset " +
                                                std::to_string(offset) + " (the " + ordinal(offset + 1) +
                                                " byte) " + why};
}

// Why a byte cannot start a character (table 3-7 has no row for it).
const char* not_a_lead_byte(std::uint8_t byte) {
  if (byte < 0xC0) return "is a continuation byte without a lead byte before it";
  if (byte < 0xC2) return "would start an overlong form of a character below U+0080";
  if (byte < 0xF8) return "would start a character beyond U+10FFFF";
  return "never occurs in UTF-8";
}

}  // namespace

Result<std::u32string> decode_utf8(std::string_view text) {
  std::u32string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    const auto byte = static_cast<std::uint8_t>(text[i]);
    if (byte < 0x80) {
      out.push_back(byte);
      ++i;
      continue;
    }
    LeadByte lead;
    if (!classify_lead(byte, lead)) {
      return invalid_at(i, byte, not_a_lead_byte(byte));
    }
    char32_t code_point = lead.payload;
    for (int k = 1; k <= lead.continuation_bytes; ++k) {
      if (i + static_cast<std::size_t>(k) >= text.size()) {
        return invalid_at(i, byte, "starts a character that the text ends before completing");
      }
      const auto next = static_cast<std::uint8_t>(text[i + static_cast<std::size_t>(k)]);
      const std::uint8_t lo = k == 1 ? lead.second_min : 0x80, hi = k == 1 ? lead.second_max : 0xBF;
      if (next < lo || next > hi) {
        return invalid_at(
            i + static_cast<std::size_t>(k), next,
            "does not continue the character begun before it (ill-formed, overlong or a surrogate)");
      }
      code_point = (code_point << 6) | (char32_t{next} & 0x3Fu);
    }
    out.push_back(code_point);
    i += static_cast<std::size_t>(lead.continuation_bytes) + 1;
  }
  return out;
}

void append_utf8(std::string& out, char32_t c) {
  // RFC 3629 section 3: 1 to 4 bytes by the number of significant bits.
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

}  // namespace curvescan
