// The CSS tokenizer (CSS Syntax Module Level 3, section 4).
//
// Input is UTF-8. Preprocessing follows section 3.3: CR LF, CR and FF become LF, NUL becomes U+FFFD.
// Bytes >= 0x80 are treated as non-ASCII code points, which the spec counts as name code points (4.2), so
// identifiers in any script work without decoding the UTF-8. Comments produce no token (4.3.2). The
// tokenizer never fails: malformed input gives <bad-string>, <bad-url> or <delim> tokens, as specified,
// and the parser decides what to drop.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

#include "token.h"

namespace curvescan::svg::css {

/// Every token of `text`, in order; at most `max_tokens` of them (then TokenList::truncated is set), so
/// that the memory a hostile input costs is bounded whatever its shape (docs/limits.md).
[[nodiscard]] TokenList tokenize(std::string_view text, std::size_t max_tokens = SIZE_MAX);

/// The text of tokens [first, last) as CSS: whitespace collapsed to one space, comments dropped (a space
/// stands where a comment separated two tokens, so that "1/**/2" does not become "12"), identifiers with
/// their escapes resolved. Used for declaration values, which the property parsers read as text.
[[nodiscard]] std::string serialize_tokens(const TokenList& list, std::size_t first, std::size_t last);

}  // namespace curvescan::svg::css
