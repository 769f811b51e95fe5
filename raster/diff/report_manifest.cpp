// The manifest of a report directory and the pruning of stale files (contract in image_diff.h,
// update_report_manifest).
//
// A report directory is rewritten run after run: a file that failed yesterday and passes today leaves its
// images behind, and a reviewer then sees images of cases that no longer exist. Removing "everything under
// images/" would also remove what a user put there, so the report removes only what it can prove it wrote:
// each run lists its files in a manifest with their size and a content hash, and the next run removes a
// listed file it did not write again only while the file is still the very bytes it wrote. The hash is
// 64-bit FNV-1a (Fowler, Noll and Vo), not a cryptographic hash: it tells a file changed by accident or
// by a user apart from the report's own, which is all this needs.
//
// Manifest format, UTF-8 text: the line "curvescan report files 1", then one line per file,
// "<size in bytes> <hash, 16 hex digits> <path relative to the directory, percent-encoded>".
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <system_error>

#include "curvescan/diff/image_diff.h"

namespace curvescan {
namespace {

namespace fs = std::filesystem;

constexpr const char* kManifestHeader = "curvescan report files 1";

struct FileStamp {
  std::uintmax_t size = 0;
  std::uint64_t hash = 0;
};

/// Size and FNV-1a hash of a file's bytes; nullopt when it cannot be read.
std::optional<FileStamp> stamp_of(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  FileStamp stamp;
  stamp.hash = 0xcbf29ce484222325ULL;  // FNV-1a 64 offset basis
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    const auto count = static_cast<std::size_t>(in.gcount());
    for (std::size_t i = 0; i < count; ++i) {
      stamp.hash ^= static_cast<unsigned char>(buffer[i]);
      stamp.hash *= 0x100000001b3ULL;  // FNV-1a 64 prime
    }
    stamp.size += count;
  }
  if (in.bad()) return std::nullopt;
  return stamp;
}

int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

/// The inverse of relative_url(); nullopt for a malformed escape, and for a NUL byte (raw or %00): no path
/// holds one, and the system reads a path only up to it, so "index.html\0" would name the page the run just
/// wrote under a name that is not in its written list, and remove it.
std::optional<std::string> percent_decode(std::string_view text) {
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      out += text[i];
      continue;
    }
    if (i + 2 >= text.size()) return std::nullopt;
    const int high = hex_value(text[i + 1]), low = hex_value(text[i + 2]);
    if (high < 0 || low < 0) return std::nullopt;
    out += static_cast<char>(high * 16 + low);
    i += 2;
  }
  if (out.find('\0') != std::string::npos) return std::nullopt;
  return out;
}

/// A manifest path the pruning may touch: relative, no "." or ".." step, not the manifest itself.
bool is_safe_relative(const fs::path& path) {
  if (path.empty() || path.is_absolute() || path.has_root_name() || path.has_root_directory()) return false;
  for (const fs::path& step : path) {
    if (step == "." || step == ".." || step.empty()) return false;
  }
  return path.generic_string() != kReportManifestName;
}

bool is_within(const fs::path& path, const fs::path& directory) {
  auto d = directory.begin(), p = path.begin();
  for (; d != directory.end(); ++d, ++p) {
    if (p == path.end() || *d != *p) return false;
  }
  return p != path.end();  // strictly inside
}

struct ManifestLine {
  std::string path;
  FileStamp stamp;
};

/// The previous manifest's lines; empty when there is none or it is not a manifest of this format.
std::vector<ManifestLine> read_manifest(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string line;
  if (!in || !std::getline(in, line) || line != kManifestHeader) return {};
  std::vector<ManifestLine> lines;
  while (std::getline(in, line)) {
    unsigned long long size = 0, hash = 0;
    int consumed = 0;
    if (std::sscanf(line.c_str(), "%llu %16llx %n", &size, &hash, &consumed) != 2 || consumed <= 0) return {};
    const std::optional<std::string> path = percent_decode(std::string_view(line).substr(consumed));
    if (!path) return {};
    lines.push_back({*path, {size, hash}});
  }
  return lines;
}

}  // namespace

Result<ReportPruning> update_report_manifest(const fs::path& report_dir,
                                             const std::vector<std::string>& written) {
  std::error_code ec;
  const fs::path root = fs::canonical(report_dir, ec);
  if (ec) {
    return Error{ErrorKind::kIoError,
                 "cannot open the report directory '" + report_dir.string() + "': " + ec.message()};
  }
  const fs::path manifest = root / kReportManifestName;
  ReportPruning pruning;
  std::vector<std::string> sorted_written = written;
  for (std::string& path : sorted_written) path = fs::path(path).lexically_normal().generic_string();
  std::sort(sorted_written.begin(), sorted_written.end());

  for (const ManifestLine& old : read_manifest(manifest)) {
    const fs::path relative = fs::path(old.path).lexically_normal();
    if (!is_safe_relative(relative) ||
        std::binary_search(sorted_written.begin(), sorted_written.end(), relative.generic_string())) {
      continue;
    }
    const fs::path file = root / relative;
    const fs::file_status status = fs::symlink_status(file, ec);
    if (ec || status.type() == fs::file_type::not_found) continue;  // gone already
    // A parent directory replaced by a symbolic link could lead outside: resolve and check.
    const fs::path resolved = fs::weakly_canonical(file, ec);
    const std::optional<FileStamp> now =
        (!ec && status.type() == fs::file_type::regular && is_within(resolved, root)) ? stamp_of(file)
                                                                                      : std::nullopt;
    if (!now || now->size != old.stamp.size || now->hash != old.stamp.hash) {
      pruning.kept_changed.push_back(relative.generic_string());
      continue;
    }
    if (!fs::remove(file, ec) || ec) {
      return Error{ErrorKind::kIoError, "cannot remove the stale report file '" + file.string() +
                                            "': " + ec.message() +
                                            " (check the permissions of the report directory)"};
    }
    ++pruning.removed_files;
    for (fs::path dir = file.parent_path(); dir != root && is_within(dir, root); dir = dir.parent_path()) {
      if (fs::symlink_status(dir, ec).type() != fs::file_type::directory || !fs::is_empty(dir, ec) || ec)
        break;
      if (!fs::remove(dir, ec) || ec) break;  // an emptied directory left behind is harmless
      ++pruning.removed_directories;
    }
  }

  std::ostringstream text;
  text << kManifestHeader << "\n";
  for (const std::string& path : sorted_written) {
    const std::optional<FileStamp> stamp = stamp_of(root / path);
    if (!stamp) {
      return Error{ErrorKind::kIoError, "cannot read back the report file '" + (root / path).string() +
                                            "' to list it in " + kReportManifestName};
    }
    char head[64];
    std::snprintf(head, sizeof head, "%ju %016llx ", stamp->size,
                  static_cast<unsigned long long>(stamp->hash));
    text << head << relative_url(path) << "\n";
  }
  CURVESCAN_PROPAGATE(write_text_file_atomically(manifest, text.str()));
  return pruning;
}

}  // namespace curvescan
