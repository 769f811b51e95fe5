// Where the bytes of an <image> come from (SVG 1.1 section 5.7, SVG 2 "The image element"): a data: URI
// (RFC 2397), decoded here, or a file relative to the document when the caller allows it. Nothing is
// ever read from the network: any other scheme (http:, https:, ftp:, ...) is refused.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace curvescan::svg::detail {

/// The payload of "data:[<mediatype>][;base64],<data>": base64 decoded (white space ignored, as in
/// HTML's forgiving decoder) or percent-decoded. nullopt when `uri` is not a well-formed data URI.
[[nodiscard]] std::optional<std::vector<std::uint8_t>> decode_data_uri(std::string_view uri);

/// What an image's bytes look like, by their signature (the media type of a data URI is not trusted:
/// files in the wild label PNGs as image/jpg and the other way round).
enum class ImageFormat { kPng, kJpeg, kGif, kWebp, kSvg, kUnknown };

/// Whether `format` is a raster format (decoded to pixels), as opposed to SVG or unknown bytes.
[[nodiscard]] constexpr bool is_raster_format(ImageFormat format) noexcept {
  return format == ImageFormat::kPng || format == ImageFormat::kJpeg || format == ImageFormat::kGif ||
         format == ImageFormat::kWebp;
}
[[nodiscard]] ImageFormat sniff_image_format(const std::vector<std::uint8_t>& bytes);

/// The bytes an href refers to, or the reason they are not read (a message for a warning).
struct ImageBytes {
  std::vector<std::uint8_t> bytes;
  std::string refused;  ///< non-empty: not loaded, and why
};

/// Resolves `href`: a data URI is decoded; a relative file reference is read from `base_directory` when
/// one is given (an absolute path, or one that climbs out of the directory with "..", is refused), at
/// most `max_bytes` of it (`limit_name` names that bound in the error); everything else is refused with a
/// message.
[[nodiscard]] ImageBytes load_image_source(std::string_view href,
                                           const std::optional<std::filesystem::path>& base_directory,
                                           std::size_t max_bytes, std::string_view limit_name);

}  // namespace curvescan::svg::detail
