// How the io/ messages name a file: 'path', in single quotes.
#pragma once

#include <filesystem>
#include <string>

namespace curvescan::detail {

// Built by appending: g++ 12 at -O3 reports a false -Wrestrict overlap for "'" + std::string.
inline std::string quoted(const std::filesystem::path& path) {
  std::string text = "'";
  text += path.string();
  text += '\'';
  return text;
}

}  // namespace curvescan::detail
