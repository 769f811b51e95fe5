// Gzip-compressed image data (RFC 1952), as SVG 1.1 appendix J.2 and SVG 2 (1.2.2 "SVG MIME type, file
// name extension and Macintosh file type") name it for compressed SVG documents: `.svgz` files and
// `data:image/svg+xml` URIs whose bytes are gzip. Inflated with zlib, to a bound given by the caller, so a
// small "bomb" that would expand to gigabytes is refused after `max_bytes` of output.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace curvescan::svg::detail {

/// Whether `bytes` begin with the gzip signature (1F 8B, RFC 1952 2.3.1).
[[nodiscard]] bool is_gzip(const std::vector<std::uint8_t>& bytes) noexcept;

/// The inflated content of the gzip stream `bytes` (its first member), or an empty result with `error`
/// set: corrupt or truncated data, or more than `max_bytes` of output.
struct Gunzipped {
  std::vector<std::uint8_t> bytes;
  std::string error;  ///< non-empty: not inflated, and why
};
[[nodiscard]] Gunzipped gunzip(const std::vector<std::uint8_t>& bytes, std::size_t max_bytes);

}  // namespace curvescan::svg::detail
