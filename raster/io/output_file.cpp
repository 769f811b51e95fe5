// Writing output files (contract in file_io.h).
//
// Why not simply open(path, O_TRUNC) as a shell does: a failure half way (disk full, a signal, a crash)
// would leave a truncated file where the user's previous one was. Why not always a temporary and a
// rename: a rename replaces whatever the name points at — as root, `-o /dev/null` would turn the device
// into a regular file, and `-o /dev/full` would "succeed". So the file type decides (lstat first).
//
// The temporaries of writes in progress sit in a fixed table of slots that a signal handler can walk
// without locks or allocation: a slot is claimed with a compare-and-swap, filled, then published; the
// handler unlinks the published ones. A path is registered before its file is created, so there is no
// moment when the file exists and the handler does not know it (unlinking a name not yet created is
// harmless: it is random).
#include "curvescan/raster/file_io.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <system_error>

#include "quoted_path.h"

namespace curvescan {
namespace {

using detail::quoted;

std::string system_message(int error_number) {
  return std::error_code(error_number, std::generic_category()).message();
}

Error io_error(std::string message) { return Error{ErrorKind::kIoError, std::move(message)}; }

// ---- The table of temporaries in progress --------------------------------------------------------------

constexpr int kFreeSlot = 0, kClaimedSlot = 1, kPublishedSlot = 2;
struct TemporarySlot {
  std::atomic<int> state{kFreeSlot};
  std::array<char, PATH_MAX> path{};
};
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs a lock-free flag");
// More writes in flight than this (threads of a batch) still work; only their cleanup on a signal is lost.
constexpr std::size_t kTemporarySlots = 64;
std::array<TemporarySlot, kTemporarySlots> temporary_slots;

// Returns the slot index, or -1 when the table is full or the path too long to keep.
int register_temporary(const std::string& path) {
  if (path.size() >= PATH_MAX) return -1;
  for (std::size_t i = 0; i < temporary_slots.size(); ++i) {
    int expected = kFreeSlot;
    if (temporary_slots[i].state.compare_exchange_strong(expected, kClaimedSlot, std::memory_order_acquire)) {
      std::memcpy(temporary_slots[i].path.data(), path.c_str(), path.size() + 1);
      temporary_slots[i].state.store(kPublishedSlot, std::memory_order_release);
      return static_cast<int>(i);
    }
  }
  return -1;
}

void unregister_temporary(int slot) {
  if (slot >= 0) temporary_slots[static_cast<std::size_t>(slot)].state.store(kFreeSlot, std::memory_order_release);
}

// ---- Writing ------------------------------------------------------------------------------------------

// Writes everything or returns the errno of the failure (0 on success).
int write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(fd, data, size);
    if (written < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return 0;
}

// 16 random hex digits: a name another process cannot predict and plant a link at.
std::string random_suffix() {
  std::uint64_t bits = 0;
  if (::getrandom(&bits, sizeof bits, 0) != static_cast<ssize_t>(sizeof bits)) {
    bits = static_cast<std::uint64_t>(::getpid()) * 0x9E3779B97F4A7C15ull ^
           static_cast<std::uint64_t>(reinterpret_cast<std::uintptr_t>(&bits));
  }
  static constexpr char kHex[] = "0123456789abcdef";
  std::string text(16, '0');
  for (char& c : text) {
    c = kHex[bits & 15];
    bits >>= 4;
  }
  return text;
}

// The atomic replacement of a regular file (or the creation of a new one). `existing` is the target's
// stat when it exists, to carry its mode and owner over.
Status replace_regular_file(const std::filesystem::path& target, const struct stat* existing,
                            std::string_view bytes, const std::filesystem::path& shown_as) {
  const std::filesystem::path directory = target.has_parent_path() ? target.parent_path() : ".";
  std::string temporary;
  int fd = -1, slot = -1;
  for (int attempt = 0; attempt < 8 && fd < 0; ++attempt) {
    std::string name = ".";  // appended piece by piece: see quoted()
    name += target.filename().string();
    name += ".tmp-";
    name += random_suffix();
    temporary = (directory / name).string();
    slot = register_temporary(temporary);
    fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0) {
      const int why = errno;
      unregister_temporary(slot);
      if (why != EEXIST) {
        return io_error("cannot write " + quoted(shown_as) + ": cannot create a file in " + quoted(directory) +
                        ": " + system_message(why));
      }
    }
  }
  if (fd < 0) return io_error("cannot write " + quoted(shown_as) + ": no free temporary name in its directory");

  if (existing != nullptr) {
    // Best effort, as a rewrite in place would keep them: a failure here is no reason to fail the write.
    (void)::fchmod(fd, existing->st_mode & 07777);
    if (::geteuid() == 0) (void)::fchown(fd, existing->st_uid, existing->st_gid);
  }
  int failure = write_all(fd, bytes.data(), bytes.size());
  const char* failed_step = "cannot write";
  if (failure == 0 && ::fsync(fd) != 0 && errno != EINVAL) {  // EINVAL: a file system without fsync
    failure = errno;
    failed_step = "cannot flush";
  }
  if (::close(fd) != 0 && failure == 0) {
    failure = errno;
    failed_step = "cannot close";
  }
  if (failure == 0 && std::rename(temporary.c_str(), target.c_str()) != 0) {
    failure = errno;
    failed_step = "cannot replace";
  }
  if (failure != 0) ::unlink(temporary.c_str());
  unregister_temporary(slot);
  if (failure != 0) return io_error(std::string(failed_step) + " " + quoted(shown_as) + ": " + system_message(failure));
  return Status::ok();
}

// A device, FIFO or other non-regular file: written through, as a shell's `>` would.
Status write_through(const std::filesystem::path& target, std::string_view bytes,
                     const std::filesystem::path& shown_as) {
  int fd;
  do {
    fd = ::open(target.c_str(), O_WRONLY | O_NOCTTY | O_CLOEXEC);
  } while (fd < 0 && errno == EINTR);
  if (fd < 0) return io_error("cannot open " + quoted(shown_as) + " for writing: " + system_message(errno));
  int failure = write_all(fd, bytes.data(), bytes.size());
  if (::close(fd) != 0 && failure == 0 && errno != EINTR) failure = errno;
  if (failure != 0) return io_error("cannot write " + quoted(shown_as) + ": " + system_message(failure));
  return Status::ok();
}

std::string describe_file_type(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a file curvescan can write";
}

}  // namespace

Status write_output_file(const std::filesystem::path& path, std::string_view bytes) {
  if (path.empty()) return Error{ErrorKind::kInvalidArgument, "cannot write: the output path is empty"};
  struct stat link_status {};
  if (::lstat(path.c_str(), &link_status) != 0) {
    if (errno != ENOENT) return io_error("cannot write " + quoted(path) + ": " + system_message(errno));
    if (!path.has_filename()) return io_error("cannot write " + quoted(path) + ": it names a directory");
    return replace_regular_file(path, nullptr, bytes, path);
  }

  std::filesystem::path target = path;
  struct stat status = link_status;
  if (S_ISLNK(link_status.st_mode)) {
    char resolved[PATH_MAX];
    if (::realpath(path.c_str(), resolved) == nullptr) {
      const int why = errno;
      if (why == ENOENT) {
        return io_error("cannot write " + quoted(path) +
                        ": it is a symbolic link to a file that does not exist (curvescan does not create files "
                        "through dangling links; remove the link or write to its target)");
      }
      return io_error("cannot write " + quoted(path) + ": cannot follow the symbolic link: " + system_message(why));
    }
    target = resolved;
    if (::stat(target.c_str(), &status) != 0)
      return io_error("cannot write " + quoted(path) + ": " + system_message(errno));
  }

  if (S_ISREG(status.st_mode)) return replace_regular_file(target, &status, bytes, path);
  if (S_ISCHR(status.st_mode) || S_ISBLK(status.st_mode) || S_ISFIFO(status.st_mode))
    return write_through(target, bytes, path);
  return io_error("cannot write " + quoted(path) + ": it is " + describe_file_type(status.st_mode));
}

Status write_output_file(const std::filesystem::path& path, std::span<const std::uint8_t> bytes) {
  return write_output_file(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

Status write_to_descriptor(int fd, std::string_view bytes, std::string_view name) {
  if (const int failure = write_all(fd, bytes.data(), bytes.size()); failure != 0)
    return io_error("cannot write to " + std::string(name) + ": " + system_message(failure));
  return Status::ok();
}

void remove_temporary_output_files() noexcept {
  for (TemporarySlot& slot : temporary_slots) {
    if (slot.state.load(std::memory_order_acquire) == kPublishedSlot) ::unlink(slot.path.data());
  }
}

}  // namespace curvescan
