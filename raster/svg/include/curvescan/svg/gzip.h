// Gzip-compressed SVG (RFC 1952): `.svgz` files, gzip data on standard input, and `data:image/svg+xml`
// URIs whose bytes are gzip, as SVG 1.1 appendix J.2 and SVG 2 (1.2.2 "SVG MIME type, file name extension
// and Macintosh file type") name them. Recognised by the magic bytes, as rsvg-convert does, and inflated
// through zlib to a bound the caller gives, so a small "bomb" that would expand to gigabytes stops there.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "curvescan/status.h"

namespace curvescan::svg {

/// True when `data` starts with the gzip magic bytes 1f 8b (RFC 1952, section 2.3.1).
[[nodiscard]] bool is_gzip(std::string_view data) noexcept;

/// The uncompressed bytes of the gzip data `data`: every member, as gzip -d concatenates them (zero
/// bytes after the last member are padding). kLimitExceeded when they pass `max_bytes`; kCorruptInput
/// when the data is truncated or corrupt, or is followed by something that is not gzip. The messages
/// do not name the input: the caller does.
[[nodiscard]] Result<std::string> gunzip(std::string_view data, std::size_t max_bytes);

}  // namespace curvescan::svg
