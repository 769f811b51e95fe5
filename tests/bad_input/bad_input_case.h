// The bad-input corpus runner: one table entry = one curvescan command on one bad input, with the exit
// code and a message it must give, run twice:
//   1. with no output file: after a failure, no output file (and no temporary file) may exist;
//   2. with an existing output file: after a failure, it must be left byte for byte as it was.
// After a success (exit 0, e.g. a document with a reference cycle that SVG says to skip with a warning)
// the output must exist and be a whole file of its kind (a PNG read_png accepts, or JSON).
//
// Placeholders in `arguments`: {in} the input file (written from `input`, or made as `input_kind` says),
// {out} the output path, {dir} the case's scratch directory.
#pragma once

#include <catch2/catch.hpp>
#include <filesystem>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "curvescan/raster/png_io.h"
#include "run_command.h"

namespace curvescan::test {

enum class InputKind {
  kFile,       ///< `input` written to {in}
  kDirectory,  ///< {in} is an empty directory
  kMissing,    ///< {in} does not exist
};

enum class OutputKind { kPng, kJson, kNone };

struct BadInputCase {
  std::string name;       ///< what the entry checks, shown on failure
  std::string arguments;  ///< the command line after "curvescan", with placeholders
  std::string input;      ///< the bytes of {in}
  int exit_code = 3;
  std::string message;  ///< ECMAScript regex that must match somewhere in stderr
  InputKind input_kind = InputKind::kFile;
  std::string input_name = "input";  ///< file name of {in} (extensions matter to `text --font`)
  OutputKind output_kind = OutputKind::kPng;
  std::string output_name = "out";  ///< file name of {out} inside the scratch directory
  /// Other files the command reads, written into the scratch directory ({dir}/name) first.
  std::vector<std::pair<std::string, std::string>> extra_files = {};
};

inline std::string replace_all(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

inline std::set<std::string> directory_listing(const std::filesystem::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.insert(entry.path().filename().string());
  return names;
}

/// Runs one entry in a fresh scratch directory, with `existing_output` (empty: none) at {out} first.
inline void run_bad_input_once(const BadInputCase& c, const std::string& existing_output) {
  const std::filesystem::path dir = scratch_directory("bad-input");
  const std::filesystem::path input = dir / c.input_name;
  const std::filesystem::path output = dir / c.output_name;
  if (c.input_kind == InputKind::kFile) write_text(input, c.input);
  if (c.input_kind == InputKind::kDirectory) std::filesystem::create_directories(input);
  for (const auto& [name, bytes] : c.extra_files) write_text(dir / name, bytes);
  if (!existing_output.empty()) write_text(output, existing_output);
  std::string arguments = replace_all(c.arguments, "{in}", shell_quote(input.string()));
  arguments = replace_all(arguments, "{out}", shell_quote(output.string()));
  arguments = replace_all(arguments, "{dir}", shell_quote(dir.string()));
  // The command's own stdout/stderr files go to a sibling directory, so that the listing below sees
  // only what the command made.
  const std::filesystem::path capture = scratch_directory("bad-input-capture");
  const std::set<std::string> before = directory_listing(dir);
  const CommandOutput result = run_curvescan(arguments, capture);

  INFO("case: " << c.name << "\ncommand: curvescan " << arguments << "\nexisting output: "
                << (existing_output.empty() ? "no" : "yes") << "\nstderr: " << result.err);
  CHECK(result.exit_code == c.exit_code);
  CHECK(std::regex_search(result.err, std::regex(c.message)));
  if (result.exit_code == 3) {
    // One line naming the subcommand ("curvescan render: error: ..."), nothing else.
    CHECK(std::regex_match(result.err, std::regex("curvescan( [a-z]+)?: error: [^\n]+\n")));
  }
  if (c.exit_code != 0) {
    std::set<std::string> after = directory_listing(dir);
    if (existing_output.empty()) {
      CHECK(after == before);  // no output file, no temporary left behind
    } else {
      CHECK(after == before);
      CHECK(read_text(output) == existing_output);
    }
  } else if (c.output_kind == OutputKind::kPng) {
    const Result<Image> image = read_png(output);
    CHECK(image.is_ok());
  } else if (c.output_kind == OutputKind::kJson) {
    const std::string json = read_text(output);
    CHECK(!json.empty());
    CHECK(json.back() == '\n');
  }
  std::filesystem::remove_all(dir);
  std::filesystem::remove_all(capture);
}

/// Runs every entry of `cases` without and with an existing output file.
inline void run_bad_inputs(const std::vector<BadInputCase>& cases) {
  for (const BadInputCase& c : cases) {
    run_bad_input_once(c, "");
    if (c.exit_code != 0) run_bad_input_once(c, "an existing output file that a failure must not touch\n");
  }
}

}  // namespace curvescan::test
