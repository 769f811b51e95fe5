// Each subcommand registers itself on the root CLI11 app and, when chosen, stores its exit code.
#pragma once

#include <CLI/CLI.hpp>

namespace curvescan::cli {

/// What --version prints.
inline constexpr const char* kVersionText = "curvescan 0.1.0";

/// Where a subcommand's callback leaves its exit code for main().
struct CommandResult {
  int exit_code = 0;
};

void add_curve_command(CLI::App& root, CommandResult& result);
void add_diff_command(CLI::App& root, CommandResult& result);
void add_render_command(CLI::App& root, CommandResult& result);
void add_text_command(CLI::App& root, CommandResult& result);

}  // namespace curvescan::cli
