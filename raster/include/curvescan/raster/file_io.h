// Reading and writing whole files: the one way curvescan takes bytes from disk (SVG, PNG, fonts,
// images, style sheets) and puts them there (PNG images, reports, JSON).
//
// Reading (read_file_bounded) stops at a size bound whatever the file is: at most the bound plus one
// byte is ever read, so a FIFO, a device such as /dev/zero or a file that grows while it is read ends
// with a clear error instead of filling memory; a regular file already larger is refused from its size
// before anything is read.
//
// Writing: what `path` names decides how it is written, the way a careful shell redirection would:
// - nothing yet, or a regular file: the bytes go to a new temporary file in the same directory (created
//   with O_CREAT | O_EXCL | O_NOFOLLOW under an unpredictable name), are flushed to the disk (fsync) and
//   only then renamed over `path`. An existing file keeps its permission bits (and, for root, its owner);
//   on any failure it is left exactly as it was and the temporary is removed.
// - a device, FIFO or socket (`/dev/null`, `/dev/stdout`, a named pipe): opened and written through, never
//   replaced; every write and the close are checked, so `/dev/full` reports "No space left on device".
// - a symbolic link: followed to the file it names, which is then written as above; the link itself stays.
//   A link that names nothing (dangling, or a loop) is refused: curvescan does not create files at the end
//   of a link it cannot resolve.
// - a directory: refused.
//
// The temporary files of writes in progress are known to remove_temporary_output_files(), which a program
// calls from its SIGINT/SIGTERM/SIGHUP handler so that an interrupted write leaves nothing behind.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>
#include <vector>

#include "curvescan/status.h"

namespace curvescan {

/// Which files read_file_bounded reads.
enum class FileKinds {
  kAny,           ///< regular files, FIFOs and devices (what a user may point a command-line input at)
  kRegularOnly,   ///< regular files only: a FIFO or device is refused without waiting for a writer
};

/// What read_file_bounded may read: at most `max_bytes`; `limit_name` says which limit that is in the
/// error ("the font file size limit", "the input size limit (raise --max-input-size)").
struct ReadBound {
  std::size_t max_bytes = 0;
  std::string_view limit_name;
  FileKinds kinds = FileKinds::kAny;
};

/// Reads the whole of `path` into memory within `bound`. Errors name the path: "cannot open 'a.png' for
/// reading: No such file or directory", "cannot read 'a.png': it is a directory", "... it is a FIFO, not a regular file",
/// "... it is larger than 64 MiB, the PNG file size limit" (kind kLimitExceeded).
[[nodiscard]] Result<std::vector<std::uint8_t>> read_file_bounded(const std::filesystem::path& path,
                                                                  const ReadBound& bound);
/// The same from an open descriptor (e.g. 0, standard input), called `name` in errors.
[[nodiscard]] Result<std::vector<std::uint8_t>> read_descriptor_bounded(int fd, std::string_view name,
                                                                        const ReadBound& bound);

/// Writes `bytes` to `path` as described at the top of this header. Errors name the path and the
/// system's reason ("cannot write 'out.png': No space left on device").
[[nodiscard]] Status write_output_file(const std::filesystem::path& path, std::span<const std::uint8_t> bytes);
[[nodiscard]] Status write_output_file(const std::filesystem::path& path, std::string_view bytes);

/// Writes all of `bytes` to the open descriptor `fd` (e.g. 1, standard output), retrying short writes and
/// EINTR. `name` is how errors call it ("cannot write to standard output: Broken pipe").
[[nodiscard]] Status write_to_descriptor(int fd, std::string_view bytes, std::string_view name);

/// Removes the temporary files of the writes in progress. Async-signal-safe: it only calls unlink(2),
/// for a signal handler to call before the program exits.
void remove_temporary_output_files() noexcept;

}  // namespace curvescan
