#include "input_file.h"

#include <unistd.h>

#include "curvescan/raster/file_io.h"
#include "curvescan/raster/png_io.h"
#include "limit_options.h"

namespace curvescan::cli {
namespace {

Result<std::vector<std::uint8_t>> read_input_bytes(const std::string& path, std::size_t max_bytes) {
  const ReadBound bound{max_bytes, {}};
  Result<std::vector<std::uint8_t>> bytes =
      path == "-" ? read_descriptor_bounded(STDIN_FILENO, "<stdin>", bound) : read_file_bounded(path, bound);
  // Over the limit: the command line's own message, which names the flag that raises it.
  if (!bytes && bytes.error().kind == ErrorKind::kLimitExceeded)
    return input_too_large(path == "-" ? "<stdin>" : path, max_bytes);
  return bytes;
}

}  // namespace

Result<std::string> read_input(const std::string& path, std::size_t max_bytes) {
  Result<std::vector<std::uint8_t>> bytes = read_input_bytes(path, max_bytes);
  if (!bytes) return bytes.error();
  return std::string(bytes->begin(), bytes->end());
}

Result<Image> read_png_input(const std::string& path, std::size_t max_bytes, std::int64_t max_pixels,
                             const std::string& pixel_limit_hint) {
  const Result<std::vector<std::uint8_t>> bytes = read_input_bytes(path, max_bytes);
  if (!bytes) return bytes.error();
  Result<Image> image = decode_png(*bytes, max_pixels);
  const std::string name = path == "-" ? "<stdin>" : path;
  // The hint names the flag only when it is that bound, not the hard image limit, that refused the image.
  if (!image && image.error().kind == ErrorKind::kLimitExceeded && max_pixels < kMaxImagePixels &&
      !pixel_limit_hint.empty())
    return Error{ErrorKind::kLimitExceeded, "cannot read '" + name + "': " + image.error().message + "; " + pixel_limit_hint};
  if (!image) return Error{image.error().kind, "cannot read '" + name + "': " + image.error().message};
  return image;
}

}  // namespace curvescan::cli
