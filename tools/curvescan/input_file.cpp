#include "input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <span>
#include <system_error>

#include <unistd.h>

#include "curvescan/raster/png_io.h"
#include "limit_options.h"

namespace curvescan::cli {
namespace {

Error io_error(const std::string& what, const std::string& path) {
  return Error{ErrorKind::kIoError, what + " '" + path + "': " + std::strerror(errno)};
}

Result<std::string> read_stream(std::istream& in, const std::string& name, std::size_t max_bytes) {
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes) {
      return input_too_large(name, max_bytes);
    }
  }
  if (in.bad()) return io_error("cannot read", name);
  return text;
}

}  // namespace

Result<std::string> read_input(const std::string& path, std::size_t max_bytes) {
  if (path == "-") return read_stream(std::cin, "<stdin>", max_bytes);
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    return Error{ErrorKind::kIoError, "cannot read '" + path + "': it is a directory"};
  }
  if (std::filesystem::is_regular_file(path, ec)) {
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (!ec && size > max_bytes) return input_too_large(path, max_bytes);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) return Error{ErrorKind::kIoError, "cannot open '" + path + "' for reading: " + std::strerror(errno)};
  return read_stream(in, path, max_bytes);
}

Result<Image> read_png_input(const std::string& path, std::size_t max_bytes, std::int64_t max_pixels,
                             const std::string& pixel_limit_hint) {
  const Result<std::string> bytes = read_input(path, max_bytes);
  if (!bytes) return bytes.error();
  const std::span<const std::uint8_t> data(reinterpret_cast<const std::uint8_t*>(bytes->data()), bytes->size());
  Result<Image> image = decode_png(data, max_pixels);
  const std::string name = path == "-" ? "<stdin>" : path;
  // The hint names the flag only when it is that bound, not the hard image limit, that refused the image.
  if (!image && image.error().kind == ErrorKind::kLimitExceeded && max_pixels < kMaxImagePixels &&
      !pixel_limit_hint.empty())
    return Error{ErrorKind::kLimitExceeded, "cannot read '" + name + "': " + image.error().message + "; " + pixel_limit_hint};
  if (!image) return Error{image.error().kind, "cannot read '" + name + "': " + image.error().message};
  return image;
}

}  // namespace curvescan::cli
