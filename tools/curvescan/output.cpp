#include "output.h"

#include <unistd.h>

#include <cstdint>
#include <vector>

#include "curvescan/raster/file_io.h"
#include "curvescan/raster/png_io.h"

namespace curvescan::cli {

Status write_output(const std::string& path, std::string_view bytes) {
  if (path == "-") return write_to_descriptor(STDOUT_FILENO, bytes, "standard output");
  return write_output_file(path, bytes);
}

Status write_png_output(const std::string& path, const Image& image) {
  const Result<std::vector<std::uint8_t>> png = encode_png(image);
  if (!png) return Error{png.error().kind, "cannot write '" + path + "': " + png.error().message};
  return write_output(path, std::string_view(reinterpret_cast<const char*>(png->data()), png->size()));
}

}  // namespace curvescan::cli
