// UTF-8 for text input: strict decoding, with an error that points at the offending byte; and encoding.
#pragma once

#include <string>
#include <string_view>

#include "curvescan/status.h"

namespace curvescan {

/// Decodes `text` as UTF-8 (RFC 3629, Unicode 15 section 3.9 table 3-7 "well-formed UTF-8 byte
/// sequences"). Refuses, with kInvalidArgument and the byte offset in the message, every ill-formed
/// sequence: a stray continuation byte, a truncated sequence, an overlong form (C0, C1, E0 80..9F,
/// F0 80..8F), a UTF-16 surrogate (ED A0..BF) and anything above U+10FFFF (F4 90.., F5..FF). A leading
/// byte-order mark is kept (it is U+FEFF, a valid character); callers that want to drop it do so.
[[nodiscard]] Result<std::u32string> decode_utf8(std::string_view text);

/// Appends the UTF-8 encoding of `c` (at most U+10FFFF; callers check) to `out`.
void append_utf8(std::string& out, char32_t c);

}  // namespace curvescan
