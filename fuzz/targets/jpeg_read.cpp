// Fuzz target jpeg_read: a JPEG file through decode_jpeg (libjpeg-turbo with curvescan's error handling
// and size limits), as an SVG <image> or <feImage> decodes one. libjpeg reports errors through a longjmp
// out of the decoder; what it allocated must be released and nothing read past the bytes.
#include <span>

#include "fuzz_targets.h"
#include "svg/jpeg_decode.h"

namespace curvescan::fuzz {

int fuzz_jpeg_read(const std::uint8_t* data, std::size_t size) {
  // 2^20 pixels: larger images are refused from their header, before their pixels are allocated (what
  // the limit itself does is tested at the default size in tests/unit/svg).
  const Result<Image> image = svg::detail::decode_jpeg(std::span<const std::uint8_t>(data, size), 1 << 20);
  if (image) {
    // Touch every pixel, so that a size that does not match the storage shows up under ASan.
    unsigned sum = 0;
    for (const Rgba8 pixel : image->pixels()) sum += pixel.r;
    (void)sum;
  }
  return 0;
}

}  // namespace curvescan::fuzz
