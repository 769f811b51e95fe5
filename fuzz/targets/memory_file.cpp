#include "memory_file.h"

#include <sys/mman.h>
#include <unistd.h>

#include <string>

namespace curvescan::fuzz {

MemoryFile::MemoryFile(const std::uint8_t* data, std::size_t size) {
  fd_ = ::memfd_create("curvescan-fuzz", MFD_CLOEXEC);
  if (fd_ < 0) return;
  std::size_t written = 0;
  while (written < size) {
    const ssize_t n = ::write(fd_, data + written, size - written);
    if (n <= 0) return;  // path_ stays empty: the caller skips the input
    written += static_cast<std::size_t>(n);
  }
  path_ = "/proc/self/fd/" + std::to_string(fd_);
}

MemoryFile::~MemoryFile() {
  if (fd_ >= 0) ::close(fd_);
}

}  // namespace curvescan::fuzz
