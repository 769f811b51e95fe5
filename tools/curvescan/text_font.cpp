#include "text_font.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <filesystem>
#include <string_view>

#include "curvescan/text/font_lookup.h"

namespace curvescan::cli {
namespace {

bool looks_like_a_path(const std::string& argument) {
  if (argument.find('/') != std::string::npos) return true;
  std::string lower = argument;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  constexpr std::array<std::string_view, 6> kExtensions{".ttf", ".otf", ".ttc", ".otc", ".pfb", ".woff"};
  return std::any_of(kExtensions.begin(), kExtensions.end(),
                     [&](std::string_view e) { return lower.ends_with(e); });
}

}  // namespace

Result<Font> open_font_argument(const std::string& file_or_family, int weight, bool italic) {
  std::error_code error;
  // Anything that exists is opened as a file: Font::open refuses what is not a regular file (a device
  // such as /dev/zero, a FIFO) by its type, and reads a regular one with its size bound.
  // So is a symbolic link that leads nowhere (dangling, or a loop): its own error says why it cannot be
  // read, where a family lookup would claim no family of that name is installed.
  if (std::filesystem::exists(file_or_family, error) ||
      std::filesystem::is_symlink(std::filesystem::symlink_status(file_or_family, error)))
    return Font::open(file_or_family);
  if (looks_like_a_path(file_or_family)) {
    return Error{ErrorKind::kIoError, "font file '" + file_or_family + "' does not exist"};
  }
  return load_font({file_or_family, weight, italic}, /*allow_fallback=*/false);
}

}  // namespace curvescan::cli
