// Running the built curvescan binary from a test: exit code, stdout and stderr captured.
#pragma once

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "scratch_directory.h"

namespace curvescan::test {

struct CommandOutput {
  int exit_code = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

inline void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

inline std::string shell_quote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

/// The names in `dir`, sorted.
inline std::set<std::string> directory_listing(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

/// Runs `command` with /bin/sh, capturing stdout and stderr in files of `scratch`.
inline CommandOutput run_shell(const std::string& command, const std::filesystem::path& scratch) {
  const std::filesystem::path out = scratch / "stdout.txt", err = scratch / "stderr.txt";
  const std::string line = command + " >" + shell_quote(out.string()) + " 2>" + shell_quote(err.string());
  const int status = std::system(line.c_str());
  CommandOutput result;
  result.exit_code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : -1;
  result.out = read_text(out);
  result.err = read_text(err);
  return result;
}

inline std::string curvescan_binary() { return std::string(CURVESCAN_BINARY_DIR) + "/tools/curvescan"; }

/// Runs `curvescan <arguments>` (arguments already shell-quoted where needed).
inline CommandOutput run_curvescan(const std::string& arguments, const std::filesystem::path& scratch) {
  return run_shell(shell_quote(curvescan_binary()) + " " + arguments, scratch);
}

}  // namespace curvescan::test
