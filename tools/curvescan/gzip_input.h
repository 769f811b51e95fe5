// gzip-compressed SVG (.svgz, or gzip data on standard input), recognised by its magic bytes as
// rsvg-convert does, and inflated through zlib with the same size limit as an uncompressed input, so a
// small compressed file cannot expand without bound (a "zip bomb" stops at --max-input-size).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "curvescan/status.h"

namespace curvescan::cli {

/// True when `data` starts with the gzip magic bytes 1f 8b (RFC 1952, section 2.3.1).
[[nodiscard]] bool is_gzip(std::string_view data) noexcept;

/// The uncompressed bytes of the gzip data `data` (every member, as gzip -d concatenates them).
/// kLimitExceeded when they pass `max_bytes` (input_too_large's message for `name`), kCorruptInput when
/// the data is truncated or corrupt.
[[nodiscard]] Result<std::string> gunzip(std::string_view data, std::size_t max_bytes, const std::string& name);

}  // namespace curvescan::cli
