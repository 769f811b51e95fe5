// Line and column of a byte offset (source_positions.h).
#include "source_positions.h"

#include <algorithm>

namespace curvescan::svg::detail {

SourcePositions::SourcePositions(std::string_view text) : size_(text.size()) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n') line_starts_.push_back(i + 1);
  }
}

std::string SourcePositions::describe(std::ptrdiff_t offset) const {
  const std::size_t at = std::min(size_, static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, offset)));
  // The last line start at or before `at`; line_starts_ begins with 0, so there is one.
  const auto line = std::upper_bound(line_starts_.begin(), line_starts_.end(), at) - 1;
  return "line " + std::to_string(line - line_starts_.begin() + 1) + ", column " +
         std::to_string(at - *line + 1);
}

}  // namespace curvescan::svg::detail
