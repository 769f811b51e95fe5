// Reading whole files within a size bound (contract in file_io.h).
//
// read(2) in chunks rather than an istream: the loop asks for at most one byte past the bound, so the
// bound holds for FIFOs, devices and growing files alike, and errno is the system's own reason. A file
// that must be regular is opened with O_NONBLOCK (a FIFO would otherwise block in open() until a writer
// came) and checked with fstat on the descriptor itself, so a name swapped between check and open cannot
// slip a FIFO past the check; O_NONBLOCK is then cleared for the read.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <string>
#include <system_error>

#include "curvescan/raster/file_io.h"
#include "quoted_path.h"

namespace curvescan {
namespace {

using detail::quoted;

std::string system_message(int error_number) {
  return std::error_code(error_number, std::generic_category()).message();
}

std::string byte_count_text(std::size_t bytes) {
  constexpr std::size_t kMiB = std::size_t{1} << 20;
  return bytes % kMiB == 0 ? std::to_string(bytes / kMiB) + " MiB" : std::to_string(bytes) + " bytes";
}

Error too_large(const std::string& name, const ReadBound& bound) {
  std::string message = "cannot read " + name + ": it is larger than " + byte_count_text(bound.max_bytes);
  if (!bound.limit_name.empty()) {
    message += ", ";
    message += bound.limit_name;
  }
  return Error{ErrorKind::kLimitExceeded, std::move(message)};
}

// The kind of a non-regular file, as a user would name it.
std::string file_kind_name(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

struct DescriptorCloser {
  int fd;
  ~DescriptorCloser() { ::close(fd); }
};

// Reads `fd` to its end, at most bound.max_bytes (one byte more proves the input is larger). `reserve`
// is the size a regular file announced, so the vector is allocated once.
Result<std::vector<std::uint8_t>> read_all(int fd, const std::string& name, const ReadBound& bound,
                                           std::size_t reserve) {
  std::vector<std::uint8_t> bytes;
  bytes.reserve(reserve + 1);
  constexpr std::size_t kChunkBytes = std::size_t{1} << 16;
  for (;;) {
    const std::size_t before = bytes.size();
    // Written so that max_bytes = SIZE_MAX does not wrap.
    const std::size_t left = bound.max_bytes - before;
    const std::size_t want = left >= kChunkBytes ? kChunkBytes : left + 1;
    bytes.resize(before + want);
    const ssize_t got = ::read(fd, bytes.data() + before, want);
    if (got < 0) {
      bytes.resize(before);
      if (errno == EINTR) continue;
      return Error{ErrorKind::kIoError, "cannot read " + name + ": " + system_message(errno)};
    }
    bytes.resize(before + static_cast<std::size_t>(got));
    if (got == 0) return bytes;
    if (bytes.size() > bound.max_bytes) return too_large(name, bound);
  }
}

}  // namespace

Result<std::vector<std::uint8_t>> read_file_bounded(const std::filesystem::path& path, const ReadBound& bound) {
  const std::string name = quoted(path);
  const bool regular_only = bound.kinds == FileKinds::kRegularOnly;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | (regular_only ? O_NONBLOCK : 0));
  if (fd < 0) return Error{ErrorKind::kIoError, "cannot open " + name + " for reading: " + system_message(errno)};
  const DescriptorCloser closer{fd};
  struct stat status {};
  if (::fstat(fd, &status) != 0) {
    return Error{ErrorKind::kIoError, "cannot read " + name + ": " + system_message(errno)};
  }
  if (S_ISDIR(status.st_mode)) return Error{ErrorKind::kIoError, "cannot read " + name + ": it is a directory"};
  const bool regular = S_ISREG(status.st_mode);
  if (regular_only && !regular) {
    return Error{ErrorKind::kInvalidArgument,
                 "cannot read " + name + ": it is " + file_kind_name(status.st_mode) + ", not a regular file"};
  }
  if (regular_only) (void)::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  std::size_t reserve = 0;
  if (regular) {
    if (static_cast<std::uintmax_t>(status.st_size) > bound.max_bytes) return too_large(name, bound);
    reserve = static_cast<std::size_t>(status.st_size);
  }
  return read_all(fd, name, bound, reserve);
}

Result<std::vector<std::uint8_t>> read_descriptor_bounded(int fd, std::string_view name, const ReadBound& bound) {
  return read_all(fd, std::string(name), bound, 0);
}

}  // namespace curvescan
