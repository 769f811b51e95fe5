// Legacy character encodings converted to UTF-8 before parsing (xml_encoding.h).
#include "xml_encoding.h"

#include <iconv.h>

#include <cerrno>
#include <memory>
#include <string>
#include <utility>

#include "css/syntax.h"

namespace curvescan::svg::detail {
namespace {

bool is_space(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

// UTF-8 and what is read as it: ASCII is a subset. UTF-16 documents begin with a byte order mark or
// "<\0?\0", never with the ASCII bytes "<?xml" that declared_encoding looks for; pugixml reads them.
bool needs_no_conversion(std::string_view name) noexcept {
  for (const std::string_view same : {"utf-8", "utf8", "us-ascii", "ascii", "utf-16", "utf-16le", "utf-16be"})
    if (css::ascii_equal_ignoring_case(name, same)) return true;
  return false;
}

// Where the encoding name of the declaration lies in `xml` (offset, length), or length 0.
std::pair<std::size_t, std::size_t> encoding_span(std::string_view xml) noexcept {
  // XML 1.0 [23] XMLDecl ::= '<?xml' VersionInfo EncodingDecl? SDDecl? S? '?>', at offset 0.
  if (xml.substr(0, 5) != "<?xml" || xml.size() < 6 || !is_space(xml[5])) return {0, 0};
  const std::size_t end = xml.find("?>");
  if (end == std::string_view::npos) return {0, 0};
  const std::string_view declaration = xml.substr(0, end);
  // [80] EncodingDecl ::= S 'encoding' Eq ('"' EncName '"' | "'" EncName "'")
  std::size_t at = declaration.find("encoding");
  while (at != std::string_view::npos && !is_space(declaration[at - 1]))
    at = declaration.find("encoding", at + 1);
  if (at == std::string_view::npos) return {0, 0};
  std::size_t i = at + 8;
  while (i < declaration.size() && is_space(declaration[i])) ++i;
  if (i >= declaration.size() || declaration[i] != '=') return {0, 0};
  ++i;
  while (i < declaration.size() && is_space(declaration[i])) ++i;
  if (i >= declaration.size() || (declaration[i] != '"' && declaration[i] != '\'')) return {0, 0};
  const char quote = declaration[i++];
  const std::size_t close = declaration.find(quote, i);
  if (close == std::string_view::npos) return {0, 0};
  return {i, close - i};
}

struct IconvCloser {
  void operator()(void* handle) const noexcept { iconv_close(static_cast<iconv_t>(handle)); }
};

}  // namespace

std::string_view declared_encoding(std::string_view xml) noexcept {
  const auto [offset, length] = encoding_span(xml);
  return xml.substr(offset, length);
}

Result<std::optional<std::string>> transcode_to_utf8(std::string_view xml, std::int64_t max_bytes) {
  const auto [offset, length] = encoding_span(xml);
  if (length == 0) return std::optional<std::string>{};
  const std::string name(xml.substr(offset, length));
  if (needs_no_conversion(name)) return std::optional<std::string>{};
  const iconv_t opened = iconv_open("UTF-8", name.c_str());
  if (opened == reinterpret_cast<iconv_t>(-1)) {
    return Error{ErrorKind::kCorruptInput, "the document's encoding '" + name + "' is not known"};
  }
  const std::unique_ptr<void, IconvCloser> converter(opened);
  // The declaration is ASCII in every encoding it can be read in: copied with its name replaced.
  std::string out(xml.substr(0, offset));
  out += "UTF-8";
  const std::size_t body_start = offset + length;
  std::string_view rest = xml.substr(body_start);
  char* in = const_cast<char*>(rest.data());  // iconv's interface; it does not write the input
  std::size_t in_left = rest.size();
  char buffer[1 << 14];
  while (in_left > 0) {
    char* out_at = buffer;
    std::size_t out_left = sizeof buffer;
    const std::size_t result = iconv(opened, &in, &in_left, &out_at, &out_left);
    out.append(buffer, sizeof buffer - out_left);
    if (static_cast<std::int64_t>(out.size()) > max_bytes) {
      return Error{ErrorKind::kLimitExceeded,
                   "the document converted to UTF-8 needs more than the memory limit"};
    }
    if (result == static_cast<std::size_t>(-1) && errno != E2BIG) {
      return Error{ErrorKind::kCorruptInput, "the document is not valid " + name + " text (byte " +
                                                 std::to_string(static_cast<std::size_t>(in - xml.data())) +
                                                 ")"};
    }
  }
  return std::optional<std::string>{std::move(out)};
}

}  // namespace curvescan::svg::detail
