// Documents in a legacy character encoding (XML 1.0 section 4.3.3 "Character Encoding in Entities"): a
// document whose XML declaration names an encoding other than UTF-8, UTF-16 or US-ASCII -- windows-1251,
// ISO-8859-2, KOI8-R, Shift_JIS... as older editors wrote them -- is converted to UTF-8 before it is
// parsed, with glibc's iconv, which knows every encoding of the IANA registry that matters here. pugixml
// itself reads only the Unicode encodings and ISO-8859-1.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "curvescan/status.h"

namespace curvescan::svg::detail {

/// The encoding name of `xml`'s XML declaration (`<?xml version="1.0" encoding="..."?>` at the very
/// start, without a byte order mark), or an empty view when it declares none.
[[nodiscard]] std::string_view declared_encoding(std::string_view xml) noexcept;

/// `xml` converted to UTF-8 when its declaration names another encoding than UTF-8, UTF-16 or
/// US-ASCII (and their aliases), with the declaration's encoding then reading "UTF-8"; nullopt when
/// nothing needs converting. kCorruptInput for an encoding iconv does not know, or bytes that are not
/// valid in the declared one; kLimitExceeded when the UTF-8 text would pass `max_bytes`.
[[nodiscard]] Result<std::optional<std::string>> transcode_to_utf8(std::string_view xml,
                                                                   std::int64_t max_bytes);

}  // namespace curvescan::svg::detail
