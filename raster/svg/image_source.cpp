// data: URIs and the file policy of <image> (image_source.h).
#include "image_source.h"

#include <algorithm>
#include <cctype>

#include "curvescan/raster/file_io.h"
#include "gif_decode.h"
#include "webp_decode.h"

namespace curvescan::svg::detail {
namespace {

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+' || c == '-') return 62;  // '-' and '_': the URL-safe alphabet, seen in the wild
  if (c == '/' || c == '_') return 63;
  return -1;
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f';
}

std::optional<std::vector<std::uint8_t>> decode_base64(std::string_view text) {
  std::vector<std::uint8_t> out;
  out.reserve(text.size() / 4 * 3);
  unsigned buffer = 0;
  int bits = 0;
  for (const char c : text) {
    if (is_space(c)) continue;
    if (c == '=') break;  // padding ends the data
    const int value = base64_value(c);
    if (value < 0) return std::nullopt;
    buffer = (buffer << 6) | static_cast<unsigned>(value);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<std::uint8_t>((buffer >> bits) & 0xffu));
    }
  }
  return out;
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

std::vector<std::uint8_t> decode_percent(std::string_view text) {
  std::vector<std::uint8_t> out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '%' && i + 2 < text.size() && hex_value(text[i + 1]) >= 0 && hex_value(text[i + 2]) >= 0) {
      out.push_back(static_cast<std::uint8_t>(hex_value(text[i + 1]) * 16 + hex_value(text[i + 2])));
      i += 2;
    } else {
      out.push_back(static_cast<std::uint8_t>(text[i]));
    }
  }
  return out;
}

bool starts_with_ignoring_case(std::string_view text, std::string_view prefix) {
  return text.size() >= prefix.size() &&
         std::equal(prefix.begin(), prefix.end(), text.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
         });
}

}  // namespace

std::optional<std::vector<std::uint8_t>> decode_data_uri(std::string_view uri) {
  while (!uri.empty() && is_space(uri.front())) uri.remove_prefix(1);
  if (!starts_with_ignoring_case(uri, "data:")) return std::nullopt;
  uri.remove_prefix(5);
  const std::size_t comma = uri.find(',');
  if (comma == std::string_view::npos) return std::nullopt;
  std::string_view header = uri.substr(0, comma);
  while (!header.empty() && is_space(header.back())) header.remove_suffix(1);
  const bool base64 =
      header.size() >= 7 && starts_with_ignoring_case(header.substr(header.size() - 7), ";base64");
  const std::string_view payload = uri.substr(comma + 1);
  if (base64) return decode_base64(payload);
  return decode_percent(payload);
}

ImageFormat sniff_image_format(const std::vector<std::uint8_t>& bytes) {
  static constexpr std::uint8_t kPng[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (bytes.size() >= 8 && std::equal(std::begin(kPng), std::end(kPng), bytes.begin()))
    return ImageFormat::kPng;
  if (bytes.size() >= 3 && bytes[0] == 0xff && bytes[1] == 0xd8 && bytes[2] == 0xff)
    return ImageFormat::kJpeg;
  if (is_gif(bytes)) return ImageFormat::kGif;
  if (is_webp(bytes)) return ImageFormat::kWebp;
  // SVG is text: an XML declaration, a comment, a doctype or the root, after optional white space or BOM.
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()),
                              std::min<std::size_t>(bytes.size(), 4096));
  const std::size_t start = text.find_first_not_of(" \t\r\n\xef\xbb\xbf");
  if (start != std::string_view::npos && text[start] == '<' && text.find("<svg") != std::string_view::npos)
    return ImageFormat::kSvg;
  return ImageFormat::kUnknown;
}

ImageBytes load_image_source(std::string_view href,
                             const std::optional<std::filesystem::path>& base_directory,
                             std::size_t max_bytes, std::string_view limit_name) {
  ImageBytes result;
  if (starts_with_ignoring_case(href, "data:")) {
    std::optional<std::vector<std::uint8_t>> bytes = decode_data_uri(href);
    if (bytes) {
      result.bytes = std::move(*bytes);
    } else {
      result.refused = "its data: URI is malformed";
    }
    return result;
  }
  // A scheme (RFC 3986: letter, then letters, digits, '+', '-', '.', then ':') other than file: is a
  // network or unknown resource: never read. A one-letter "scheme" is a Windows drive, not a URI.
  const std::size_t colon = href.find(':');
  const std::size_t slash = href.find('/');
  if (colon != std::string_view::npos && colon > 1 && (slash == std::string_view::npos || colon < slash)) {
    if (!starts_with_ignoring_case(href, "file:")) {
      result.refused = "'" + std::string(href.substr(0, colon)) + ":' resources are never fetched";
      return result;
    }
  }
  if (!base_directory) {
    result.refused = "external files are not read (allow files beside the document with --allow-files)";
    return result;
  }
  std::string_view path_text = href;
  if (starts_with_ignoring_case(path_text, "file:")) path_text.remove_prefix(5);
  const std::vector<std::uint8_t> path_bytes = decode_percent(path_text);
  const std::string decoded(path_bytes.begin(), path_bytes.end());
  const std::filesystem::path relative(decoded);
  if (relative.empty() || relative.is_absolute() || relative.has_root_name() ||
      relative.has_root_directory()) {
    result.refused = "only paths relative to the document are read";
    return result;
  }
  for (const auto& part : relative.lexically_normal()) {
    if (part == "..") {
      result.refused = "paths leaving the document's directory are not read";
      return result;
    }
  }
  // Regular files only: a FIFO or a device named by a document must not make the render wait or read
  // forever.
  Result<std::vector<std::uint8_t>> bytes = read_file_bounded(
      *base_directory / relative, ReadBound{max_bytes, limit_name, FileKinds::kRegularOnly});
  if (!bytes) {
    result.refused = bytes.error().message;
    return result;
  }
  result.bytes = std::move(*bytes);
  return result;
}

}  // namespace curvescan::svg::detail
