// Fuzz target svg_document: a whole SVG document through render_svg_document.
//
// The output is at most 64 pixels wide (the height follows the document's aspect ratio) and the limits are
// small — 256 x 256 pixels, 20000 elements, nesting 64, <use> depth 8 — so that one input stays fast while
// every limit can still be reached by a small input (nested <use> multiplying elements, an extreme aspect
// ratio asking for a huge canvas). Exceeding a limit is a clean Error, which is what we check. The render
// budget is 2^16 segments, 64 MiB and 2^12 dashes (defaults: 2^22, 1 GiB, 2^20): a document whose shapes
// flatten or dash past what a 64-pixel image shows is refused by the same checks, in milliseconds
// instead of seconds; the defaults themselves are tested in tests/bad_input.
#include <cstdint>
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
  options.limits.render.max_segments = std::int64_t{1} << 16;
  options.limits.render.max_memory_bytes = std::int64_t{64} << 20;
  options.limits.render.max_dashes = std::int64_t{1} << 12;
  (void)svg::render_svg_document(xml, options);
  return 0;
}

}  // namespace curvescan::fuzz
