// A test's own directory under the system temporary directory, removed with its content when the test
// leaves the scope: also when an assertion fails or throws, so a test run leaves nothing in /tmp.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <random>
#include <string>
#include <system_error>

namespace curvescan::test {

/// Converts to the directory's path, so it can be passed wherever a path is taken. Keep the object
/// (`const auto dir = scratch_directory("x");`), not a copy of its path: a `std::filesystem::path`
/// initialized from the call outlives the object, whose directory is removed at the end of that line.
class ScratchDirectory {
 public:
  explicit ScratchDirectory(const std::string& tag) {
    std::random_device entropy;
    path_ = std::filesystem::temp_directory_path() /
            ("curvescan-" + tag + "-" + std::to_string(::getpid()) + "-" + std::to_string(entropy()));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    // A test may have taken the owner's write permission away to provoke an error; give it back first.
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all, std::filesystem::perm_options::add,
                                 ignored);
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  operator const std::filesystem::path&() const { return path_; }  // NOLINT(google-explicit-constructor)
  [[nodiscard]] std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  [[nodiscard]] std::string string() const { return path_.string(); }
  [[nodiscard]] const char* c_str() const { return path_.c_str(); }

 private:
  std::filesystem::path path_;
};

/// A fresh empty directory named after `tag`, removed at the end of the caller's scope.
inline ScratchDirectory scratch_directory(const std::string& tag) {
  return ScratchDirectory(tag);
}

}  // namespace curvescan::test
