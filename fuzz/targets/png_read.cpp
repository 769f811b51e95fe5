// Fuzz target png_read: a PNG file through decode_png (libpng with curvescan's error handling and size
// limits), in memory: read_png only adds a bounded read of the file before the same call, and skipping
// the file makes each execution several times cheaper.
#include <span>

#include "curvescan/raster/png_io.h"
#include "fuzz_targets.h"

namespace curvescan::fuzz {

int fuzz_png_read(const std::uint8_t* data, std::size_t size) {
  const Result<Image> image = decode_png(std::span<const std::uint8_t>(data, size));
  if (image) {
    // Touch every pixel, so that a size that does not match the storage shows up under ASan.
    unsigned sum = 0;
    for (const Rgba8 pixel : image->pixels()) sum += pixel.a;
    (void)sum;
  }
  return 0;
}

}  // namespace curvescan::fuzz
