// Writing a finished output file: the one way curvescan puts bytes on disk (PNG images, reports, JSON).
//
// What `path` names decides how it is written, the way a careful shell redirection would:
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

#include <cstdint>
#include <filesystem>
#include <span>
#include <string_view>

#include "curvescan/status.h"

namespace curvescan {

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
