// Fuzz target image_read: the bytes of an SVG <image> through the decoders that are not fuzzed elsewhere
// -- GIF (giflib's record reader with curvescan's frame placement) and WebP (libwebp), each with its
// limits (svgz inflation has its own target, gzip_input). Each decoder refuses bytes without its signature at
// once, so one input exercises whichever format it looks like.
#include <span>

#include "fuzz_targets.h"
#include "svg/gif_decode.h"
#include "svg/webp_decode.h"

namespace curvescan::fuzz {

namespace {

void touch(const Result<Image>& image) {
  if (!image) return;
  // Every pixel read, so that a size that does not match the storage shows up under ASan.
  unsigned sum = 0;
  for (const Rgba8 pixel : image->pixels()) sum += pixel.a;
  (void)sum;
}

}  // namespace

int fuzz_image_read(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  // 2^20 pixels: larger is refused before it is allocated (the limits themselves are tested in
  // tests/unit/svg).
  touch(svg::detail::decode_gif(bytes, 1 << 20));
  touch(svg::detail::decode_webp(bytes, 1 << 20));
  return 0;
}

}  // namespace curvescan::fuzz
