// MemoryFile: fuzz bytes made available under a file path, for the readers that only take a path
// (read_png). Backed by an anonymous memfd (Linux), so nothing is left on disk when a run crashes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace curvescan::fuzz {

class MemoryFile {
 public:
  /// A file holding exactly `size` bytes of `data`; path() is empty if the memfd could not be made.
  MemoryFile(const std::uint8_t* data, std::size_t size);
  MemoryFile(const MemoryFile&) = delete;
  MemoryFile& operator=(const MemoryFile&) = delete;
  ~MemoryFile();

  /// "/proc/self/fd/<n>", readable by any path-taking reader of this process.
  [[nodiscard]] const std::filesystem::path& path() const noexcept { return path_; }

 private:
  int fd_ = -1;
  std::filesystem::path path_;
};

}  // namespace curvescan::fuzz
