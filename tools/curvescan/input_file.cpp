#include "input_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <system_error>

#include <unistd.h>

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
  std::ifstream in(path, std::ios::binary);
  if (!in) return io_error("cannot open", path);
  return read_stream(in, path, max_bytes);
}

}  // namespace curvescan::cli
