// Font files read once per process while they stay the same.
//
// Every document of a batch render opened its fonts again, and Font::open read the whole file each time
// (DejaVu Sans is 757 kB; reading it was 5.7 % of a batch of resvg's small text documents,
// docs/benchmarks.md). The bytes of a file are now kept, shared and read-only, by every Font made from it:
// FreeType and HarfBuzz only read them (font_face_p.h). An entry is keyed by the file's path and what
// stat(2) says of it — device, inode, size and modification time — so a font replaced or edited on disk
// is read again. The kept files are bounded: past kMaxCachedBytes the least recently used are dropped
// (a Font still using their bytes keeps them alive through its shared pointer).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include "curvescan/status.h"

namespace curvescan::detail {

using FontFileBytes = std::shared_ptr<const std::vector<std::uint8_t>>;

/// The whole of the regular file `file`, at most `max_bytes` long (read_file_bounded's errors), from the
/// process's cache when the file has not changed since it was read. Thread-safe.
[[nodiscard]] Result<FontFileBytes> read_font_file_cached(const std::filesystem::path& file,
                                                          std::size_t max_bytes);

/// The total size of the files kept, for tests.
[[nodiscard]] std::size_t cached_font_file_bytes() noexcept;

inline constexpr std::size_t kMaxCachedFontFileBytes = std::size_t{64} << 20;

}  // namespace curvescan::detail
