// The process's cache of font file bytes (font_file_cache_p.h).
#include <sys/stat.h>

#include <list>
#include <mutex>
#include <optional>
#include <string>

#include "curvescan/raster/file_io.h"
#include "font_file_cache_p.h"

namespace curvescan::detail {
namespace {

// What identifies one version of one file: its path as given and stat(2)'s answer.
struct FileVersion {
  std::string path;
  dev_t device = 0;
  ino_t inode = 0;
  off_t size = 0;
  std::int64_t modified_ns = 0;
  bool operator==(const FileVersion&) const = default;
};

std::optional<FileVersion> version_of(const std::filesystem::path& file) {
  struct stat info {};
  if (::stat(file.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return std::nullopt;
  return FileVersion{file.string(), info.st_dev, info.st_ino, info.st_size,
                     std::int64_t{info.st_mtim.tv_sec} * 1'000'000'000 + info.st_mtim.tv_nsec};
}

struct Entry {
  FileVersion version;
  FontFileBytes bytes;
};

// Most recently used first. A handful of fonts per process is the common case, so a list searched from
// the front is enough; the bound on bytes keeps it short.
struct Cache {
  std::mutex lock;
  std::list<Entry> entries;
  std::size_t bytes = 0;
};

Cache& cache() {
  static Cache the_cache;
  return the_cache;
}

}  // namespace

Result<FontFileBytes> read_font_file_cached(const std::filesystem::path& file, std::size_t max_bytes) {
  const std::optional<FileVersion> version = version_of(file);
  Cache& kept = cache();
  if (version) {
    const std::lock_guard<std::mutex> guard(kept.lock);
    for (auto entry = kept.entries.begin(); entry != kept.entries.end(); ++entry) {
      if (entry->version == *version && entry->bytes->size() <= max_bytes) {
        kept.entries.splice(kept.entries.begin(), kept.entries, entry);
        return kept.entries.front().bytes;
      }
    }
  }
  // Read outside the lock, so that one thread's read does not hold up another's lookup; two threads that
  // read the same file at once keep the first copy inserted.
  Result<std::vector<std::uint8_t>> read =
      read_file_bounded(file, ReadBound{max_bytes, "the font file size limit", FileKinds::kRegularOnly});
  if (!read) return read.error();
  FontFileBytes bytes = std::make_shared<const std::vector<std::uint8_t>>(std::move(*read));
  // A file that changed while it was read, or a file larger than the whole cache, is not kept.
  if (version && version_of(file) == version && bytes->size() <= kMaxCachedFontFileBytes &&
      static_cast<off_t>(bytes->size()) == version->size) {
    const std::lock_guard<std::mutex> guard(kept.lock);
    for (const Entry& entry : kept.entries) {
      if (entry.version == *version) return entry.bytes;
    }
    kept.entries.push_front(Entry{*version, bytes});
    kept.bytes += bytes->size();
    while (kept.bytes > kMaxCachedFontFileBytes) {
      kept.bytes -= kept.entries.back().bytes->size();
      kept.entries.pop_back();
    }
  }
  return bytes;
}

std::size_t cached_font_file_bytes() noexcept {
  Cache& kept = cache();
  const std::lock_guard<std::mutex> guard(kept.lock);
  return kept.bytes;
}

}  // namespace curvescan::detail
