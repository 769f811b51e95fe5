// Exit codes shared by every curvescan subcommand (documented in README.md, "Exit codes").
#pragma once

#include <string>
#include <string_view>

#include "curvescan/status.h"

namespace curvescan::cli {

inline constexpr int kExitOk = 0;            ///< success (diff: images the same within tolerance)
inline constexpr int kExitDifferent = 1;     ///< diff only: the images differ beyond tolerance
inline constexpr int kExitSizeMismatch = 2;  ///< diff only: the images have different sizes
inline constexpr int kExitError = 3;         ///< bad input, I/O failure or a limit exceeded
inline constexpr int kExitUsage = 64;        ///< the command line itself is wrong (sysexits EX_USAGE)

/// The footer of render, text and curve --help: the codes above and the signal codes every command shares
/// (termination_signals.h). diff has its own, which adds its comparison codes.
inline constexpr const char* kExitCodesHelp =
    "Exit codes: 0 success; 3 an error (an unreadable, corrupt or too large input, a limit passed, a failed "
    "write; with several inputs, any one of them, after all were tried): one line on stderr names the file "
    "and the problem; 64 a malformed command line (an option out of its range, an output that is also an "
    "input); 128+N stopped by signal N (130 SIGINT, 143 SIGTERM, 129 SIGHUP), the output being written "
    "removed. See docs/limits.md.";

/// `message` with its control characters (C0 and DEL, tab aside) written as \xNN. Messages quote file
/// names and text from the input (a --files-from list, a style sheet rule), which a hostile file can fill
/// with an escape sequence that rewrites the terminal, or a line break that forges a second message: each
/// message stays one visible line. Every report_* function below prints through it.
std::string printable(std::string_view message);

/// Prints "curvescan <command>: error: <message>" on one line of stderr and returns kExitError.
int report_error(std::string_view command, const Error& error);
int report_error(std::string_view command, std::string_view message);

/// A wrong command line found after parsing (options that need each other): prints "curvescan <command>:
/// usage error: <message>" and the --help hint, as main() does for CLI11's errors, and returns kExitUsage.
int report_usage_error(std::string_view command, std::string_view message);

/// Prints "curvescan <command>: warning: <message>" on stderr.
void report_warning(std::string_view command, std::string_view message);

}  // namespace curvescan::cli
