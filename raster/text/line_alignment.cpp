// The lines of a layout as one block aligned at each line's start (text_layout.h, align_lines_at_start).
#include <algorithm>

#include "curvescan/text/text_layout.h"

namespace curvescan {

void align_lines_at_start(TextLayout& layout) noexcept {
  if (layout.vertical || layout.lines.empty()) return;
  const auto mixed = std::any_of(layout.lines.begin(), layout.lines.end(), [&](const TextLine& line) {
    return line.right_to_left != layout.lines.front().right_to_left;
  });
  if (!mixed) return;
  double left = layout.lines.front().origin.x, width = 0.0;
  for (const TextLine& line : layout.lines) {
    left = std::min(left, line.origin.x);
    width = std::max(width, line.advance);
  }
  for (TextLine& line : layout.lines) {
    const double start = line.right_to_left ? left + width - line.advance : left;
    const Vec2 shift{start - line.origin.x, 0.0};
    line.origin += shift;
    for (std::size_t g = line.first_glyph; g < line.first_glyph + line.glyph_count; ++g) {
      layout.glyphs[g].origin += shift;
    }
  }
}

}  // namespace curvescan
