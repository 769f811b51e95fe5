// Fuzz target svg_document: a whole SVG document through render_svg_document.
//
// The output is at most 64 pixels wide (the height follows the document's aspect ratio) and the limits are
// small — 256 x 256 pixels, 20000 elements, nesting 64, <use> depth 8 — so that one input stays fast while
// every limit can still be reached by a small input (nested <use> multiplying elements, an extreme aspect
// ratio asking for a huge canvas). Exceeding a limit is a clean Error, which is what we check.
#include <string_view>

#include "curvescan/svg/document.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {

int fuzz_svg_document(const std::uint8_t* data, std::size_t size) {
  const std::string_view xml(reinterpret_cast<const char*>(data), size);  // bytes as characters
  svg::RenderOptions options;
  options.width = 64.0;
  options.limits.max_pixels = 256 * 256;
  options.limits.max_elements = 20'000;
  options.limits.max_depth = 64;
  options.limits.max_use_depth = 8;
  (void)svg::render_svg_document(xml, options);
  return 0;
}

}  // namespace curvescan::fuzz
