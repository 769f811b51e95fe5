// Positions in the document's text for messages: "line L, column C" of a byte offset, such as the one
// pugixml records for each node (xml_node::offset_debug). Lines and columns count from 1; columns count
// bytes, as the positions of XML errors and of style sheet warnings do.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace curvescan::svg::detail {

/// The offsets where the lines of a text begin, found once so that each position is a binary search
/// instead of a scan from the start (a document with thousands of invalid values stays linear).
class SourcePositions {
 public:
  SourcePositions() = default;
  explicit SourcePositions(std::string_view text);

  /// "line L, column C" of byte `offset`; an offset outside the text is clamped to its end.
  [[nodiscard]] std::string describe(std::ptrdiff_t offset) const;

  /// Bytes held, for the document's memory count.
  [[nodiscard]] std::size_t memory_bytes() const noexcept {
    return line_starts_.capacity() * sizeof(std::size_t);
  }

 private:
  std::vector<std::size_t> line_starts_{0};
  std::size_t size_ = 0;
};

}  // namespace curvescan::svg::detail
