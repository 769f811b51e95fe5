// parse_svg_glyph_tree (svg_glyph_document.h).
#include "svg_glyph_document.h"

#include <algorithm>
#include <string>
#include <utility>

#include "curvescan/svg/gzip.h"

namespace curvescan::svg::detail {

Status parse_svg_glyph_tree(std::string_view stored, std::int64_t max_memory_bytes, SvgTree& tree) {
  std::string inflated;
  std::string_view text = stored;
  if (is_gzip(text)) {
    Result<std::string> unpacked =
        gunzip(text, static_cast<std::size_t>(std::max<std::int64_t>(max_memory_bytes, 0)));
    if (!unpacked && unpacked.error().kind == ErrorKind::kLimitExceeded) return unpacked.error();
    if (!unpacked)
      return Error{ErrorKind::kCorruptInput, "cannot be inflated (" + unpacked.error().message + ")"};
    inflated = std::move(unpacked).value();
    text = inflated;
  }
  const Status parsed = parse_svg_tree(text, max_memory_bytes, tree);
  if (!parsed && parsed.error().kind == ErrorKind::kLimitExceeded) return parsed;
  if (!parsed) {
    return Error{ErrorKind::kCorruptInput,
                 "is not a well-formed SVG document (" + parsed.error().message + ")"};
  }
  return Status::ok();
}

}  // namespace curvescan::svg::detail
