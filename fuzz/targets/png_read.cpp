// Fuzz target png_read: a PNG file through read_png (libpng with curvescan's error handling and size
// limits). The bytes are handed over as a file (memory_file.h), since read_png reads a path.
#include "curvescan/raster/png_io.h"
#include "fuzz_targets.h"
#include "memory_file.h"

namespace curvescan::fuzz {

int fuzz_png_read(const std::uint8_t* data, std::size_t size) {
  const MemoryFile file(data, size);
  if (file.path().empty()) return 0;
  const Result<Image> image = read_png(file.path());
  if (image) {
    // Touch every pixel, so that a size that does not match the storage shows up under ASan.
    unsigned sum = 0;
    for (const Rgba8 pixel : image->pixels()) sum += pixel.a;
    (void)sum;
  }
  return 0;
}

}  // namespace curvescan::fuzz
